// The GDAL plugin's entry point (gdal_plugin.h): the only symbol libairis_gdal.so exports.

#include "scenes/gdal_plugin.h"

extern "C" __attribute__((visibility("default"))) const airis::scenes::GdalPluginApi*
airis_gdal_plugin_api() {
  static const airis::scenes::GdalPluginApi api{airis::scenes::kGdalPluginAbiVersion,
                                                airis::scenes::GdalLoadDemTerrain,
                                                airis::scenes::GdalWriteTerrainGeoTiff};
  return &api;
}
