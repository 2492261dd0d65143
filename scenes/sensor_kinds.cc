#include "scenes/sensor_kinds.h"

#include "sensors/barometer.h"
#include "sensors/camera/camera_sensor.h"
#include "sensors/camera/stereo_camera_sensor.h"
#include "sensors/gps.h"
#include "sensors/imu.h"
#include "sensors/lidar.h"
#include "sensors/magnetometer.h"
#include "sensors/rangefinder.h"

namespace airis::scenes {

std::span<const SensorKind> SensorKinds() {
  // A new kind is a folder in sensors/ and one line here.
  static const SensorKind kKinds[] = {
      SensorKindOf<sensors::ImuConfig, sensors::Imu>("imu", "IMU (gyroscope and accelerometer)"),
      SensorKindOf<sensors::BarometerConfig, sensors::Barometer>("barometer", "barometer"),
      SensorKindOf<sensors::MagnetometerConfig, sensors::Magnetometer>("magnetometer",
                                                                       "magnetometer"),
      SensorKindOf<sensors::GpsConfig, sensors::Gps>("gps", "GPS receiver"),
      SensorKindOf<sensors::RangefinderConfig, sensors::Rangefinder>("rangefinder",
                                                                     "single-beam rangefinder"),
      SensorKindOf<sensors::LidarConfig, sensors::Lidar>("lidar", "scanning lidar"),
      SensorKindOf<sensors::CameraConfig, sensors::CameraSensor>(
          "camera", "camera rendering RGB, depth, segmentation (docs/rendering.md)"),
      SensorKindOf<sensors::StereoCameraConfig, sensors::StereoCameraSensor>(
          "stereo_camera", "synchronised stereo pair of cameras"),
  };
  return kKinds;
}

void SensorEntry::ReadFromYaml(const YamlReader& reader, const YAML::Node& node,
                               const YAML::Mark& mark, const std::string& key_path) {
  std::vector<std::string> kinds;
  for (const SensorKind& k : SensorKinds()) kinds.emplace_back(k.name);
  std::string all;
  for (std::size_t i = 0; i < kinds.size(); ++i) {
    all += (i == 0 ? "" : i + 1 == kinds.size() ? " or " : ", ") + kinds[i];
  }
  if (!node.IsMap()) {
    reader.Fail(
        mark, key_path,
        "expected a map with one sensor (" + all + ") (got " + YamlReader::Describe(node) + ")");
  }
  where = reader.Where(mark);
  const SensorKind* found = nullptr;
  YAML::Node value;
  YAML::Mark value_mark;
  bool named = false;
  for (const auto& item : node) {
    const std::string& key =
        reader.RequireScalar(item.first, item.first.Mark(), key_path, "a plain name as a key");
    const YAML::Mark key_mark = item.first.Mark();
    if (key == "name") {
      if (named) reader.Fail(key_mark, yaml_detail::JoinKey(key_path, "name"), "duplicate key");
      named = true;
      reader.Read(item.second, yaml_detail::JoinKey(key_path, "name"), name);
      try {
        engine::RequireName("name", name);
      } catch (const engine::InvalidField& e) {
        reader.Fail(key_mark, yaml_detail::JoinKey(key_path, "name"), e.problem());
      }
      continue;
    }
    const SensorKind* kind = nullptr;
    for (const SensorKind& k : SensorKinds()) {
      if (k.name == key) kind = &k;
    }
    if (!kind) {
      std::vector<std::string> keys = kinds;
      keys.emplace_back("name");
      std::string problem = "unknown key " + engine::QuoteValue(key);
      if (const auto close = engine::ClosestMatch(key, keys)) {
        problem += " (did you mean '" + *close + "'?)";
      }
      reader.Fail(key_mark, yaml_detail::JoinKey(key_path, key),
                  problem + "; a sensor entry has `name` and one of " + all);
    }
    if (found) {
      reader.Fail(
          key_mark, yaml_detail::JoinKey(key_path, key),
          "give one sensor per entry (this one also has '" + std::string(found->name) + "')");
    }
    found = kind;
    value.reset(item.second);
    value_mark = key_mark;
  }
  if (!found) reader.Fail(mark, key_path, "expected one sensor: " + all);
  spec = found->read(reader, value, value_mark,
                     yaml_detail::JoinKey(key_path, std::string(found->name)));
  if (name.empty()) name = found->name;
}

}  // namespace airis::scenes
