#include "scenes/limits_doc.h"

#include "engine/core/config.h"
#include "engine/core/error.h"
#include "engine/core/limits.h"
#include "engine/world/vehicle_command.h"

namespace airis::scenes {

using namespace engine;  // the limits' names, as limits.h spells them

namespace {

std::string Count(std::size_t n) {
  std::string digits = std::to_string(n);
  for (int i = static_cast<int>(digits.size()) - 3; i > 0; i -= 3) digits.insert(i, ",");
  return digits;
}

/// A whole quantity given as a double (m, s), with thousands separators.
std::string Whole(double value) { return Count(static_cast<std::size_t>(value)); }

std::string Mebibytes(std::uintmax_t bytes) { return Count(bytes >> 20) + " MiB"; }

}  // namespace

std::span<const LimitDoc> Limits() {
  static const LimitDoc kLimits[] = {
      {"size of a scene, mission or campaign file", Mebibytes(kMaxYamlFileBytes),
       "`airis` SCENE, `--mission`, `include`"},
      {"values read from one file, each expansion of a YAML alias counted", Count(kMaxYamlValues),
       "any file"},
      {"entries of one list", Count(kMaxListEntries),
       "`objects`, `waypoints_ned_m`, `polygon_ne_m`, `steps`, ..."},
      {"depth of include chains", Count(kMaxIncludeDepth), "`include`"},
      {"files read through includes (each at most once)", Count(kMaxIncludedFiles), "`include`"},
      {"objects and vehicles of a scene (ground, generated objects and vehicle bodies included: "
       "each has an instance id)",
       Count(kMaxInstances), "`objects`, `repeat`, `generators`, `vehicles`"},
      {"objects and vehicles of a scene with a camera writing 16-bit grey instance images",
       Count(kMaxGray16Instances), "`camera.instance_format: gray16`"},
      {"size of a mesh file", Mebibytes(kMaxMeshFileBytes), "`mesh`, `car_mesh`"},
      {"triangles of one mesh file (declared counts checked before reading)",
       Count(kMaxMeshTriangles), "`mesh`, `car_mesh`"},
      {"vertices of one mesh file (declared counts checked before reading)",
       Count(kMaxMeshVertices), "`mesh`, `car_mesh`"},
      {"triangles stored for a whole scene", Count(kMaxSceneTriangles),
       "`mesh`, `car_mesh`, generators"},
      {"side of a texture image", Count(kMaxTextureSide_px) + " px", "`material.texture`"},
      {"size of a texture file", Mebibytes(kMaxTextureFileBytes), "`material.texture`"},
      {"distance of any position from the world origin", Whole(kMaxCoordinate_m) + " m",
       "`position_ned_m`, `repeat`, `area`, `ground.size_ne_m`, mission targets"},
      {"height above the origin a mission may fly to", Whole(kMaxFlightHeight_m) + " m",
       "mission steps"},
      {"street blocks of one city", Count(kMaxCityBlocks), "`city.area`, `city.block_size_ne_m`"},
      {"Poisson-disc grid cells of one forest", Count(kMaxForestGridCells),
       "`forest.area`, `forest.min_spacing_m`"},
      {"samples of the terrain heightfield", Count(kMaxTerrainSamples),
       "`terrain.extent_ne_m`, `terrain.resolution_m`"},
      {"pixels of a DEM file read for one terrain (the window under its grid)",
       Count(kMaxDemWindowPixels), "`terrain.dem`, `terrain.extent_ne_m`"},
      {"lines of one survey", Count(kMaxSurveyLines), "`survey.polygon_ne_m`, `survey.spacing_m`"},
      {"rays of one lidar scan (channels x columns)", Count(kMaxLidarRaysPerScan),
       "`lidar.channels`, `lidar.horizontal_resolution_deg`"},
      {"side of a camera image", Count(kMaxImageSide_px) + " px",
       "`camera.width_px`, `camera.height_px`"},
      {"pixels of a camera image", Count(kMaxImagePixels), "`camera.width_px` x `height_px`"},
      {"radial distortion coefficients k1, k2, k3",
       "-" + FormatNumber(kMaxRadialDistortion) + " to " + FormatNumber(kMaxRadialDistortion),
       "`camera.distortion`"},
      {"tangential distortion coefficients p1, p2",
       "-" + FormatNumber(kMaxTangentialDistortion) + " to " +
           FormatNumber(kMaxTangentialDistortion),
       "`camera.distortion`"},
      {"level-of-detail tolerance of a camera",
       "0 to " + FormatNumber(kMaxDetailTolerance_px) + " px", "`camera.detail_tolerance_px`"},
      {"undistorted view of a distorted camera", "1/4 to 4 times the image on each axis",
       "`camera.distortion`"},
      {"actuators of a vehicle (rotors and tilt servos)", Count(kMaxActuators), "`rotors`"},
      {"lowest rate", FormatNumber(kMinRate_hz) + " Hz",
       "every `rate_hz`, `rotation_rate_hz`, `--truth-rate-hz`"},
      {"highest rate of a sensor, camera or log", "the scene's `physics.rate_hz`",
       "every `rate_hz`, `rotation_rate_hz`, `--truth-rate-hz`"},
      {"physics rate", Whole(kMinPhysicsRate_hz) + " to " + Whole(kMaxPhysicsRate_hz) + " Hz",
       "`physics.rate_hz`"},
      {"simulated duration of a mission step, its timeout and a whole mission",
       Whole(kMaxMissionDuration_s) + " s", "mission steps, `timeout_s`"},
      {"poses of one random_poses step", Count(kMaxRandomPoses), "`random_poses.count`"},
      {"length of a name", Count(kMaxNameLength) + " characters",
       "vehicle, sensor, camera, class and object names"},
      {"characters of a value quoted in an error message", Count(kMaxQuotedChars), "messages"},
      {"errors reported for one input before reading stops", Count(kMaxReportedErrors), "messages"},
  };
  return kLimits;
}

std::string LimitsMarkdown() {
  std::string out = "| what | limit | applies to |\n|---|---|---|\n";
  for (const LimitDoc& l : Limits()) {
    out += std::string("| ") + l.what + " | " + l.value + " | " + l.keys + " |\n";
  }
  return out;
}

}  // namespace airis::scenes
