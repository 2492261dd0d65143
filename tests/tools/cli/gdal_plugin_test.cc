// The GDAL plugin (scenes/gdal_plugin.h) as the real `airis` binary loads it: only a scene with a
// DEM loads it, and one that cannot be loaded is reported on the scene's `dem` key.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "tests/tools/cli/airis_binary.h"

namespace airis::tools {
namespace {

using testing::BinaryResult;
using testing::RunAirisBinary;

const std::string kDemScene = std::string(AIRIS_SOURCE_DIR) + "/scenes/dem_hills.yaml";

TEST(GdalPluginTest, ASceneWithADemReadsItThroughThePlugin) {
  const BinaryResult r = RunAirisBinary({"scene", "check", kDemScene});
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("is valid"), std::string::npos) << r.out;
}

TEST(GdalPluginTest, APluginThatCannotBeLoadedIsReportedOnTheDemKey) {
  const BinaryResult r = RunAirisBinary({"scene", "check", kDemScene},
                                        {"AIRIS_GDAL_PLUGIN=/nonexistent/libairis_gdal.so"});
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  // file:line:column: key: the file it could not read, and why.
  EXPECT_NE(r.err.find("dem_hills.yaml:14:3: terrain.dem: cannot read "), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("cannot load airis's GDAL plugin /nonexistent/libairis_gdal.so"),
            std::string::npos)
      << r.err;
}

TEST(GdalPluginTest, ProcessesThatReadNoDemDoNotLoadGdal) {
  // The binary itself does not link GDAL (nor OpenCV's image codecs, which link it): its start
  // costs a few milliseconds, not the ~100 ms of loading GDAL's libraries.
  const BinaryResult r = RunAirisBinary({"--version"}, {"LD_DEBUG=libs"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("calling init"), std::string::npos) << "LD_DEBUG gave nothing: " << r.err;
  EXPECT_EQ(r.err.find("libgdal"), std::string::npos) << "libgdal was loaded";
  EXPECT_EQ(r.err.find("libopencv_imgcodecs"), std::string::npos) << "imgcodecs was loaded";
}

}  // namespace
}  // namespace airis::tools
