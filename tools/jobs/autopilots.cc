#include "tools/jobs/autopilots.h"

#include <memory>

#include "engine/mavlink/px4/hil_sensor_feed.h"

namespace airis::tools {

std::vector<AttachedAutopilot> AttachAutopilots(
    SimulationJob& job, const std::function<void(const std::string&)>& log) {
  namespace mavlink = engine::mavlink;
  std::vector<AttachedAutopilot> out;
  const scenes::Scene& scene = job.scene();
  engine::World& world = job.world();
  for (std::size_t i = 0; i < scene.vehicles.size(); ++i) {
    const scenes::VehicleDescription& d = scene.vehicles[i];
    if (d.autopilot.kind != mavlink::AutopilotKind::kPx4) continue;
    const engine::Vehicle& vehicle = world.vehicle(i);
    mavlink::Px4Autopilot::Options o;
    o.config = d.autopilot;
    o.vehicle = d.name;
    o.frame = &world.environment().frame();
    o.utc_start_us = mavlink::UnixTimeUsFromDecimalYear(scene.environment.date_decimal_year);
    o.actuator_count = vehicle.actuator_count();
    o.motor_count = vehicle.motor_count();
    o.log = log;
    auto px4 = std::make_unique<mavlink::Px4Autopilot>(o, world.sensors(i));
    if (log) {
      const std::string missing = px4->DescribeMissing();
      if (!missing.empty()) log("vehicle '" + d.name + "' lacks what PX4 needs:\n" + missing);
    }
    out.push_back({i, px4.get()});
    job.simulation().SetAutopilot(i, std::move(px4));
  }
  return out;
}

}  // namespace airis::tools
