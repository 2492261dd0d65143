#include "tools/jobs/run_job.h"

#include <memory>

#include "engine/dataset/telemetry_recorder.h"
#include "scenes/mission_file.h"
#include "tools/jobs/autopilots.h"
#include "tools/jobs/realtime_pacer.h"
#include "tools/jobs/telemetry_log.h"

namespace airis::tools {

RunJobResult RunMissionJob(const RunJobOptions& o,
                           const std::function<void(const JobProgress&)>& progress) {
  SimulationJob job(o.scene, o.threads);
  CheckPacingOptions(o.realtime, o.truth_rate_hz, job.scene().physics.rate_hz, o.until_ns);
  const engine::Mission mission = scenes::LoadMissionFile(o.mission);
  job.CheckMission(mission);  // a mission that cannot be flown fails before anything is written
  job.DisableImageSensors();
  AttachAutopilots(job, o.log);  // PX4 vehicles: their links open before anything is written

  const std::unique_ptr<engine::TelemetryRecorder> telemetry =
      OpenTelemetryLog(job.world(), o.out, o.truth_rate_hz);
  const RealtimePacer pacer(o.realtime.value_or(1.0));
  MissionFlight flight;
  flight.until_ns = o.until_ns;
  flight.stop = o.stop;
  flight.progress = progress;
  flight.callbacks.after_tick = [&](engine::TimeNs now_ns) {
    if (telemetry) telemetry->OnTick(now_ns);
    if (o.realtime) pacer.WaitFor(now_ns);
  };
  flight.callbacks.on_event = [&](const engine::MissionEvent& e) {
    if (telemetry) {
      telemetry->RecordMissionEvent(e.time_ns, e.vehicle, e.step_index, e.step_kind, e.what);
    }
  };
  RunJobResult r;
  r.mission = job.FlyMission(mission, flight);
  if (telemetry) telemetry->Close();
  r.wall_s = job.wall_s();
  return r;
}

}  // namespace airis::tools
