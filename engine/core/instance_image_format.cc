#include "engine/core/instance_image_format.h"

#include "engine/core/limits.h"

namespace airis::engine {
namespace {

constexpr EnumName<InstanceImageFormat> kNames[] = {{InstanceImageFormat::kRgb24, "rgb24"},
                                                    {InstanceImageFormat::kGray16, "gray16"}};

}  // namespace

std::span<const EnumName<InstanceImageFormat>> EnumNames(InstanceImageFormat) { return kNames; }

std::uint32_t MaxInstanceId(InstanceImageFormat format) {
  return format == InstanceImageFormat::kGray16 ? kMaxGray16Instances : kMaxInstances;
}

}  // namespace airis::engine
