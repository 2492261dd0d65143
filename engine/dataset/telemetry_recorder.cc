#include "engine/dataset/telemetry_recorder.h"

#include "engine/core/frames.h"
#include "engine/dataset/file_io.h"

namespace airis::engine {
namespace {

std::vector<std::string> TimeColumns(std::vector<std::string> rest) {
  rest.insert(rest.begin(), {"time_ns", "time_s"});
  return rest;
}

}  // namespace

TelemetryRecorder::TelemetryRecorder(World& world, const std::filesystem::path& dir,
                                     const TelemetryOptions& options)
    : world_(world),
      options_(options),
      truth_schedule_(options.truth_rate_hz),
      recording_(!options.window_only) {
  truth_ =
      std::make_unique<CsvWriter>(dir / "truth.csv", TimeColumns({"vehicle",
                                                                  "position_ned_x_m",
                                                                  "position_ned_y_m",
                                                                  "position_ned_z_m",
                                                                  "velocity_ned_x_m_s",
                                                                  "velocity_ned_y_m_s",
                                                                  "velocity_ned_z_m_s",
                                                                  "attitude_frd_to_ned_w",
                                                                  "attitude_frd_to_ned_x",
                                                                  "attitude_frd_to_ned_y",
                                                                  "attitude_frd_to_ned_z",
                                                                  "roll_deg",
                                                                  "pitch_deg",
                                                                  "yaw_deg",
                                                                  "angular_velocity_frd_x_rad_s",
                                                                  "angular_velocity_frd_y_rad_s",
                                                                  "angular_velocity_frd_z_rad_s",
                                                                  "acceleration_ned_x_m_s2",
                                                                  "acceleration_ned_y_m_s2",
                                                                  "acceleration_ned_z_m_s2",
                                                                  "latitude_deg",
                                                                  "longitude_deg",
                                                                  "altitude_m"}));
  for (std::size_t v = 0; v < world.vehicle_count(); ++v) {
    std::vector<std::string> cols = {"mode",
                                     "position_setpoint_ned_x_m",
                                     "position_setpoint_ned_y_m",
                                     "position_setpoint_ned_z_m",
                                     "velocity_setpoint_ned_x_m_s",
                                     "velocity_setpoint_ned_y_m_s",
                                     "velocity_setpoint_ned_z_m_s",
                                     "acceleration_setpoint_ned_x_m_s2",
                                     "acceleration_setpoint_ned_y_m_s2",
                                     "acceleration_setpoint_ned_z_m_s2",
                                     "speed_limit_m_s",
                                     "yaw_setpoint_deg",
                                     "attitude_setpoint_frd_to_ned_w",
                                     "attitude_setpoint_frd_to_ned_x",
                                     "attitude_setpoint_frd_to_ned_y",
                                     "attitude_setpoint_frd_to_ned_z",
                                     "rates_setpoint_frd_x_rad_s",
                                     "rates_setpoint_frd_y_rad_s",
                                     "rates_setpoint_frd_z_rad_s",
                                     "thrust_fraction"};
    for (int a = 0; a < world.vehicle(v).actuator_count(); ++a) {
      cols.push_back("actuator_" + std::to_string(a));
    }
    commands_.push_back(std::make_unique<CsvWriter>(
        PathUnder(dir, world.vehicle(v).name() + ".commands.csv"), TimeColumns(cols)));
  }
  for (std::size_t v = 0; v < world.vehicle_count(); ++v) {
    for (const auto& sensor : world.sensors(v)) {
      // Images are recorded by the dataset recorder, with their poses in <camera>/poses.csv.
      if (sensor->image()) continue;
      const std::string stream = world.vehicle(v).name() + "." + sensor->name();
      const std::vector<std::string> cols =
          TimeColumns({sensor->columns().begin(), sensor->columns().end()});
      auto out = std::make_unique<SensorStream>();
      if (options_.sensor_format == StreamFormat::kNpy) {
        std::vector<NpyField> fields = {NpyField::kInt64, NpyField::kFloat64};
        for (std::size_t c = 0; c < sensor->columns().size(); ++c) {
          fields.push_back(sensor->IsDoubleColumn(c) ? NpyField::kFloat64 : NpyField::kFloat32);
        }
        out->npy = std::make_unique<NpyStreamWriter>(PathUnder(dir, stream + ".npy"), cols, fields);
      } else {
        out->csv = std::make_unique<CsvWriter>(PathUnder(dir, stream + ".csv"), cols);
      }
      SensorStream* target = out.get();
      sensors_.push_back(std::move(out));
      sensor->AddListener([this, target](const Sensor& s) {
        if (!recording_) return;
        const std::size_t n = s.columns().size();
        row_.resize(n + 2);
        row_[0] = static_cast<double>(s.last_sample_ns());
        row_[1] = ToSeconds(s.last_sample_ns());
        s.CopyLatestRow(std::span<double>(row_).subspan(2));
        if (target->npy) {
          target->npy->AddRow(row_);
          return;
        }
        CsvWriter& csv = *target->csv;
        csv.Add(static_cast<std::int64_t>(s.last_sample_ns())).Add(row_[1]);
        for (std::size_t c = 0; c < n; ++c) {
          if (s.IsDoubleColumn(c)) {
            csv.Add(row_[c + 2]);
          } else {
            csv.AddFloat(row_[c + 2]);
          }
        }
        csv.EndRow();
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
                                        TimeColumns({"step", "kind", "event"}));
}

void TelemetryRecorder::OnTick(TimeNs now_ns) {
  if (truth_schedule_.ConsumeDue(now_ns) == 0 || !recording_) return;
  const LocalNedFrame& frame = world_.environment().frame();
  for (std::size_t v = 0; v < world_.vehicle_count(); ++v) {
    const RigidBodyState& s = world_.vehicle(v).state();
    const RigidBodyAccelerations& a = world_.accelerations(v);
    const EulerAngles e = EulerFromQuat(s.q_WB);
    const GeodeticPosition g = frame.ToGeodetic(s.p_W);
    CsvWriter& out = *truth_;
    out.Add(static_cast<std::int64_t>(now_ns)).Add(ToSeconds(now_ns)).Add(world_.vehicle(v).name());
    for (int i = 0; i < 3; ++i) out.Add(s.p_W[i]);
    for (int i = 0; i < 3; ++i) out.Add(s.v_W[i]);
    out.Add(s.q_WB.w()).Add(s.q_WB.x()).Add(s.q_WB.y()).Add(s.q_WB.z());
    out.Add(RadToDeg(e.roll_rad)).Add(RadToDeg(e.pitch_rad)).Add(RadToDeg(e.yaw_rad));
    for (int i = 0; i < 3; ++i) out.Add(s.w_B[i]);
    for (int i = 0; i < 3; ++i) out.Add(a.a_W[i]);
    out.Add(RadToDeg(g.latitude_rad)).Add(RadToDeg(g.longitude_rad)).Add(g.altitude_m);
    out.EndRow();
    WriteCommandRow(v, now_ns);
  }
}

void TelemetryRecorder::WriteCommandRow(std::size_t v, TimeNs now_ns) {
  const Vehicle& vehicle = world_.vehicle(v);
  const VehicleCommand& c = vehicle.command();
  CsvWriter& out = *commands_[v];
  out.Add(static_cast<std::int64_t>(now_ns)).Add(ToSeconds(now_ns));
  out.Add(std::string(ToString(c.mode)));
  for (int i = 0; i < 3; ++i) out.Add(c.position_W[i]);
  for (int i = 0; i < 3; ++i) out.Add(c.velocity_W[i]);
  for (int i = 0; i < 3; ++i) out.Add(c.acceleration_W[i]);
  out.Add(c.speed_limit_m_s).Add(RadToDeg(c.yaw_rad));
  out.Add(c.attitude_WB.w()).Add(c.attitude_WB.x()).Add(c.attitude_WB.y()).Add(c.attitude_WB.z());
  for (int i = 0; i < 3; ++i) out.Add(c.rates_B[i]);
  out.Add(c.thrust_fraction);
  for (double u : vehicle.actuator_commands()) out.Add(u);
  out.EndRow();
}

void TelemetryRecorder::RecordMissionEvent(TimeNs time_ns, int step_index,
                                           const std::string& step_kind, const std::string& what) {
  events_->Add(static_cast<std::int64_t>(time_ns)).Add(ToSeconds(time_ns));
  events_->Add(static_cast<std::int64_t>(step_index + 1)).Add(step_kind).Add(what);
  events_->EndRow();
}

void TelemetryRecorder::Close() {
  truth_->Close();
  for (auto& c : commands_) c->Close();
  for (auto& s : sensors_) {
    if (s->csv) s->csv->Close();
    if (s->npy) s->npy->Close();
  }
  collisions_->Close();
  events_->Close();
}

}  // namespace airis::engine
