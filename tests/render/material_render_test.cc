// Materials as rendered (shaders/surface.glsl, shaders/scene.frag): patterns and metallic-roughness
// shading change the colour image only; a facade shows the storeys and window columns its pattern
// lengths ask for; black metal face on is almost black, and a black dielectric mirrors the sky,
// more at grazing angles.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "engine/core/image_codec.h"
#include "engine/dataset/file_io.h"
#include "engine/render/camera_renderer.h"
#include "engine/render/gpu_scene.h"
#include "tests/fixtures/temp_dir.h"
#include "tests/render/render_test_util.h"

namespace airis::engine {
namespace {

// Linear luminance (Rec. 709) of pixel (u, v) of an sRGB8 colour image.
double Luminance(const CameraFrame& frame, int u, int v) {
  const std::size_t i = 4 * (static_cast<std::size_t>(v) * frame.rgba.width + u);
  return 0.2126 * testing::SrgbToLinear(frame.rgba.pixels[i]) +
         0.7152 * testing::SrgbToLinear(frame.rgba.pixels[i + 1]) +
         0.0722 * testing::SrgbToLinear(frame.rgba.pixels[i + 2]);
}

// Pixel of world point p_W (it must be in front of the camera).
Eigen::Vector2i Project(const CameraIntrinsics& k, const Eigen::Isometry3d& T_WC,
                        const Eigen::Vector3d& p_W) {
  const Eigen::Vector3d p_C = T_WC.inverse() * p_W;
  return {static_cast<int>(std::floor(k.fx_px * p_C.x() / p_C.z() + k.cx_px)),
          static_cast<int>(std::floor(k.fy_px * p_C.y() / p_C.z() + k.cy_px))};
}

// Runs of pixels darker than `share` of the brightest along the samples (the wall between windows).
int CountDarkRuns(const std::vector<double>& luminance, double share) {
  const double bright = *std::max_element(luminance.begin(), luminance.end());
  int runs = 0;
  bool dark = false;
  for (double l : luminance) {
    const bool now = l < share * bright;
    if (now && !dark) ++runs;
    dark = now;
  }
  return runs;
}

TEST(MaterialRenderTest, PatternsAndShadingChangeTheColourImageOnly) {
  // GIVEN a ground and a box of every pattern, once plain and once with patterns, roughness and
  // metalness
  StaticScene plain = testing::MakeEmptyScene();
  testing::AddGround(plain, 2000.0, 1);
  const int patterns = static_cast<int>(EnumNames(SurfacePattern{}).size());
  for (int k = 1; k < patterns; ++k) {
    testing::AddBox(plain, {25.0 + 6.0 * k, -30.0 + 6.0 * k, -4.0}, {5.0, 5.0, 8.0}, 2,
                    static_cast<std::uint32_t>(10 + k));
  }
  StaticScene patterned = plain;
  patterned.materials[0].pattern = SurfacePattern::kGrass;
  for (int k = 1; k < patterns; ++k) {
    Material& m = patterned.materials[static_cast<std::size_t>(k)];
    m.pattern = static_cast<SurfacePattern>(k);
    m.roughness = 0.1f * static_cast<float>(k);
    m.metallic = k % 3 == 0 ? 1.0f : 0.0f;
    m.pattern_size_m = {3.0f, 2.5f};
  }
  SceneLighting light;
  light.sun_direction_W = Eigen::Vector3d(0.3, 0.5, 0.8).normalized();
  const auto camera = CameraIntrinsics::FromHorizontalFov(160, 120, 90.0, 0.1, 5000.0);
  const Eigen::Isometry3d T_WC = testing::LookPose({0.0, 0.0, -12.0}, 0.3, -10.0 * M_PI / 180);
  const CameraFrame a = testing::RenderColourDepthLabels(plain, light, camera, T_WC);
  const CameraFrame b = testing::RenderColourDepthLabels(patterned, light, camera, T_WC);
  // THEN depth and labels are the same to the byte
  EXPECT_EQ(a.depth_planar_m.pixels, b.depth_planar_m.pixels);
  EXPECT_EQ(a.class_id.pixels, b.class_id.pixels);
  EXPECT_EQ(a.instance_id.pixels, b.instance_id.pixels);
  // AND the colour of most pixels of the boxes and the ground differs
  int surface = 0;
  int changed = 0;
  for (std::size_t i = 0; i < a.class_id.pixels.size(); ++i) {
    if (a.class_id.pixels[i] == 0) continue;  // sky
    ++surface;
    if (std::memcmp(&a.rgba.pixels[4 * i], &b.rgba.pixels[4 * i], 3) != 0) ++changed;
  }
  EXPECT_GT(surface, 5000);
  EXPECT_GT(changed, surface * 8 / 10);
}

TEST(MaterialRenderTest, FacadeHasTheStoreysAndWindowColumnsOfItsPattern) {
  // GIVEN a wall 30 m wide and 19.5 m high (6 storeys of 3 m and a 1.5 m parapet) with a window
  // pitch of 2.9 m (the nearest whole number of columns across 30 m is 10), seen face on
  StaticScene scene = testing::MakeEmptyScene();
  testing::AddBox(scene, {0.0, 20.0, -9.75}, {30.0, 10.0, 19.5}, 2, 7,
                  Eigen::Vector3f::Constant(0.8f));
  scene.materials.back().pattern = SurfacePattern::kFacade;
  scene.materials.back().pattern_size_m = {3.0f, 2.9f};
  SceneLighting light;
  light.sun_direction_W = Eigen::Vector3d(0.2, 1.0, 0.6).normalized();  // onto the face
  const auto camera = CameraIntrinsics::FromHorizontalFov(320, 240, 60.0, 0.1, 1000.0);
  const Eigen::Isometry3d T_WC = testing::LookPose({0.0, -25.0, -9.75}, M_PI / 2, 0.0);
  const CameraFrame frame = testing::RenderColourDepthLabels(scene, light, camera, T_WC);
  // THEN across the middle of the fourth storey's windows (0.59 of a storey up) there are 10
  const double y_face = 15.0;
  const Eigen::Vector2i left = Project(camera, T_WC, {14.9, y_face, -(3.0 * 3.59)});
  const Eigen::Vector2i right = Project(camera, T_WC, {-14.9, y_face, -(3.0 * 3.59)});
  std::vector<double> row;
  for (int u = std::min(left.x(), right.x()); u <= std::max(left.x(), right.x()); ++u) {
    row.push_back(Luminance(frame, u, left.y()));
  }
  EXPECT_EQ(CountDarkRuns(row, 0.6), 10);
  // AND up the middle of the sixth column (1.5 m east of the centre) one window per storey, the
  // shop front included, and none in the parapet
  const Eigen::Vector2i base = Project(camera, T_WC, {1.5, y_face, -0.1});
  const Eigen::Vector2i top = Project(camera, T_WC, {1.5, y_face, -19.4});
  std::vector<double> column;
  for (int v = std::min(base.y(), top.y()); v <= std::max(base.y(), top.y()); ++v) {
    column.push_back(Luminance(frame, base.x(), v));
  }
  EXPECT_EQ(CountDarkRuns(column, 0.6), 6);
}

// Black ground of `roughness` under a sun behind the camera, seen by a 64x48 camera 10 m up looking
// straight down and 10 degrees down.
struct BlackGround {
  StaticScene scene = testing::MakeEmptyScene();
  SceneLighting light;
  CameraIntrinsics camera = CameraIntrinsics::FromHorizontalFov(64, 48, 60.0, 0.1, 5000.0);
  Eigen::Isometry3d down = testing::LookPose({0.0, 0.0, -10.0}, 0.0, -M_PI / 2);
  Eigen::Isometry3d oblique = testing::LookPose({0.0, 0.0, -10.0}, 0.0, -10.0 * M_PI / 180);

