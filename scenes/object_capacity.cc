#include "scenes/object_capacity.h"

#include <algorithm>
#include <cstdio>

#include "engine/core/limits.h"
#include "engine/core/machine_memory.h"

namespace airis::scenes {

namespace {

/// "23.4 GiB", or "128 MiB" under a gibibyte.
std::string Bytes(std::uint64_t bytes) {
  char text[32];
  if (bytes < (1ull << 30)) {
    std::snprintf(text, sizeof text, "%llu MiB", static_cast<unsigned long long>(bytes >> 20));
  } else {
    std::snprintf(text, sizeof text, "%.1f GiB", static_cast<double>(bytes) / (1ull << 30));
  }
  return text;
}

}  // namespace

ObjectCapacity::ObjectCapacity(std::optional<std::uint64_t> memory_limit_bytes)
    : max_instances_(engine::kMaxInstances) {
  const std::uint64_t memory = memory_limit_bytes.value_or(engine::PhysicalMemoryBytes());
  if (memory == 0 && !memory_limit_bytes) return;  // the system does not say: ids alone
  const std::uint64_t fit = memory / engine::kMinBuiltObjectBytes;
  if (fit >= engine::kMaxInstances) return;
  max_instances_ = static_cast<std::uint32_t>(fit);
  memory_ = (memory_limit_bytes ? "the memory limit of " : "this machine's ") + Bytes(memory) +
            (memory_limit_bytes ? "" : " of memory");
}

std::string ObjectCapacity::DescribeShortfall(std::uint64_t wanted, std::uint64_t placed) const {
  // The ids first: a scene beyond them is refused on every machine, in the same words.
  const std::uint64_t ids_left =
      engine::kMaxInstances - std::min<std::uint64_t>(placed, engine::kMaxInstances);
  if (wanted > ids_left) {
    return "places " + std::to_string(wanted) + " objects where " + std::to_string(ids_left) +
           " instance ids are left (a scene holds at most " +
           std::to_string(engine::kMaxInstances) +
           " objects: instance ids are 24-bit; docs/limits.md)";
  }
  const std::uint64_t left = max_instances_ - std::min<std::uint64_t>(placed, max_instances_);
  if (wanted <= left) return "";
  return "places " + std::to_string(wanted) + " objects where " + std::to_string(left) +
         " more fit in memory (" + memory_ + " holds " + std::to_string(max_instances_) +
         " objects and vehicles of at least " + std::to_string(engine::kMinBuiltObjectBytes) +
         " bytes each once built; docs/limits.md)";
}

std::string ObjectCapacity::DescribeFull(const std::string& what) const {
  if (memory_.empty()) {
    return "the scene exceeds " + std::to_string(engine::kMaxInstances) + " " + what +
           " (docs/limits.md)";
  }
  return "the scene exceeds the " + std::to_string(max_instances_) + " " + what + " that " +
         memory_ + " holds (at least " + std::to_string(engine::kMinBuiltObjectBytes) +
         " bytes each once built; docs/limits.md)";
}

}  // namespace airis::scenes
