#include "engine/dataset/telemetry_recorder.h"

#include "engine/core/config.h"
#include "engine/core/frames.h"
#include "engine/dataset/file_io.h"

namespace airis::engine {
namespace {

std::vector<std::string> TimeColumns(std::vector<std::string> rest) {
  rest.insert(rest.begin(), {"time_ns", "time_s"});
  return rest;
}

void AddVec3(std::vector<LogColumn>& out, const std::string& prefix, const std::string& unit,
             LogType type) {
  for (const char* axis : {"x", "y", "z"}) {
    out.push_back({prefix + "_" + axis + (unit.empty() ? "" : "_" + unit), type, {}});
  }
}

void AddQuat(std::vector<LogColumn>& out, const std::string& prefix, LogType type) {
  for (const char* part : {"w", "x", "y", "z"}) out.push_back({prefix + "_" + part, type, {}});
}

std::size_t ModeIndex(CommandMode mode) {
  const auto names = EnumNames(CommandMode{});
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i].value == mode) return i;
  }
  return 0;
}

}  // namespace

std::vector<LogColumn> TelemetryRecorder::TruthColumns() {
  using enum LogType;
  std::vector<LogColumn> c;
  AddVec3(c, "position_ned", "m", kFloat64);
  AddVec3(c, "velocity_ned", "m_s", kFloat32);
  AddQuat(c, "attitude_frd_to_ned", kFloat32);  // resolves 1e-7 rad
  for (const char* angle : {"roll_deg", "pitch_deg", "yaw_deg"}) c.push_back({angle, kFloat32, {}});
  AddVec3(c, "angular_velocity_frd", "rad_s", kFloat32);
  AddVec3(c, "acceleration_ned", "m_s2", kFloat32);
  for (const char* g : {"latitude_deg", "longitude_deg", "altitude_m"}) {
    c.push_back({g, kFloat64, {}});
  }
  return c;
}

std::vector<LogColumn> TelemetryRecorder::CommandColumns(int actuator_count) {
  using enum LogType;
  std::vector<LogColumn> c;
  LogColumn mode{"mode", kLabel, {}};
  for (const auto& n : EnumNames(CommandMode{})) mode.labels.emplace_back(n.name);
  c.push_back(std::move(mode));
  AddVec3(c, "position_setpoint_ned", "m", kFloat64);
  AddVec3(c, "velocity_setpoint_ned", "m_s", kFloat32);
  AddVec3(c, "acceleration_setpoint_ned", "m_s2", kFloat32);
  c.push_back({"speed_limit_m_s", kFloat32, {}});
  c.push_back({"yaw_setpoint_deg", kFloat32, {}});
  AddQuat(c, "attitude_setpoint_frd_to_ned", kFloat32);
  AddVec3(c, "rates_setpoint_frd", "rad_s", kFloat32);
  c.push_back({"thrust_fraction", kFloat32, {}});
  for (int a = 0; a < actuator_count; ++a)
    c.push_back({"actuator_" + std::to_string(a), kFloat32, {}});
  return c;
}

std::vector<std::string> TelemetryRecorder::FileNames(const World& world, StreamFormat format) {
  std::vector<std::string> out = {"collisions.csv", "mission_events.csv"};
  for (std::size_t v = 0; v < world.vehicle_count(); ++v) {
    const std::string& name = world.vehicle(v).name();
    out.push_back(StreamWriter::FileName(name + ".truth", format));
    out.push_back(StreamWriter::FileName(name + ".commands", format));
    for (const auto& s : world.sensors(v)) {
      if (!s->image()) out.push_back(StreamWriter::FileName(name + "." + s->name(), format));
    }
  }
  return out;
}

