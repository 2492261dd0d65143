#include "tools/jobs/px4_job.h"

#include <memory>

#include "engine/dataset/telemetry_recorder.h"
#include "tools/jobs/autopilots.h"
#include "tools/jobs/realtime_pacer.h"
#include "tools/jobs/telemetry_log.h"

namespace airis::tools {

Px4JobResult RunPx4Job(const Px4JobOptions& o,
                       const std::function<void(const JobProgress&)>& progress) {
  CheckPacingOptions(o.realtime, o.truth_rate_hz);
  SimulationJob job(o.scene, o.threads);
  job.DisableImageSensors();
  const std::vector<AttachedAutopilot> px4 = AttachAutopilots(job, o.log);
  if (px4.empty()) {
    throw engine::ConfigError({job.scene().path, 0, 0}, "vehicles",
                              "no vehicle has `autopilot: {kind: px4}`: nothing for PX4 to fly "
                              "(docs/px4.md)");
  }
  const std::unique_ptr<engine::TelemetryRecorder> telemetry =
      OpenTelemetryLog(job.world(), o.out, o.truth_rate_hz);
  const RealtimePacer pacer(o.realtime.value_or(1.0));
  engine::Simulation& sim = job.simulation();
  Px4JobResult r;
  const auto report = [&] {
    r.vehicles.clear();
    for (const AttachedAutopilot& a : px4) {
      r.vehicles.push_back(
          {job.world().vehicle(a.vehicle).name(), a.px4->DescribeLink(), a.px4->stats()});
    }
  };
  constexpr engine::TimeNs kProgressEvery = 250'000'000;
  engine::TimeNs next_progress = kProgressEvery;
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
      progress(p);
    }
  }
  if (telemetry) {
    telemetry->Close();
    r.collisions = telemetry->collision_count();
  }
  report();
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
