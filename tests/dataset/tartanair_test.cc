#include "engine/dataset/tartanair.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "engine/core/camera_model.h"
#include "engine/dataset/file_io.h"
#include "tests/fixtures/temp_dir.h"

namespace airis::engine {
namespace {

namespace fs = std::filesystem;

// GIVEN a camera looking level to the north (optical z north, x east, y down) WHEN its orientation
// is given in TartanAir's camera frame (x forward, y right, z down) THEN that frame is the world
// NED frame itself.
TEST(TartanAirTest, LevelNorthCameraIsTheIdentity) {
  const Quat q_WC(CalcR_SC());  // the optical frame of a sensor frame aligned with NED
  const Quat q = ToTartanAirOrientation(q_WC);
  EXPECT_NEAR(std::abs(q.w()), 1.0, 1e-15);
  EXPECT_NEAR(q.vec().norm(), 0.0, 1e-15);
}

// GIVEN a camera yawed 90 degrees (looking east) and pitched 30 degrees down THEN TartanAir's x
// axis is its viewing direction and its y axis the image's right.
TEST(TartanAirTest, AxesAreForwardRightDown) {
  const Mat3 R_WS =
      (Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ()) * Eigen::AngleAxisd(-M_PI / 6, Vec3::UnitY()))
          .toRotationMatrix();
  const Mat3 R_WC = R_WS * CalcR_SC();
  const Mat3 R_WT = ToTartanAirOrientation(Quat(R_WC)).toRotationMatrix();
  EXPECT_LT((R_WT.col(0) - R_WC.col(2)).norm(), 1e-12);     // forward = optical axis
  EXPECT_LT((R_WT.col(1) - R_WC.col(0)).norm(), 1e-12);     // right = image x
  EXPECT_LT((R_WT.col(2) - R_WC.col(1)).norm(), 1e-12);     // down = image y
  EXPECT_NEAR(R_WT.col(0).y(), std::cos(M_PI / 6), 1e-12);  // looking east...
  EXPECT_NEAR(R_WT.col(0).z(), std::sin(M_PI / 6), 1e-12);  // ...and down (NED z positive)
}

TEST(TartanAirTest, NoReturnDepthIsTenThousandMetres) {
  Image<float> d;
  d.Resize(4, 1, 1);
  d.pixels = {2.5f, std::numeric_limits<float>::infinity(), 0.0f, std::nanf("")};
  const Image<float> t = ToTartanAirDepth(d);
  EXPECT_EQ(t.pixels, (std::vector<float>{2.5f, 10000.0f, 10000.0f, 10000.0f}));
}

TEST(TartanAirTest, FileNamesFollowTheTartanAirTools) {
  const TartanAirSlot slot{"front", "right"};
  EXPECT_EQ(TartanAirFramePath("/d", slot, "image", 42),
            fs::path("/d/tartanair/front/image_right/000042_right.png"));
  EXPECT_EQ(TartanAirFramePath("/d", slot, "depth", 7),
            fs::path("/d/tartanair/front/depth_right/000007_right_depth.npy"));
  EXPECT_EQ(TartanAirFramePath("/d", slot, "seg", 0),
            fs::path("/d/tartanair/front/seg_right/000000_right_seg.npy"));
  EXPECT_EQ(TartanAirPosePath("/d", slot), fs::path("/d/tartanair/front/pose_right.txt"));
}

TEST(TartanAirTest, PoseFileHasOneLinePerFrameAndMalformedCsvNamesTheLine) {
  const fs::path dir = airis::testing::TestTempDir() / "airis_tartanair_test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string header =
      "time_ns,time_s,frame,position_ned_x_m,position_ned_y_m,position_ned_z_m,"
      "attitude_cam_to_ned_w,attitude_cam_to_ned_x,attitude_cam_to_ned_y,attitude_cam_to_ned_z\n";
  std::ofstream(dir / "poses.csv") << header << "0,0,0,1.5,-2,-10,1,0,0,0\n"
                                   << "5,5e-9,1,1.25,-2,-10,0,1,0,0\n";
  WriteTartanAirPoses(dir / "poses.csv", dir / "pose_left.txt");
  std::ifstream in(dir / "pose_left.txt");
  std::string first, second, third;
  ASSERT_TRUE(std::getline(in, first));
  ASSERT_TRUE(std::getline(in, second));
  EXPECT_FALSE(std::getline(in, third));
  std::istringstream s(first);
  double v[7];
  for (double& x : v) s >> x;
  EXPECT_EQ(v[0], 1.5);
  EXPECT_EQ(v[1], -2.0);
  EXPECT_EQ(v[2], -10.0);
  EXPECT_NEAR(Quat(v[6], v[3], v[4], v[5]).norm(), 1.0, 1e-15);

  // Malformed poses.csv files are errors naming the file, and the line and column where there is
  // one.
  auto expect_error = [&](const char* name, const std::string& text, const std::string& message) {
    std::ofstream(dir / name) << text;
    try {
      WriteTartanAirPoses(dir / name, dir / "pose_bad.txt");
      ADD_FAILURE() << name << " was accepted";
    } catch (const DatasetIoError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  };
  expect_error("bad.csv", header + "0,0,0,1.5,-2,-10,1,0,0,0\n5,5e-9,1,north,-2,-10,0,1,0,0\n",
               "bad.csv:3: column 4: 'north' is not a number");
  expect_error("short.csv", "time_ns,frame\n0,0\n",
               "short.csv: no column 'position_ned_x_m' in the header");
}

TEST(TartanAirTest, ClassIdsAreWrittenAsUint8Npy) {
  Image<std::uint8_t> cls;
  cls.Resize(3, 2, 1);
  cls.pixels = {0, 1, 2, 250, 251, 255};
  const std::vector<std::uint8_t> npy = EncodeNpy(cls);
  const std::string text(npy.begin(), npy.end());
  EXPECT_NE(text.find("{'descr': '|u1', 'fortran_order': False, 'shape': (2, 3), }"),
            std::string::npos);
  EXPECT_EQ(npy.size() % 64, 6u);  // header padded to a multiple of 64, then 6 pixel bytes
  EXPECT_EQ(std::vector<std::uint8_t>(npy.end() - 6, npy.end()), cls.pixels);
}

}  // namespace
}  // namespace airis::engine
