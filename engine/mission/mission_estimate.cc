#include "engine/mission/mission_estimate.h"

#include <cmath>
#include <numbers>
#include <variant>

#include "engine/mission/path.h"

namespace airis::engine {

double EstimateMissionDuration_s(const Mission& mission, const Vec3& start_W,
                                 const LocalNedFrame& frame) {
  const Vec3 home = start_W;
  Vec3 p = start_W;
  double total_s = 0.0;
  auto fly_path = [&](std::vector<Vec3> points, double corner_radius_m, double speed_m_s) {
    points.insert(points.begin(), p);
    const Path path(points, corner_radius_m);
    total_s += path.length_m() / speed_m_s;
    p = points.back();
  };
  for (const MissionStep& step : mission.steps) {
    if (const auto* t = std::get_if<TakeoffStep>(&step.spec)) {
      const Vec3 to(p.x(), p.y(), home.z() - t->altitude_m);
      total_s += std::abs(to.z() - p.z());
      p = to;
    } else if (const auto* g = std::get_if<GotoStep>(&step.spec)) {
      const Vec3 to = g->position_ned_m
                          ? *g->position_ned_m
                          : frame.ToNed({DegToRad((*g->geodetic)[0]), DegToRad((*g->geodetic)[1]),
                                         (*g->geodetic)[2]});
      total_s += (to - p).norm() / g->speed_m_s;
      p = to;
    } else if (const auto* path = std::get_if<PathStep>(&step.spec)) {
      fly_path(path->waypoints_ned_m, path->corner_radius_m, path->speed_m_s);
    } else if (const auto* s = std::get_if<SurveyStep>(&step.spec)) {
      fly_path(CalcLawnmowerWaypoints(s->polygon_ned_m, s->spacing_m, DegToRad(s->heading_deg),
                                      home.z() - s->altitude_m),
               s->corner_radius_m, s->speed_m_s);
    } else if (const auto* o = std::get_if<OrbitStep>(&step.spec)) {
      total_s += 2.0 * std::numbers::pi * o->radius_m * o->turns / o->speed_m_s;
    } else if (const auto* h = std::get_if<HoverStep>(&step.spec)) {
      total_s += h->duration_s;
    } else if (std::holds_alternative<YawStep>(step.spec)) {
      total_s += std::numbers::pi;  // half a turn at 1 rad/s
    } else if (std::holds_alternative<LandStep>(step.spec)) {
      total_s += std::abs(home.z() - p.z());
      p.z() = home.z();
    } else if (const auto* w = std::get_if<WaitStep>(&step.spec)) {
      total_s += w->duration_s;
    } else if (const auto* r = std::get_if<RandomPosesStep>(&step.spec)) {
      total_s += r->count * r->dwell_s;
    }
  }
  return total_s;
}

}  // namespace airis::engine
