#include "tools/jobs/scene_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "engine/core/random.h"
#include "engine/environment/environment.h"
#include "engine/world/image_sensor.h"

namespace airis::tools {

namespace {

std::string Format(const char* format, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), format, value);
  return buffer;
}

std::string Vector(const engine::Vec3& v, const char* format = "%.4g") {
  return "[" + Format(format, v.x()) + ", " + Format(format, v.y()) + ", " + Format(format, v.z()) +
         "]";
}

std::string JoinNames(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

SceneReport::Sun ReportSun(const scenes::Scene& scene) {
  SceneReport::Sun sun;
  sun.azimuth_deg = engine::RadToDeg(scene.sun.azimuth_rad);
  // Clockwise from north in [0, 360).
  sun.azimuth_deg = std::fmod(std::fmod(sun.azimuth_deg, 360.0) + 360.0, 360.0);
  sun.elevation_deg = engine::RadToDeg(scene.sun.elevation_rad);
  sun.time_of_day_h = scene.sun.time_of_day_h;
  sun.date_decimal_year = scene.environment.date_decimal_year;
  sun.latitude_deg = engine::RadToDeg(scene.origin.latitude_rad);
  sun.longitude_deg = engine::RadToDeg(scene.origin.longitude_rad);
  return sun;
}

SceneReport::Airframe ReportAirframe(const scenes::VehicleDescription& v,
                                     const engine::Environment& environment) {
  std::unique_ptr<engine::Vehicle> vehicle;
  try {
    vehicle = v.spec->Build(v.name);
  } catch (const engine::InvalidField& e) {
    throw engine::ConfigError(v.where, v.key_path + "." + e.field(), e.problem());
  }
  SceneReport::Airframe a;
  a.vehicle = v.name;
  a.kind = v.kind;
  a.preset = v.preset;
  a.mass_kg = vehicle->body().mass_kg();
  a.inertia_frd_kg_m2 = vehicle->body().inertia_B();
  a.air_density_kg_m3 = environment.CalcAir(v.start.p_W).density_kg_m3;
  a.gravity_m_s2 = environment.CalcGravity_m_s2(v.start.p_W);
  double lift_per_command_N = 0.0;
  for (const engine::RotorLayout& r : vehicle->CalcRotorLayout()) {
    SceneReport::Rotor rotor;
    rotor.position_frd_m = r.position_B_m;
    rotor.thrust_direction_frd = r.thrust_axis_B;
    // RotorLayout's moment ratio is positive for a counter-clockwise rotor (PX4's CA_ROTORi_KM).
    rotor.ccw = r.moment_ratio_m > 0.0;
    rotor.diameter_m = r.diameter_m;
    rotor.tiltable = r.tilt_actuator >= 0;
    a.rotors.push_back(rotor);
    lift_per_command_N += r.max_thrust_per_density * a.air_density_kg_m3 * -r.thrust_axis_B.z();
  }
  if (lift_per_command_N > 0.0) a.hover_command = a.mass_kg * a.gravity_m_s2 / lift_per_command_N;
  return a;
}

}  // namespace