TelemetryRecorder::TelemetryRecorder(World& world, const std::filesystem::path& dir,
                                     const TelemetryOptions& options)
    : world_(world),
      options_(options),
      truth_schedule_(options.truth_rate_hz),
      recording_(!options.window_only) {
  for (std::size_t v = 0; v < world.vehicle_count(); ++v) {
    const Vehicle& vehicle = world.vehicle(v);
    truth_.push_back(std::make_unique<StreamWriter>(dir, vehicle.name() + ".truth", TruthColumns(),
                                                    options.format));
    commands_.push_back(std::make_unique<StreamWriter>(dir, vehicle.name() + ".commands",
                                                       CommandColumns(vehicle.actuator_count()),
                                                       options.format));
  }
  for (std::size_t v = 0; v < world.vehicle_count(); ++v) {
    for (const auto& sensor : world.sensors(v)) {
      // Images are recorded by the dataset recorder, with their poses in <camera>/poses.csv.
      if (sensor->image()) continue;
      std::vector<LogColumn> columns;
      for (std::size_t c = 0; c < sensor->columns().size(); ++c) {
        columns.push_back({sensor->columns()[c], sensor->column_type(c), {}});
      }
      sensors_.push_back(std::make_unique<StreamWriter>(
          dir, world.vehicle(v).name() + "." + sensor->name(), std::move(columns), options.format));
      StreamWriter* target = sensors_.back().get();
      sensor->AddListener([this, target](const Sensor& s) {
        if (!recording_) return;
        row_.resize(s.columns().size());
        s.CopyLatestRow(row_);
        target->AddRow(s.last_sample_ns(), row_);
      });
    }
  }
  collisions_ = std::make_unique<CsvWriter>(
      dir / "collisions.csv",
      TimeColumns({"vehicle", "object", "class_id", "instance_id", "point_ned_x_m", "point_ned_y_m",
                   "point_ned_z_m", "normal_ned_x", "normal_ned_y", "normal_ned_z",
                   "impulse_n_s"}));
  world.AddCollisionListener([this](const CollisionEvent& e) {
    collisions_->Add(static_cast<std::int64_t>(e.time_ns)).Add(ToSeconds(e.time_ns));
    collisions_->Add(e.vehicle_name).Add(e.object_name);
    collisions_->Add(static_cast<std::int64_t>(e.class_id))
        .Add(static_cast<std::int64_t>(e.instance_id));
    for (int i = 0; i < 3; ++i) collisions_->Add(e.point_W[i]);
    for (int i = 0; i < 3; ++i) collisions_->Add(e.normal_W[i]);
    collisions_->Add(e.impulse_Ns);
    collisions_->EndRow();
  });
  events_ = std::make_unique<CsvWriter>(dir / "mission_events.csv",
                                        TimeColumns({"vehicle", "step", "kind", "event"}));
}

void TelemetryRecorder::OnTick(TimeNs now_ns) {
  if (truth_schedule_.ConsumeDue(now_ns) == 0 || !recording_) return;
  for (std::size_t v = 0; v < world_.vehicle_count(); ++v) {
    WriteTruthRow(v, now_ns);
    WriteCommandRow(v, now_ns);
  }
}

void TelemetryRecorder::CopyTruthRow(const World& world, std::size_t v, std::vector<double>& out) {
  const RigidBodyState& s = world.vehicle(v).state();
  const RigidBodyAccelerations& a = world.accelerations(v);
  const EulerAngles e = EulerFromQuat(s.q_WB);
  const GeodeticPosition g = world.environment().frame().ToGeodetic(s.p_W);
  out.clear();
  for (int i = 0; i < 3; ++i) out.push_back(s.p_W[i]);
  for (int i = 0; i < 3; ++i) out.push_back(s.v_W[i]);
  out.insert(out.end(), {s.q_WB.w(), s.q_WB.x(), s.q_WB.y(), s.q_WB.z()});
  out.insert(out.end(), {RadToDeg(e.roll_rad), RadToDeg(e.pitch_rad), RadToDeg(e.yaw_rad)});
  for (int i = 0; i < 3; ++i) out.push_back(s.w_B[i]);
  for (int i = 0; i < 3; ++i) out.push_back(a.a_W[i]);
  out.insert(out.end(), {RadToDeg(g.latitude_rad), RadToDeg(g.longitude_rad), g.altitude_m});
}

void TelemetryRecorder::CopyCommandRow(const Vehicle& vehicle, std::vector<double>& out) {
  const VehicleCommand& c = vehicle.command();
  out.clear();
  out.push_back(static_cast<double>(ModeIndex(c.mode)));
  for (int i = 0; i < 3; ++i) out.push_back(c.position_W[i]);
  for (int i = 0; i < 3; ++i) out.push_back(c.velocity_W[i]);
  for (int i = 0; i < 3; ++i) out.push_back(c.acceleration_W[i]);
  out.insert(out.end(), {c.speed_limit_m_s, RadToDeg(c.yaw_rad)});
  out.insert(out.end(),
             {c.attitude_WB.w(), c.attitude_WB.x(), c.attitude_WB.y(), c.attitude_WB.z()});
  for (int i = 0; i < 3; ++i) out.push_back(c.rates_B[i]);
  out.push_back(c.thrust_fraction);
  for (double u : vehicle.actuator_commands()) out.push_back(u);
}

void TelemetryRecorder::WriteTruthRow(std::size_t v, TimeNs now_ns) {
  CopyTruthRow(world_, v, row_);
  truth_[v]->AddRow(now_ns, row_);
}

void TelemetryRecorder::WriteCommandRow(std::size_t v, TimeNs now_ns) {
  CopyCommandRow(world_.vehicle(v), row_);
  commands_[v]->AddRow(now_ns, row_);
}

void TelemetryRecorder::RecordMissionEvent(TimeNs time_ns, const std::string& vehicle,
                                           int step_index, const std::string& step_kind,
                                           const std::string& what) {
  events_->Add(static_cast<std::int64_t>(time_ns)).Add(ToSeconds(time_ns)).Add(vehicle);
  events_->Add(static_cast<std::int64_t>(step_index + 1)).Add(step_kind).Add(what);
  events_->EndRow();
}

void TelemetryRecorder::Close() {
  for (auto& t : truth_) t->Close();
  for (auto& c : commands_) c->Close();
  for (auto& s : sensors_) s->Close();
  collisions_->Close();
  events_->Close();
}

}  // namespace airis::engine
