#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace airis::engine {

/// How a logged column is stored (docs/dataset-format.md, "Streams"). Readings are float32: their
/// noise is far above float32's 6e-8 relative step. Positions that need more (a latitude, a world
/// position in metres) are float64.
enum class LogType : std::uint8_t {
  kFloat32,
  kFloat64,
  kInt64,  ///< a whole number (a GPS fix type)
  kLabel,  ///< an index into LogColumn::labels: the label's text in CSV, its index (uint8) in .npy
};

/// One column of a logged stream: its name with its unit ("specific_force_sensor_x_m_s2").
struct LogColumn {
  std::string name;
  LogType type = LogType::kFloat32;
  std::vector<std::string> labels;  ///< kLabel only
  std::string doc;                  ///< what it holds, for docs/dataset-format.md's column tables
};

}  // namespace airis::engine