SceneReport BuildSceneReport(const scenes::Scene& scene, const engine::Mission* mission) {
  SceneReport report;
  report.sun = ReportSun(scene);
  if (report.sun.elevation_deg < 0.0) {
    report.warnings.push_back(
        "the sun is " + Format("%.1f", -report.sun.elevation_deg) +
        " deg below the horizon, but the renderer has no night: images are lit by the sky's "
        "ambient light as by day");
  }
  // The scene's own environment, as the world builder makes it (the wind stream is unused here).
  const engine::Environment environment(scene.environment, scene.origin,
                                        engine::RandomStreams(scene.seed).Stream("report"));
  for (const scenes::VehicleDescription& v : scene.vehicles) {
    report.airframes.push_back(ReportAirframe(v, environment));
    const SceneReport::Airframe& a = report.airframes.back();
    if (a.hover_command && *a.hover_command >= 1.0) {
      report.warnings.push_back("vehicle '" + v.name + "' cannot hover at its start: it needs " +
                                Format("%.3g", *a.hover_command) + " of its full thrust");
    }
  }
  // Cameras by their dataset names: a name two vehicles use is prefixed with the vehicle's.
  std::vector<engine::ImageSensorNames> sensors;
  for (const scenes::VehicleDescription& v : scene.vehicles) {
    for (const scenes::SensorDescription& s : v.sensors) {
      std::vector<std::string> streams = s.spec->ImageStreamNames(s.name);
      if (!streams.empty()) sensors.push_back({v.name, s.name, std::move(streams)});
    }
  }
  const std::vector<std::string> prefixes = engine::CalcDatasetNamePrefixes(sensors);
  for (std::size_t k = 0; k < sensors.size(); ++k) {
    for (const std::string& stream : sensors[k].streams) {
      report.cameras.push_back(
          {prefixes[k] + stream, sensors[k].vehicle, sensors[k].sensor, stream});
    }
  }
  if (mission == nullptr) return report;

  report.mission_file = mission->file;
  std::vector<bool> captured(report.cameras.size(), false);
  for (const engine::MissionTrack& track : mission->tracks) {
    // A track without a vehicle is flown by the scene's first (engine::MissionTrack::vehicle).
    const std::string vehicle = !track.vehicle.empty()   ? track.vehicle
                                : scene.vehicles.empty() ? std::string()
                                                         : scene.vehicles.front().name;
    std::vector<std::string> own;  // the track vehicle's cameras by their own names
    for (const SceneReport::Camera& camera : report.cameras) {
      if (camera.vehicle == vehicle) own.push_back(camera.stream);
    }
    for (std::size_t i = 0; i < track.steps.size(); ++i) {
      const engine::CaptureStep* step = track.steps[i].As<engine::CaptureStep>();
      if (step == nullptr || !step->enabled) continue;
      const std::vector<std::string>& names = step->cameras;
      for (std::size_t c = 0; c < report.cameras.size(); ++c) {
        const SceneReport::Camera& camera = report.cameras[c];
        if (camera.vehicle != vehicle) continue;
        const auto named = [&](const std::string& n) {
          return std::find(names.begin(), names.end(), n) != names.end();
        };
        if (names.empty() || named(camera.stream) || named(camera.sensor)) captured[c] = true;
      }
      for (const std::string& name : names) {
        const bool known = std::any_of(
            report.cameras.begin(), report.cameras.end(), [&](const SceneReport::Camera& camera) {
              return camera.vehicle == vehicle && (camera.stream == name || camera.sensor == name);
            });
        if (known) continue;
        const std::string path = (track.key_path.empty() ? "" : track.key_path + ".") + "steps[" +
                                 std::to_string(i) + "]";
        report.warnings.push_back("mission " + path + " (capture) names camera '" + name +
                                  "', which vehicle '" + vehicle + "' does not have (it has " +
                                  (own.empty() ? "none" : JoinNames(own)) + ")");
      }
    }
  }
  for (std::size_t c = 0; c < report.cameras.size(); ++c) {
    if (captured[c]) report.mission_cameras.push_back(report.cameras[c].name);
  }
  return report;
}

