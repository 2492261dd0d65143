// The side of dem_file.h and geotiff_export.h that every process links: it loads the GDAL plugin
// (gdal_plugin.h) when a DEM is first read or written, and calls into it.

#include <dlfcn.h>

#include <cstdlib>
#include <mutex>

#include "engine/core/error.h"
#include "engine/dataset/file_io.h"
#include "scenes/dem_file.h"
#include "scenes/gdal_plugin.h"
#include "scenes/geotiff_export.h"

namespace airis::scenes {
namespace {

constexpr engine::EnumName<DemHeights> kHeightNames[] = {{DemHeights::kMsl, "msl"},
                                                         {DemHeights::kEllipsoid, "ellipsoid"}};

// The plugin's file, or why it could not be loaded (kept: a second attempt would fail alike).
struct LoadedPlugin {
  const GdalPluginApi* api = nullptr;
  std::string error;
};

LoadedPlugin Load() {
  const char* from_env = std::getenv("AIRIS_GDAL_PLUGIN");
  const std::string path = from_env != nullptr && *from_env ? from_env : AIRIS_GDAL_PLUGIN_PATH;
  // RTLD_LOCAL: GDAL's symbols stay out of the process's global scope.
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* why = dlerror();
    return {nullptr, "cannot load airis's GDAL plugin " + path + " (" + (why ? why : "?") +
                         "; set AIRIS_GDAL_PLUGIN to its path if the build was moved)"};
  }
  using Entry = const GdalPluginApi* (*)();
  auto entry = reinterpret_cast<Entry>(dlsym(handle, kGdalPluginEntry));
  const GdalPluginApi* api = entry != nullptr ? entry() : nullptr;
  if (api == nullptr || api->abi_version != kGdalPluginAbiVersion) {
    return {nullptr, path + " is not this build's GDAL plugin (rebuild airis)"};
  }
  return {api, ""};  // never unloaded: GDAL keeps drivers and caches for the process
}

}  // namespace

const GdalPluginApi* FindGdalPlugin(std::string* error) {
  static std::once_flag once;
  static LoadedPlugin plugin;
  std::call_once(once, [] { plugin = Load(); });
  if (plugin.api == nullptr) *error = plugin.error;
  return plugin.api;
}

std::span<const engine::EnumName<DemHeights>> EnumNames(DemHeights) { return kHeightNames; }

engine::Heightfield LoadDemTerrain(const DemSampling& sampling,
                                   const engine::LocalNedFrame& frame) {
  std::string error;
  const GdalPluginApi* gdal = FindGdalPlugin(&error);
  if (gdal == nullptr)
    throw engine::InvalidField("dem", "cannot read " + sampling.path + ": " + error);
  return gdal->load_dem_terrain(sampling, frame);
}

void WriteTerrainGeoTiff(const engine::Heightfield& field, const engine::LocalNedFrame& frame,
                         double pixel_m,
                         const std::vector<std::pair<std::string, std::string>>& metadata,
                         const std::string& path) {
  std::string error;
  const GdalPluginApi* gdal = FindGdalPlugin(&error);
  if (gdal == nullptr) throw engine::DatasetIoError("cannot write " + path + ": " + error);
  gdal->write_terrain_geotiff(field, frame, pixel_m, metadata, path);
}

}  // namespace airis::scenes
