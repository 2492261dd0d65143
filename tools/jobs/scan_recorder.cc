#include "tools/jobs/scan_recorder.h"

#include <algorithm>
#include <memory>

#include "engine/dataset/csv_writer.h"

namespace airis::tools {

const std::vector<engine::LogColumn>& ScanRecorder::PoseColumns() {
  using enum engine::LogType;
  static const std::vector<engine::LogColumn> kColumns = {
      {"scan", kInt64, {}, "scan index: the file NNNNNN.pcd"},
      {"points", kInt64, {}, "returns in the file"},
      {"position_ned_x_m", kFloat64, {}, "sensor origin at the scan time, world NED (m)"},
      {"position_ned_y_m", kFloat64, {}, ""},
      {"position_ned_z_m", kFloat64, {}, ""},
      {"attitude_sensor_to_ned_w", kFloat64, {}, "rotation sensor -> world NED (q_WS)"},
      {"attitude_sensor_to_ned_x", kFloat64, {}, ""},
      {"attitude_sensor_to_ned_y", kFloat64, {}, ""},
      {"attitude_sensor_to_ned_z", kFloat64, {}, ""},
      {"velocity_ned_x_m_s", kFloat64, {}, "velocity of the sensor origin, world NED (m/s)"},
      {"velocity_ned_y_m_s", kFloat64, {}, ""},
      {"velocity_ned_z_m_s", kFloat64, {}, ""},
      {"angular_velocity_sensor_x_rad_s", kFloat64, {}, "angular velocity in sensor axes (rad/s)"},
      {"angular_velocity_sensor_y_rad_s", kFloat64, {}, ""},
      {"angular_velocity_sensor_z_rad_s", kFloat64, {}, ""},
      {"latitude_deg", kFloat64, {}, "sensor origin, WGS84"},
      {"longitude_deg", kFloat64, {}, ""},
      {"altitude_m", kFloat64, {}, "above the WGS84 ellipsoid"},
  };
  return kColumns;
}

ScanRecorder::ScanRecorder(engine::World& world, engine::DatasetWriter& writer,
                           std::filesystem::path root, const Options& options)
    : world_(world),
      writer_(writer),
      root_(std::move(root)),
      options_(options),
      recording_(world.vehicle_count(), 0) {
  for (std::size_t v = 0; v < world.vehicle_count(); ++v) {
    for (const auto& sensor : world.sensors(v)) {
      const engine::PointCloudSample* cloud = sensor->point_cloud();
      if (!cloud) continue;
      LidarInfo info;
      info.vehicle = world.vehicle(v).name();
      info.sensor = sensor->name();
      info.name = info.vehicle + "." + info.sensor;  // names hold no '.': unique, and no camera's
      info.rate_hz = sensor->schedule().rate_hz();
      info.pattern = cloud->pattern;
      recordings_.push_back({v, writer_.AddScanner(info.name), 0, {}});
      info_.push_back(std::move(info));
      const std::size_t lidar = info_.size() - 1;
      engine::Sensor* source = sensor.get();
      sensor->AddListener(
          [this, lidar, source](const engine::Sensor&) { OnScan(lidar, *source->point_cloud()); });
    }
  }
}

bool ScanRecorder::recording() const {
  return std::find(recording_.begin(), recording_.end(), 1) != recording_.end();
}

bool ScanRecorder::has_lidar(std::size_t vehicle) const {
  return std::any_of(recordings_.begin(), recordings_.end(),
                     [&](const Recording& r) { return r.vehicle == vehicle; });
}

void ScanRecorder::OnScan(std::size_t lidar, const engine::PointCloudSample& scan) {
  Recording& rec = recordings_[lidar];
  if (!recording_[rec.vehicle]) return;
  const std::int64_t index = rec.next_scan++;
  if (index % options_.shard_count != options_.shard_index) return;  // another shard's scan
  std::string why;
  if (options_.resume && writer_.VerifyScan(rec.scanner, index, &why)) {
    writer_.AdoptScan(rec.scanner, index);
  } else {
    if (options_.resume && why.find(": missing") == std::string::npos) {
      redone_.push_back(info_[lidar].name + " scan " + std::to_string(index) + ": " + why);
    }
    writer_.SubmitScan(rec.scanner, index, std::make_shared<engine::PointCloudSample>(scan));
  }
  rec.poses.push_back({index, scan.time_ns, scan.points.size(), scan.p_WS, scan.v_WS_m_s,
                       scan.w_S_rad_s, scan.q_WS});
}

void ScanRecorder::Finish() {
  std::vector<std::string> names = {"time_ns", "time_s"};
  for (const engine::LogColumn& c : PoseColumns()) names.push_back(c.name);
  for (std::size_t i = 0; i < recordings_.size(); ++i) {
    Recording& rec = recordings_[i];
    const std::set<std::int64_t>& written = writer_.scans(rec.scanner);
    std::erase_if(rec.poses, [&](const Pose& p) { return !written.count(p.index); });
    info_[i].scans = static_cast<std::int64_t>(rec.poses.size());
    const std::filesystem::path dir = root_ / info_[i].name;
    std::filesystem::create_directories(dir);
    engine::CsvWriter out(dir / "poses.csv", names);
    for (const Pose& p : rec.poses) {
      const engine::GeodeticPosition g = world_.environment().frame().ToGeodetic(p.p_WS);
      out.Add(static_cast<std::int64_t>(p.time_ns)).Add(engine::ToSeconds(p.time_ns));
      out.Add(p.index).Add(static_cast<std::int64_t>(p.points));
      for (int k = 0; k < 3; ++k) out.Add(p.p_WS[k]);
      out.Add(p.q_WS.w()).Add(p.q_WS.x()).Add(p.q_WS.y()).Add(p.q_WS.z());
      for (int k = 0; k < 3; ++k) out.Add(p.v_WS_m_s[k]);
      for (int k = 0; k < 3; ++k) out.Add(p.w_S_rad_s[k]);
      out.Add(engine::RadToDeg(g.latitude_rad))
          .Add(engine::RadToDeg(g.longitude_rad))
          .Add(g.altitude_m);
      out.EndRow();
    }
    out.Close();
  }
}

}  // namespace airis::tools