  explicit BlackGround(float roughness) {
    testing::AddGround(scene, 4000.0, 1);
    material().base_color_rgb.setZero();
    material().roughness = roughness;
    light.sun_direction_W = Eigen::Vector3d(-0.3, 0.0, 0.9).normalized();
  }
  Material& material() { return scene.materials.back(); }
  CameraFrame Render(const Eigen::Isometry3d& T_WC) const {
    return testing::RenderColourDepthLabels(scene, light, camera, T_WC);
  }
};

TEST(MaterialRenderTest, BlackMetalIsAlmostBlackFaceOnAndDielectricsReflectMoreAtGrazingAngles) {
  // GIVEN black ground, once a metal (F0 = albedo = 0) and once a dielectric (F0 = 0.04)
  BlackGround ground(0.3f);
  ground.material().metallic = 1.0f;
  const CameraFrame metal = ground.Render(ground.down);
  ground.material().metallic = 0.0f;
  const CameraFrame dielectric = ground.Render(ground.down);
  const CameraFrame dielectric_oblique = ground.Render(ground.oblique);
  // THEN seen face on the metal reflects almost nothing (Schlick: F = F0 = 0; what is left is the
  // bias of Karis's fit of the sky's reflectance, 0.003 at roughness 0.3) and the dielectric
  // reflects the sky's 4% and the sun's highlight
  const double metal_face_on = Luminance(metal, 32, 24);
  const double dielectric_face_on = Luminance(dielectric, 32, 24);
  EXPECT_GT(dielectric_face_on, 0.0);
  EXPECT_LT(metal_face_on, 0.1 * dielectric_face_on);
  // AND the dielectric reflects more at grazing angles (Fresnel): a row 2 deg below the horizon is
  // more than twice as bright as the bottom row (32 deg down)
  const double steep = Luminance(dielectric_oblique, 32, 47);
  const double grazing = Luminance(dielectric_oblique, 32, 16);
  EXPECT_GT(steep, 0.0);
  EXPECT_GT(grazing, 2.0 * steep);
}

// GIVEN black, rough paint (roughness 0.6) on the ground, once bare and once under the car_paint
// clear coat (a smooth dielectric, F0 0.04)
// THEN the coat adds the sky's mirror image: brighter face on, and far brighter at grazing angles,
// where Fresnel's reflectance of a smooth coat rises toward 1 while the rough paint's stays blurred
TEST(MaterialRenderTest, CarPaintsClearCoatMirrorsTheSky) {
  BlackGround ground(0.6f);
  const CameraFrame bare = ground.Render(ground.down);
  const CameraFrame bare_oblique = ground.Render(ground.oblique);
  ground.material().pattern = SurfacePattern::kCarPaint;
  const CameraFrame coated = ground.Render(ground.down);
  const CameraFrame coated_oblique = ground.Render(ground.oblique);
  EXPECT_GT(Luminance(coated, 32, 24), Luminance(bare, 32, 24));
  EXPECT_GT(Luminance(coated_oblique, 32, 16), 1.5 * Luminance(bare_oblique, 32, 16));
  // Depth and labels do not see it.
  EXPECT_EQ(coated.depth_planar_m.pixels, bare.depth_planar_m.pixels);
  EXPECT_EQ(coated.class_id.pixels, bare.class_id.pixels);
}

// Writes a w x h PNG whose every pixel is `rgb` (top half `rgb`, bottom half `bottom_rgb` when
// given) and returns its path.
std::string WritePng(const std::string& name, const cv::Vec3b& rgb, int w = 8, int h = 8,
                     const cv::Vec3b* bottom_rgb = nullptr) {
  std::vector<std::uint8_t> pixels(std::size_t(w) * h * 3);
  for (int v = 0; v < h; ++v) {
    const cv::Vec3b c = bottom_rgb != nullptr && v >= h / 2 ? *bottom_rgb : rgb;
    for (int u = 0; u < w; ++u) std::copy(c.val, c.val + 3, pixels.begin() + 3 * (w * v + u));
  }
  const std::string path = (airis::testing::TestTempDir() / name).string();
  WriteFileAtomically(path, EncodePng(pixels.data(), w, h, 3, PngLayout::kRgb8));
  return path;
}

TEST(MaterialRenderTest, TexturesAreUprightOnBoxes) {
  // GIVEN a box whose texture is red in the image's top half and blue in its bottom half
  StaticScene scene = testing::MakeEmptyScene();
  testing::AddBox(scene, {10.0, 0.0, -5.0}, {2.0, 8.0, 8.0}, 2, 2, Eigen::Vector3f::Ones());
  const cv::Vec3b blue(0, 0, 255);
  scene.materials.back().texture_path = WritePng("upright.png", {255, 0, 0}, 8, 8, &blue);
  SceneLighting light;
  light.sun_direction_W = Eigen::Vector3d(1.0, 0.0, 0.3).normalized();  // onto the face
  const auto camera = CameraIntrinsics::FromHorizontalFov(64, 64, 60.0, 0.1, 100.0);
  const CameraFrame frame = testing::RenderColourDepthLabels(
      scene, light, camera, testing::LookPose({0.0, 0.0, -5.0}, 0.0, 0.0));
  // THEN the face seen from the camera is red above and blue below
  const auto rgb = [&](int u, int v) {
    const std::size_t i = 4 * (static_cast<std::size_t>(v) * 64 + u);
    return Eigen::Vector3i(frame.rgba.pixels[i], frame.rgba.pixels[i + 1],
                           frame.rgba.pixels[i + 2]);
  };
  const Eigen::Vector3i top = rgb(32, 22);
  const Eigen::Vector3i bottom = rgb(32, 42);
  EXPECT_GT(top.x(), 4 * top.z()) << top.transpose();
  EXPECT_GT(bottom.z(), 4 * bottom.x()) << bottom.transpose();
}

// GIVEN the box of TexturesAreUprightOnBoxes with its texture once as a file and once as the same
//       bytes embedded in the scene (StaticScene::embedded_images: a GLB's images)
// THEN both render the same bytes
TEST(MaterialRenderTest, EmbeddedTexturesRenderAsTheirFiles) {
  const auto render = [](bool embedded) {
    StaticScene scene = testing::MakeEmptyScene();
    testing::AddBox(scene, {10.0, 0.0, -5.0}, {2.0, 8.0, 8.0}, 2, 2, Eigen::Vector3f::Ones());
    const cv::Vec3b blue(0, 0, 255);
    const std::string path = WritePng("embedded.png", {255, 0, 0}, 8, 8, &blue);
    scene.materials.back().texture_path = path;
    if (embedded) {
      std::ifstream in(path, std::ios::binary);
      const std::string bytes((std::istreambuf_iterator<char>(in)),
                              std::istreambuf_iterator<char>());
      scene.materials.back().texture_path = "model.glb#*0";
      scene.embedded_images["model.glb#*0"] = bytes;
    }
    SceneLighting light;
    light.sun_direction_W = Eigen::Vector3d(1.0, 0.0, 0.3).normalized();
    const auto camera = CameraIntrinsics::FromHorizontalFov(64, 64, 60.0, 0.1, 100.0);
    return testing::RenderColourDepthLabels(scene, light, camera,
                                            testing::LookPose({0.0, 0.0, -5.0}, 0.0, 0.0));
  };
  const CameraFrame from_file = render(false);
  const CameraFrame from_memory = render(true);
  EXPECT_EQ(from_memory.rgba.pixels, from_file.rgba.pixels);
  // AND the texture is drawn (the face's top is red)
  const std::size_t i = 4 * (22 * 64 + 32);
  EXPECT_GT(from_memory.rgba.pixels[i], 4 * from_memory.rgba.pixels[i + 2]);
}

// A wall face on to the camera, 10 m north of it, turned by R about its centre, seen under the sun
// alone (no sky light) shining along `sun_W`, with its material changed by `edit`; returns the
// centre pixel (linear luminance).
template <class Edit>
double WallCentre(const Eigen::Matrix3d& R, const Eigen::Vector3d& sun_W, Edit edit) {
  StaticScene scene = testing::MakeEmptyScene();
  testing::AddBox(scene, {10.5, 0.0, -5.0}, {1.0, 8.0, 8.0}, 2, 2, {0.6f, 0.6f, 0.6f});
  scene.objects.back().T_WO =
      Eigen::Translation3d(10.5, 0.0, -5.0) * R * Eigen::Scaling(1.0, 8.0, 8.0);
  edit(scene.materials.back());
  SceneLighting light;
  light.ambient = 0.0f;
  light.sun_direction_W = sun_W.normalized();
  const auto camera = CameraIntrinsics::FromHorizontalFov(33, 33, 20.0, 0.1, 100.0);
  const CameraFrame frame = testing::RenderColourDepthLabels(
      scene, light, camera, testing::LookPose({0.0, 0.0, -5.0}, 0.0, 0.0));
  return Luminance(frame, 16, 16);
}

std::uint8_t EncodeNormal(double c) {
  return static_cast<std::uint8_t>(std::lround(127.5 * (c + 1.0)));
}

TEST(MaterialRenderTest, NormalMapTurnsTheShadingNormalAsTurningTheWallWould) {
  // GIVEN a wall face on (its normal -x, toward the camera), once turned 20 deg toward the sun,
  // once flat with a normal map holding that turned normal in tangent space: the face's u runs
  // along +y and its v up (-z), so a normal turned toward -y is the map's (-sin, 0, cos) and one
  // turned up is (0, sin, cos). Sun from the south-west, level, then from the west, 40 deg up.
  const double angle = 20.0 * M_PI / 180;
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  struct Case {
    Eigen::Matrix3d R;
    Eigen::Vector3d sun_W;
    cv::Vec3b map;
  };
  const Case cases[] = {
      {Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix(),
       {0.6, 0.8, 0.0},
       {EncodeNormal(-std::sin(angle)), EncodeNormal(0.0), EncodeNormal(std::cos(angle))}},
      {Eigen::AngleAxisd(-angle, Eigen::Vector3d::UnitY()).toRotationMatrix(),
       {0.5, 0.6, 0.8},
       {EncodeNormal(0.0), EncodeNormal(std::sin(angle)), EncodeNormal(std::cos(angle))}},
  };
  int k = 0;
  for (const Case& c : cases) {
    const double turned = WallCentre(c.R, c.sun_W, [](Material&) {});
    const double flat = WallCentre(I, c.sun_W, [](Material&) {});
    const std::string map = WritePng("turned_normal" + std::to_string(k++) + ".png", c.map);
    const double mapped = WallCentre(I, c.sun_W, [&](Material& m) { m.normal_texture_path = map; });
    // THEN the mapped wall is shaded as the turned one (within the 8-bit map's resolution), not as
    // the flat one
    EXPECT_GT(turned, 1.05 * flat) << "case " << k;
    EXPECT_NEAR(mapped, turned, 0.01 * turned) << "case " << k << ", flat " << flat;
  }
}

TEST(MaterialRenderTest, NormalScaleTurnsTheMappedNormalAsGltfSays) {
  // GIVEN a flat wall face on whose normal map holds a normal turned 40 deg toward -y, with the
  // scale tan 20 / tan 40: glTF multiplies the map's x and y by it, which turns the normal 20 deg
  const double angle = 20.0 * M_PI / 180;
  const double mapped_angle = 40.0 * M_PI / 180;
  const Eigen::Vector3d sun_W(0.6, 0.8, 0.0);
  const std::string map =
      WritePng("turned_normal_40.png", {EncodeNormal(-std::sin(mapped_angle)), EncodeNormal(0.0),
                                        EncodeNormal(std::cos(mapped_angle))});
  const double turned =
      WallCentre(Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix(), sun_W,
                 [](Material&) {});
  const double scaled = WallCentre(Eigen::Matrix3d::Identity(), sun_W, [&](Material& m) {
    m.normal_texture_path = map;
    m.normal_scale = static_cast<float>(std::tan(angle) / std::tan(mapped_angle));
  });
  const double unscaled = WallCentre(Eigen::Matrix3d::Identity(), sun_W,
                                     [&](Material& m) { m.normal_texture_path = map; });
  const double flattened = WallCentre(Eigen::Matrix3d::Identity(), sun_W, [&](Material& m) {
    m.normal_texture_path = map;
    m.normal_scale = 0.0f;
  });
  const double flat = WallCentre(Eigen::Matrix3d::Identity(), sun_W, [](Material&) {});
  // THEN the scaled map shades the wall as turning it 20 deg would, not 40; scale 0 as flat
  EXPECT_NEAR(scaled, turned, 0.01 * turned) << "unscaled " << unscaled;
  EXPECT_GT(std::abs(unscaled - turned), 0.05 * turned);
  EXPECT_NEAR(flattened, flat, 0.01 * flat);
}

TEST(MaterialRenderTest, MetallicRoughnessMapScalesTheFactors) {
  const Eigen::Matrix3d kFaceOn = Eigen::Matrix3d::Identity();
  const Eigen::Vector3d kSunLevel(0.6, 0.8, 0.0);
  // GIVEN a wall with metallic 1 and roughness 1, once with a map of green 128 and blue 255
  // (roughness x 0.5, metalness x 1), once with roughness 0.5 set directly
  const std::string map = WritePng("metallic_roughness.png", {0, 128, 255});
  const double mapped = WallCentre(kFaceOn, kSunLevel, [&](Material& m) {
    m.metallic = 1.0f;
    m.roughness = 1.0f;
    m.metallic_roughness_texture_path = map;
  });
  const double direct = WallCentre(kFaceOn, kSunLevel, [](Material& m) {
    m.metallic = 1.0f;
    m.roughness = 128.0f / 255.0f;
  });
  const double rough = WallCentre(kFaceOn, kSunLevel, [](Material& m) {
    m.metallic = 1.0f;
    m.roughness = 1.0f;
  });
  // THEN the map gives what the factors give
  EXPECT_NEAR(mapped, direct, 0.01 * direct + 1e-4) << "rough " << rough;
  EXPECT_GT(std::abs(rough - direct), 0.05 * direct);
}

}  // namespace
}  // namespace airis::engine
