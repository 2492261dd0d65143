#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace airis::scenes {

/// How many objects and vehicles one scene may hold: engine::kMaxInstances (24-bit instance ids),
/// or fewer where the memory they would need once built (engine::kMinBuiltObjectBytes each) is
/// more than the machine has or the caller allows (docs/limits.md).
class ObjectCapacity {
 public:
  /// `memory_limit_bytes`: what the objects may take; default: this machine's physical memory.
  explicit ObjectCapacity(std::optional<std::uint64_t> memory_limit_bytes);

  /// Objects and vehicle bodies the scene may hold.
  std::uint32_t max_instances() const { return max_instances_; }
  /// Why `wanted` more objects do not fit after `placed` ("places N objects where M instance ids
  /// are left (...; docs/limits.md)", the ids checked first), or "" when they fit.
  std::string DescribeShortfall(std::uint64_t wanted, std::uint64_t placed) const;
  /// "the scene exceeds N WHAT (why; docs/limits.md)", once the scene is full.
  std::string DescribeFull(const std::string& what) const;

 private:
  std::uint32_t max_instances_;
  std::string memory_;  // the memory that bounds the scene, as messages say it; empty: the ids do
};

}  // namespace airis::scenes
