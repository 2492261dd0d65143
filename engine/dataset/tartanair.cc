#include "engine/dataset/tartanair.h"

#include <charconv>
#include <cmath>
#include <cstdio>

#include "engine/core/camera_model.h"
#include "engine/dataset/csv_reader.h"
#include "engine/dataset/file_io.h"

namespace airis::engine {
namespace {

void AppendNumber(std::string& line, double value) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof(buf), value);
  if (!line.empty()) line.push_back(' ');
  line.append(buf, r.ptr);
}

}  // namespace

std::filesystem::path TartanAirFramePath(const std::filesystem::path& root,
                                         const TartanAirSlot& slot, const char* kind,
                                         std::int64_t index) {
  const std::string folder = std::string(kind) + "_" + slot.side;
  const char* suffix = std::string_view(kind) == "image"   ? ".png"
                       : std::string_view(kind) == "depth" ? "_depth.npy"
                                                           : "_seg.npy";
  char name[64];
  std::snprintf(name, sizeof(name), "%06lld_%s%s", static_cast<long long>(index), slot.side.c_str(),
                suffix);
  return root / "tartanair" / slot.trajectory / folder / name;
}

std::filesystem::path TartanAirPosePath(const std::filesystem::path& root,
                                        const TartanAirSlot& slot) {
  return root / "tartanair" / slot.trajectory / ("pose_" + slot.side + ".txt");
}

Image<float> ToTartanAirDepth(const Image<float>& depth_planar_m) {
  Image<float> out = depth_planar_m;
  for (float& d : out.pixels) {
    if (!(std::isfinite(d) && d > 0.0f)) d = kTartanAirNoReturnDepthM;
  }
  return out;
}

Quat ToTartanAirOrientation(const Quat& q_WC) {
  // T is the sensor frame S of CalcR_SC (forward, right, down): R_WT = R_WC * R_CS.
  return Quat(q_WC.toRotationMatrix() * CalcR_SC().transpose()).normalized();
}

void WriteTartanAirPoses(const std::filesystem::path& poses_csv,
                         const std::filesystem::path& pose_txt) {
  const CsvText csv = ReadCsvText(poses_csv);
  const std::size_t px = csv.Column("position_ned_x_m"), py = csv.Column("position_ned_y_m"),
                    pz = csv.Column("position_ned_z_m");
  const std::size_t qw = csv.Column("attitude_cam_to_ned_w"),
                    qx = csv.Column("attitude_cam_to_ned_x"),
                    qy = csv.Column("attitude_cam_to_ned_y"),
                    qz = csv.Column("attitude_cam_to_ned_z");
  std::string text;
  for (std::size_t r = 0; r < csv.rows.size(); ++r) {
    const Quat q_WC(csv.Number(r, qw), csv.Number(r, qx), csv.Number(r, qy), csv.Number(r, qz));
    const Quat q = ToTartanAirOrientation(q_WC);
    std::string line;
    for (double v :
         {csv.Number(r, px), csv.Number(r, py), csv.Number(r, pz), q.x(), q.y(), q.z(), q.w()}) {
      AppendNumber(line, v);
    }
    text += line + '\n';
  }
  WriteFileAtomically(pose_txt, text);
}

}  // namespace airis::engine