std::string FormatSceneReport(const SceneReport& report) {
  std::string out;
  const auto line = [&](const std::string& label, const std::string& text) {
    std::string padded = label;
    padded.resize(std::max<std::size_t>(padded.size() + 1, 12), ' ');
    out += padded + text + "\n";
  };
  const SceneReport::Sun& sun = report.sun;
  std::string placed = "given as angles";
  if (sun.time_of_day_h) {
    placed = "at " + Format("%.2f", *sun.time_of_day_h) + " h local solar time on " +
             Format("%.3f", sun.date_decimal_year) + " at latitude " +
             Format("%.4f", sun.latitude_deg) + " deg";
  }
  line("sun", "azimuth " + Format("%.1f", sun.azimuth_deg) + " deg, elevation " +
                  Format("%.1f", sun.elevation_deg) + " deg (" + placed + ")");
  for (const SceneReport::Airframe& a : report.airframes) {
    const engine::Mat3& I = a.inertia_frd_kg_m2;
    std::string text = a.vehicle + " (" + a.kind + " " + a.preset +
                       "): " + Format("%.4g", a.mass_kg) + " kg, inertia diag " +
                       Vector(I.diagonal(), "%.4g") + " kg m^2";
    if (I(0, 1) != 0.0 || I(0, 2) != 0.0 || I(1, 2) != 0.0) {
      text +=
          ", products [Ixy, Ixz, Iyz] " + Vector(engine::Vec3(I(0, 1), I(0, 2), I(1, 2)), "%.4g");
    }
    text += ", " + std::to_string(a.rotors.size()) + " rotors";
    if (a.hover_command) {
      text += ", hover command " + Format("%.3f", *a.hover_command) + " (air " +
              Format("%.4g", a.air_density_kg_m3) + " kg/m^3, g " + Format("%.5g", a.gravity_m_s2) +
              " m/s^2 at its start)";
    }
    line("airframe", text);
    for (std::size_t i = 0; i < a.rotors.size(); ++i) {
      const SceneReport::Rotor& r = a.rotors[i];
      line("  rotor " + std::to_string(i),
           Vector(r.position_frd_m) + " m FRD from the centre of mass, " + (r.ccw ? "ccw" : "cw") +
               ", thrust " + Vector(r.thrust_direction_frd, "%.3g") + ", " +
               Format("%.4g", r.diameter_m) + " m" + (r.tiltable ? ", tiltable" : ""));
    }
  }
  std::vector<std::string> cameras;
  for (const SceneReport::Camera& c : report.cameras)
    cameras.push_back(c.name + " (" + c.vehicle + ")");
  line("cameras", cameras.empty() ? "none" : JoinNames(cameras));
  if (report.mission_file) {
    line("captures", *report.mission_file + " records " +
                         (report.mission_cameras.empty() ? std::string("no camera")
                                                         : JoinNames(report.mission_cameras)));
  }
  for (const std::string& w : report.warnings) line("warning", w);
  return out;
}

nlohmann::json SceneReportJson(const SceneReport& report) {
  const auto vec = [](const engine::Vec3& v) { return nlohmann::json{v.x(), v.y(), v.z()}; };
  nlohmann::json out;
  const SceneReport::Sun& sun = report.sun;
  out["sun"] = {{"azimuth_deg", sun.azimuth_deg},
                {"elevation_deg", sun.elevation_deg},
                {"below_horizon", sun.elevation_deg < 0.0},
                {"time_of_day_h", sun.time_of_day_h ? nlohmann::json(*sun.time_of_day_h) : nullptr},
                {"date_decimal_year", sun.date_decimal_year},
                {"latitude_deg", sun.latitude_deg},
                {"longitude_deg", sun.longitude_deg}};
  nlohmann::json& airframes = out["airframes"] = nlohmann::json::array();
  for (const SceneReport::Airframe& a : report.airframes) {
    nlohmann::json rotors = nlohmann::json::array();
    for (const SceneReport::Rotor& r : a.rotors) {
      rotors.push_back({{"position_frd_m", vec(r.position_frd_m)},
                        {"thrust_direction_frd", vec(r.thrust_direction_frd)},
                        {"spin", r.ccw ? "ccw" : "cw"},
                        {"diameter_m", r.diameter_m},
                        {"tiltable", r.tiltable}});
    }
    const engine::Mat3& I = a.inertia_frd_kg_m2;
    airframes.push_back(
        {{"vehicle", a.vehicle},
         {"kind", a.kind},
         {"preset", a.preset},
         {"mass_kg", a.mass_kg},
         {"inertia_frd_kg_m2",
          {vec(I.row(0).transpose()), vec(I.row(1).transpose()), vec(I.row(2).transpose())}},
         {"rotor_count", a.rotors.size()},
         {"rotors", rotors},
         {"hover_command", a.hover_command ? nlohmann::json(*a.hover_command) : nullptr},
         {"air_density_kg_m3", a.air_density_kg_m3},
         {"gravity_m_s2", a.gravity_m_s2}});
  }
  nlohmann::json& cameras = out["cameras"] = nlohmann::json::array();
  for (const SceneReport::Camera& c : report.cameras) {
    cameras.push_back({{"name", c.name}, {"vehicle", c.vehicle}, {"sensor", c.sensor}});
  }
  if (report.mission_file) {
    out["mission"] = {{"file", *report.mission_file}, {"capture_cameras", report.mission_cameras}};
  }
  out["warnings"] = report.warnings;
  return out;
}

}  // namespace airis::tools
