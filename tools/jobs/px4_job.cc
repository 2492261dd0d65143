#include "tools/jobs/px4_job.h"

#include <memory>

#include "engine/dataset/telemetry_recorder.h"
#include "engine/mavlink/link/link.h"
#include "engine/mission/steps/host_steps.h"
#include "tools/jobs/autopilots.h"
#include "tools/jobs/realtime_pacer.h"
#include "tools/jobs/telemetry_log.h"

namespace airis::tools {
namespace {

// The dataset options of a session: checked, and with the streams of the whole session (there are
// no capture windows).
std::optional<DatasetWriteOptions> SessionDataset(const Px4JobOptions& o) {
  if (!o.dataset) return std::nullopt;
  if (!o.out.empty()) {
    throw engine::ConfigError({}, "--out",
                              "not with --dataset: the dataset holds the telemetry streams");
  }
  const char* repeat = "a session PX4 flies from outside does not repeat";
  if (o.dataset->resume) throw engine::ConfigError({}, "--resume", repeat);
  if (o.dataset->shard.count != 1) throw engine::ConfigError({}, "--shard", repeat);
  CheckDatasetWriteOptions(*o.dataset);
  DatasetWriteOptions d = *o.dataset;
  d.full_streams = true;
  return d;
}

}  // namespace

nlohmann::json Px4ManifestEntry(const std::vector<Px4VehicleReport>& vehicles) {
  nlohmann::json list = nlohmann::json::array();
  for (const Px4VehicleReport& v : vehicles) {
    list.push_back({{"vehicle", v.vehicle},
                    {"link", v.link},
                    {"sensor_messages", v.stats.sensor_messages},
                    {"actuator_messages", v.stats.actuator_messages},
                    {"lockstep_steps", v.stats.lockstep_steps},
                    {"timeouts", v.stats.timeouts}});
  }
  return list;
}

Px4JobResult RunPx4Job(const Px4JobOptions& o,
                       const std::function<void(const JobProgress&)>& progress) {
  const std::optional<DatasetWriteOptions> dataset_options = SessionDataset(o);
  SimulationJob job(o.scene, o.threads);
  CheckPacingOptions(o.realtime, o.truth_rate_hz, job.scene().physics.rate_hz, o.until_ns);
  if (!dataset_options) job.DisableImageSensors();
  const std::vector<AttachedAutopilot> px4 = AttachAutopilots(job, o.log);
  if (px4.empty()) {
    throw engine::ConfigError({job.scene().path, 0, 0}, "vehicles",
                              "no vehicle has `autopilot: {kind: px4}`: nothing for PX4 to fly "
                              "(docs/px4.md)");
  }
  Px4JobResult r;
  std::int64_t contacts = 0;  // the job's world, and its listener, end with this function
  job.world().AddCollisionListener([&contacts](const engine::CollisionEvent&) { ++contacts; });
  const auto report = [&] {
    r.vehicles.clear();
    for (const AttachedAutopilot& a : px4) {
      r.vehicles.push_back(
          {job.world().vehicle(a.vehicle).name(), a.px4->DescribeLink(), a.px4->stats()});
    }
  };
  std::unique_ptr<DatasetSession> dataset;
  if (dataset_options) {
    report();
    dataset =
        std::make_unique<DatasetSession>(job, *dataset_options, o.scene.path, nullptr,
                                         std::vector<std::size_t>{}, Px4ManifestEntry(r.vehicles));
    // No mission: every selected camera records at its own rate for the whole session.
    for (std::size_t v = 0; v < job.world().vehicle_count(); ++v) {
      dataset->recorder().SetCapture(v, engine::CaptureStep{});
    }
  }
  const std::unique_ptr<engine::TelemetryRecorder> log =
      OpenTelemetryLog(job.world(), o.out, o.truth_rate_hz);
  engine::TelemetryRecorder* telemetry = dataset ? &dataset->telemetry() : log.get();
  const RealtimePacer pacer(o.realtime.value_or(1.0));
  engine::Simulation& sim = job.simulation();
  // The dataset is finished however the session ends; complete only when --until-s ended it.
  const auto finish = [&](bool complete) {
    report();
    if (dataset) {
      dataset->Finish(complete, r.interrupted_by, sim.clock().now_s(),
                      Px4ManifestEntry(r.vehicles));
      r.frames = dataset->frames();
      r.cameras = dataset->recorder().cameras().size();
    } else if (telemetry) {
      telemetry->Close();
    }
  };
  constexpr engine::TimeNs kProgressEvery = 250'000'000;
  engine::TimeNs next_progress = kProgressEvery;
  try {
    while (sim.clock().now_ns() < o.until_ns) {
      if (o.stop && (r.interrupted_by = o.stop->load()) != 0) break;
      sim.Step();
      const engine::TimeNs now = sim.clock().now_ns();
      if (telemetry) telemetry->OnTick(now);
      if (o.realtime) pacer.WaitFor(now);
      if (progress && now >= next_progress) {
        next_progress = now + kProgressEvery;
        JobProgress p;
        p.simulated_s = sim.clock().now_s();
        p.wall_s = job.wall_s();
        p.position_W = job.world().vehicle(px4.front().vehicle).state().p_W;
        if (dataset) p.frames = dataset->recorder().frames_written();
        progress(p);
      }
    }
  } catch (const engine::mavlink::LinkError&) {
    if (dataset) finish(false);  // what was recorded stays usable, marked incomplete
    throw;
  }
  finish(r.interrupted_by == 0);
  r.contacts = contacts;
  r.simulated_s = sim.clock().now_s();
  r.wall_s = job.wall_s();
  return r;
}

std::string WritePx4AirframeFor(const SceneSource& scene, const std::string& vehicle,
                                engine::mavlink::Px4AirframeOptions options) {
  SimulationJob job(scene);
  const engine::World& w = job.world();
  const int index = w.FindVehicle(vehicle);
  if (index < 0) {
    std::string names;
    for (std::size_t i = 0; i < w.vehicle_count(); ++i) {
      names += (names.empty() ? "" : ", ") + w.vehicle(i).name();
    }
    throw engine::ConfigError({job.scene().path, 0, 0}, "--vehicle",
                              "no vehicle '" + vehicle + "' in the scene (it has " +
                                  (names.empty() ? std::string("none") : names) + ")");
  }
  const auto i = static_cast<std::size_t>(index);
  if (options.name.empty()) options.name = "airis_" + vehicle;
  w.CalcLocalConditions(i, &options.air_density_kg_m3, &options.gravity_m_s2);
  try {
    return engine::mavlink::WritePx4Airframe(w.vehicle(i), w.sensors(i),
                                             job.scene().vehicles[i].autopilot, options);
  } catch (const engine::InvalidField& e) {
    const scenes::VehicleDescription& d = job.scene().vehicles[i];
    throw engine::ConfigError(d.where, d.key_path + "." + e.field(), e.problem());
  }
}

}  // namespace airis::tools
