#pragma once

#include <cstdint>

namespace airis::engine {

/// Bytes of physical memory this machine has (sysconf), or 0 when the system does not say.
std::uint64_t PhysicalMemoryBytes();

}  // namespace airis::engine
