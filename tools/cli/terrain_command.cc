// `airis terrain export`: a scene's terrain written as a GeoTIFF elevation model with its
// provenance (docs/terrain.md).
#include <chrono>
#include <cstdio>
#include <ctime>
#include <memory>
#include <string>
#include <vector>

#include "scenes/scene_overrides.h"
#include "tools/cli/cli_util.h"
#include "tools/cli/commands.h"
#include "tools/jobs/terrain_export.h"

namespace airis::tools {
namespace {

struct TerrainOptions {
  std::string file;
  std::string out;
  std::string pixel_m;  // empty: the terrain's resolution
  std::vector<std::string> overrides;
};

// Today's date (UTC, ISO 8601): when the file was made, for its metadata only.
std::string TodayUtc() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[16];
  std::strftime(text, sizeof text, "%Y-%m-%d", &utc);
  return text;
}

}  // namespace

void AddTerrainCommand(CLI::App& app, int& exit_code) {
  CLI::App* cmd =
      app.add_subcommand("terrain", "Write a scene's terrain to an elevation model file");
  cmd->require_subcommand(1);
  auto options = std::make_shared<TerrainOptions>();

  CLI::App* out = cmd->add_subcommand(
      "export",
      "Write the scene's terrain as a GeoTIFF (WGS84, ellipsoidal heights, DEFLATE) with its "
      "provenance in the file's metadata; a scene's `terrain: {dem: FILE, heights: ellipsoid}` "
      "reads it back");
  out->add_option("file", options->file, "scene file (YAML)")->required()->type_name("PATH");
  out->add_option("--out", options->out, "GeoTIFF to write")->required()->type_name("PATH");
  out->add_option("--pixel-m", options->pixel_m,
                  "pixel size (m; default: the terrain's resolution_m)")
      ->type_name("METRES");
  AddSceneOverrideOption(out, options->overrides);
  SetCommandCallback(out, exit_code, [options]() -> std::function<int()> {
    SceneSource source;
    source.path = options->file;
    source.overrides = scenes::ParseSceneOverrides(options->overrides);
    double pixel_m = 0.0;
    if (!options->pixel_m.empty()) {
      pixel_m = ParseFiniteNumber("pixel-m", options->pixel_m);
      if (pixel_m <= 0.0) {
        throw engine::ConfigError({}, "--pixel-m", "must be > 0 (got " + options->pixel_m + ")");
      }
    }
    return [options, source, pixel_m] {
      const TerrainExport r = ExportTerrain(source, pixel_m, TodayUtc(), options->out);
      std::printf("wrote %s (%g m pixels; terrain %.2f to %.2f m above the origin)\n",
                  r.path.c_str(), r.pixel_m, r.lowest_m, r.highest_m);
      return 0;
    };
  });
}

}  // namespace airis::tools
