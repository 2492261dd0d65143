#include "engine/dataset/pcd_file.h"

#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "engine/dataset/file_io.h"

namespace airis::engine {
namespace {

PointCloudSample TwoPointScan() {
  PointCloudSample scan;
  PointReturn a;
  a.p_S_m = Eigen::Vector3f(1.5f, -2.25f, 0.125f);
  a.range_m = 2.7f;
  a.intensity = 0.35f;
  a.time_offset_s = -0.0999f;
  a.ring = 15;
  a.column = 624;
  a.instance_id = 65535;
  a.class_id = 255;
  PointReturn b;
  b.p_S_m = Eigen::Vector3f(-99.0f, 0.0f, std::numeric_limits<float>::min());
  b.range_m = 99.0f;
  b.ring = 0;
  b.column = 100000;  // more columns than 16 bits hold
  b.instance_id = 1;
  b.class_id = 1;
  scan.points = {a, b};
  return scan;
}

TEST(PcdFileTest, AScanRoundTripsWithItsFieldsTypesAndValues) {
  const PointCloudSample scan = TwoPointScan();
  const std::vector<std::uint8_t> bytes = EncodeScanPcd(scan);
  const PcdCloud cloud = DecodePcd(bytes, "scan.pcd");
  // GIVEN the PCD v0.7 fields PCL and Open3D read: x y z float32, then the labels
  const std::vector<PcdField> want = {{"x", 'F', 4, ""},           {"y", 'F', 4, ""},
                                      {"z", 'F', 4, ""},           {"range_m", 'F', 4, ""},
                                      {"intensity", 'F', 4, ""},   {"time_offset_s", 'F', 4, ""},
                                      {"ring", 'U', 2, ""},        {"column", 'U', 4, ""},
                                      {"instance_id", 'U', 4, ""}, {"class_id", 'U', 1, ""}};
  EXPECT_EQ(cloud.fields, want);
  EXPECT_EQ(cloud.record_bytes, 35u);
  ASSERT_EQ(cloud.points, 2u);
  const std::string text(bytes.begin(), bytes.end());
  EXPECT_EQ(bytes.size(), text.find("DATA binary\n") + 12 + 2 * 35);  // packed, nothing after
  // THEN every value reads back bit for bit
  for (std::size_t i = 0; i < 2; ++i) {
    const PointReturn& p = scan.points[i];
    EXPECT_EQ(cloud.Get<float>(i, "x"), p.p_S_m.x());
    EXPECT_EQ(cloud.Get<float>(i, "y"), p.p_S_m.y());
    EXPECT_EQ(cloud.Get<float>(i, "z"), p.p_S_m.z());
    EXPECT_EQ(cloud.Get<float>(i, "range_m"), p.range_m);
    EXPECT_EQ(cloud.Get<float>(i, "intensity"), p.intensity);
    EXPECT_EQ(cloud.Get<float>(i, "time_offset_s"), p.time_offset_s);
    EXPECT_EQ(cloud.Get<std::uint16_t>(i, "ring"), p.ring);
    EXPECT_EQ(cloud.Get<std::uint32_t>(i, "column"), p.column);
    EXPECT_EQ(cloud.Get<std::uint32_t>(i, "instance_id"), p.instance_id);
    EXPECT_EQ(cloud.Get<std::uint8_t>(i, "class_id"), p.class_id);
  }
}

TEST(PcdFileTest, TheHeaderIsPlainPcdV07) {
  const std::vector<std::uint8_t> bytes = EncodeScanPcd(TwoPointScan());
  const std::string text(bytes.begin(), bytes.end());
  const std::string header = text.substr(0, text.find("DATA binary\n") + 12);
  EXPECT_EQ(header,
            "# .PCD v0.7 - Point Cloud Data file format\n"
            "VERSION 0.7\n"
            "FIELDS x y z range_m intensity time_offset_s ring column instance_id class_id\n"
            "SIZE 4 4 4 4 4 4 2 4 4 1\n"
            "TYPE F F F F F F U U U U\n"
            "COUNT 1 1 1 1 1 1 1 1 1 1\n"
            "WIDTH 2\n"
            "HEIGHT 1\n"
            "VIEWPOINT 0 0 0 1 0 0 0\n"
            "POINTS 2\n"
            "DATA binary\n");
  // An empty scan is a valid file with no points.
  const PcdCloud empty = DecodePcd(EncodeScanPcd(PointCloudSample{}), "empty.pcd");
  EXPECT_EQ(empty.points, 0u);
}

TEST(PcdFileTest, AShortOrForeignFileIsRefusedNamingIt) {
  std::vector<std::uint8_t> bytes = EncodeScanPcd(TwoPointScan());
  bytes.resize(bytes.size() - 1);
  try {
    DecodePcd(bytes, "short.pcd");
    FAIL();
  } catch (const DatasetIoError& e) {
    EXPECT_EQ(std::string(e.what()), "short.pcd: holds 69 bytes of points, expected 70");
  }
  const std::string ascii =
      "VERSION 0.7\nFIELDS x\nSIZE 4\nTYPE F\nCOUNT 1\nPOINTS 1\nDATA ascii\n1\n";
  EXPECT_THROW(
      DecodePcd({reinterpret_cast<const std::uint8_t*>(ascii.data()), ascii.size()}, "ascii.pcd"),
      DatasetIoError);
}

}  // namespace
}  // namespace airis::engine
