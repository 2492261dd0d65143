#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/frames.h"
#include "engine/mission/mission.h"
#include "scenes/scene.h"

namespace airis::tools {

/// What a scene resolves to, as `airis scene check` shows it: the sun for its date, time and place,
/// the effective airframe of every vehicle (its preset with the scene's overrides), the cameras by
/// the names datasets give them, and, with a mission, the cameras its capture steps record.
struct SceneReport {
  /// The sun the renderer lights the scene with.
  struct Sun {
    double azimuth_deg = 0.0;    ///< toward the sun, clockwise from north
    double elevation_deg = 0.0;  ///< above the horizon (negative below)
    /// Local solar time it was placed for (with the date and the origin's latitude), or unset when
    /// the scene gave the angles.
    std::optional<double> time_of_day_h;
    double date_decimal_year = 0.0;  ///< the environment's date
    double latitude_deg = 0.0;       ///< of the scene's origin
    double longitude_deg = 0.0;
  };
  /// One rotor of an airframe, untilted.
  struct Rotor {
    engine::Vec3 position_frd_m = engine::Vec3::Zero();  ///< from the centre of mass, body FRD
    engine::Vec3 thrust_direction_frd = engine::Vec3(0.0, 0.0, -1.0);  ///< unit, body FRD
    bool ccw = true;  ///< spin seen from the side the thrust points to
    double diameter_m = 0.0;
    bool tiltable = false;  ///< a tilt actuator turns it in flight
  };
  /// A vehicle's effective airframe.
  struct Airframe {
    std::string vehicle;
    std::string kind;
    std::string preset;
    double mass_kg = 0.0;
    engine::Mat3 inertia_frd_kg_m2 = engine::Mat3::Zero();  ///< about the centre of mass
    std::vector<Rotor> rotors;
    /// The equal command on every motor whose thrust balances the weight at the start position
    /// (thrust linear in the command: m g / sum F_max,i (-thrust_direction_i.z)); > 1: cannot
    /// hover. Not set for a vehicle without lifting rotors.
    std::optional<double> hover_command;
    double air_density_kg_m3 = 0.0;  ///< at the start position, for hover_command
    double gravity_m_s2 = 0.0;       ///< at the start position
  };
  /// An image stream, as a dataset names its folder.
  struct Camera {
    /// The camera, or a stereo eye `<sensor>_left` / `<sensor>_right`, prefixed `<vehicle>_`
    /// when another vehicle has a camera of the same name (engine::CalcDatasetNamePrefixes).
    std::string name;
    std::string vehicle;  ///< the vehicle it is mounted on
    std::string sensor;   ///< the sensor it belongs to (a stereo pair's name)
    std::string stream;   ///< its name on its vehicle (`name` without a vehicle prefix)
  };

  Sun sun;
  std::vector<Airframe> airframes;
  std::vector<Camera> cameras;
  /// With a mission: the file, and the cameras its capture steps record (all of the scene's for a
  /// step without a list), in the scene's order.
  std::optional<std::string> mission_file;
  std::vector<std::string> mission_cameras;
  /// What a user should know: the sun below the horizon, a vehicle that cannot hover, a capture
  /// step naming a camera the scene lacks.
  std::vector<std::string> warnings;
};

/// The report of `scene`, and of `mission` flown in it when given. Builds each vehicle from its
/// spec (throws ConfigError naming the vehicle on a config its class refuses).
SceneReport BuildSceneReport(const scenes::Scene& scene, const engine::Mission* mission = nullptr);

/// The report as text lines of `airis scene check` (labels padded to 12 columns, each line ending
/// in a newline; warnings as `warning     ...`).
std::string FormatSceneReport(const SceneReport& report);

/// The report as JSON: {"sun": {...}, "airframes": [...], "cameras": [...], "mission": {...} or
/// absent, "warnings": [...]}, keys named as in the files (units last, frames before them).
nlohmann::json SceneReportJson(const SceneReport& report);

}  // namespace airis::tools
