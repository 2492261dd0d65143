#include "engine/mission/domain_randomization.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "engine/environment/sun.h"

namespace airis::engine {
namespace {

DomainRandomizationConfig EveryRange() {
  DomainRandomizationConfig c;
  c.sun_elevation_deg = Eigen::Vector2d(10.0, 60.0);
  c.sun_azimuth_deg = Eigen::Vector2d(-90.0, 90.0);
  c.fog_distance_m = Eigen::Vector2d(200.0, 2000.0);
  c.exposure_ev = Eigen::Vector2d(-1.0, 1.0);
  c.read_noise_e = Eigen::Vector2d(1.0, 10.0);
  return c;
}

constexpr TimeNs kFrame = 50'000'000;  // 20 Hz

TEST(DomainRandomizationTest, SameSeedSameDrawsInTheirRanges) {
  const DomainRandomizationConfig c = EveryRange();
  const SceneLighting scene;
  std::set<double> elevations;
  for (int k = 1; k <= 200; ++k) {
    const DomainDraw a = DrawDomain(c, 7, k * kFrame, scene);
    const DomainDraw b = DrawDomain(c, 7, k * kFrame, scene);
    EXPECT_EQ(DomainValues(c, a), DomainValues(c, b));
    EXPECT_NE(DomainValues(c, a), DomainValues(c, DrawDomain(c, 8, k * kFrame, scene)));
    const std::vector<double> v = DomainValues(c, a);
    ASSERT_EQ(v.size(), 5u);
    EXPECT_GE(v[0], 10.0);
    EXPECT_LT(v[0], 60.0);
    EXPECT_GE(v[1], -90.0);
    EXPECT_LT(v[1], 90.0);
    EXPECT_GE(v[2], 200.0);
    EXPECT_LT(v[2], 2000.0);
    EXPECT_GE(v[3], -1.0);
    EXPECT_LT(v[3], 1.0);
    EXPECT_GE(v[4], 1.0);
    EXPECT_LT(v[4], 10.0);
    elevations.insert(v[0]);
  }
  EXPECT_EQ(elevations.size(), 200u);  // per frame: every frame draws anew
}

// Each range has its own stream: adding one keeps the draws of the others.
TEST(DomainRandomizationTest, AddingARangeKeepsTheOthersDraws) {
  DomainRandomizationConfig fog_only;
  fog_only.fog_distance_m = Eigen::Vector2d(200.0, 2000.0);
  const SceneLighting scene;
  for (int k = 1; k <= 20; ++k) {
    EXPECT_EQ(DrawDomain(fog_only, 3, k * kFrame, scene).fog_distance_m,
              DrawDomain(EveryRange(), 3, k * kFrame, scene).fog_distance_m);
  }
}

TEST(DomainRandomizationTest, PerEpisodeDrawsOnce) {
  DomainRandomizationConfig c = EveryRange();
  c.per = RandomizeEvery::kEpisode;
  const SceneLighting scene;
  const std::vector<double> first = DomainValues(c, DrawDomain(c, 7, kFrame, scene));
  for (int k = 2; k <= 50; ++k)
    EXPECT_EQ(DomainValues(c, DrawDomain(c, 7, k * kFrame, scene)), first);
}

// A sun angle not randomized keeps the scene's; the conditions carry the sun the angles place.
TEST(DomainRandomizationTest, SunKeepsTheSceneAngleNotRandomized) {
  SceneLighting scene;
  scene.sun_direction_W = CalcSunDirection_W(135.0, 50.0);
  DomainRandomizationConfig c;
  c.sun_azimuth_deg = Eigen::Vector2d(0.0, 30.0);
  const DomainDraw d = DrawDomain(c, 1, kFrame, scene);
  EXPECT_NEAR(*d.sun_elevation_deg, 50.0, 1e-9);
  const FrameConditions f = d.ToFrameConditions();
  ASSERT_TRUE(f.sun_direction_W);
  EXPECT_TRUE(f.sun_direction_W->isApprox(CalcSunDirection_W(*d.sun_azimuth_deg, 50.0)));
  EXPECT_FALSE(f.fog_distance_m);
  EXPECT_FALSE(f.read_noise_e);
  EXPECT_EQ(f.exposure_ev_offset, 0.0);
  EXPECT_EQ(DomainColumns(c), (std::vector<std::string>{"sun_elevation_deg", "sun_azimuth_deg"}));
}

// A drawn time of day places the sun at the scene's latitude and date: the conditions carry the
// sun CalcSolarAngles gives for the drawn hour, and poses.csv gets the hour and the angles.
TEST(DomainRandomizationTest, TimeOfDayPlacesTheSunByTheScenesLatitudeAndDate) {
  SceneLighting scene;
  scene.solar_place = {47.4, 2026.5};
  DomainRandomizationConfig c;
  c.time_of_day_h = Eigen::Vector2d(6.0, 18.0);
  std::set<bool> morning;
  for (int k = 1; k <= 100; ++k) {
    const DomainDraw d = DrawDomain(c, 5, k * kFrame, scene);
    ASSERT_TRUE(d.time_of_day_h);
    EXPECT_GE(*d.time_of_day_h, 6.0);
    EXPECT_LT(*d.time_of_day_h, 18.0);
    double azimuth = 0.0, elevation = 0.0;
    CalcSolarAngles(47.4, 2026.5, *d.time_of_day_h, azimuth, elevation);
    EXPECT_EQ(*d.sun_elevation_deg, elevation);
    EXPECT_EQ(*d.sun_azimuth_deg, azimuth);
    EXPECT_TRUE(
        d.ToFrameConditions().sun_direction_W->isApprox(CalcSunDirection_W(azimuth, elevation)));
    // The sun stands east before solar noon, west after it.
    EXPECT_EQ(*d.sun_azimuth_deg<0.0, *d.time_of_day_h> 12.0) << *d.time_of_day_h;
    morning.insert(*d.time_of_day_h < 12.0);
  }
  EXPECT_EQ(morning.size(), 2u);
  EXPECT_EQ(DomainColumns(c),
            (std::vector<std::string>{"time_of_day_h", "sun_elevation_deg", "sun_azimuth_deg"}));
  // At solar noon on the equinox the sun stands due south, 90 - latitude high (Cooper's
  // declination is -0.4 deg that day).
  c.time_of_day_h = Eigen::Vector2d(12.0, 12.0);
  scene.solar_place = {47.4, 2026.0 + 79.0 / 365.0};
  const DomainDraw noon = DrawDomain(c, 5, kFrame, scene);
  EXPECT_NEAR(*noon.sun_elevation_deg, 90.0 - 47.4, 0.5);
  EXPECT_NEAR(std::abs(*noon.sun_azimuth_deg), 180.0, 1e-9);
  // The sun's angles and the time of day are one or the other.
  c.sun_elevation_deg = Eigen::Vector2d(10.0, 20.0);
  try {
    c.Validate();
    FAIL();
  } catch (const InvalidField& e) {
    EXPECT_EQ(e.field(), "time_of_day_h");
  }
}

// Each class named draws its own material from the ranges, writes its columns in the order of the
// classes, and its change goes to the class id the scene gives it.
TEST(DomainRandomizationTest, MaterialsAreDrawnPerClass) {
  DomainRandomizationConfig c;
  c.materials = MaterialRandomizationConfig{{"building", "car"},
                                            Eigen::Vector2d(0.5, 1.5),
                                            Eigen::Vector2d(-30.0, 30.0),
                                            std::nullopt,
                                            std::nullopt};
  c.Validate();
  EXPECT_EQ(DomainColumns(c),
            (std::vector<std::string>{"material_building_value", "material_building_hue_deg",
                                      "material_car_value", "material_car_hue_deg"}));
  const SceneLighting scene;
  std::set<double> values;
  for (int k = 1; k <= 50; ++k) {
    const DomainDraw d = DrawDomain(c, 4, k * kFrame, scene);
    ASSERT_EQ(d.materials.size(), 2u);
    for (const ClassMaterialChange& m : d.materials) {
      EXPECT_GE(m.value, 0.5);
      EXPECT_LT(m.value, 1.5);
      EXPECT_GE(m.hue_deg, -30.0);
      EXPECT_LT(m.hue_deg, 30.0);
      EXPECT_FALSE(m.roughness);
      values.insert(m.value);
    }
    const std::vector<double> v = DomainValues(c, d);
    EXPECT_EQ(v, (std::vector<double>{d.materials[0].value, d.materials[0].hue_deg,
                                      d.materials[1].value, d.materials[1].hue_deg}));
    const std::vector<std::uint8_t> ids{4, 11};
    const FrameConditions f = d.ToFrameConditions(ids);
    ASSERT_EQ(f.class_materials.size(), 2u);
    EXPECT_EQ(f.class_materials[0].class_id, 4);
    EXPECT_EQ(f.class_materials[1].class_id, 11);
    EXPECT_EQ(f.class_materials[1].value, d.materials[1].value);
  }
  EXPECT_EQ(values.size(), 100u);  // each class and frame its own draw
}

TEST(DomainRandomizationTest, MaterialClassesAreTheScenes) {
  DomainRandomizationConfig c;
  c.materials = MaterialRandomizationConfig{
      {"car", "bilding"}, Eigen::Vector2d(0.5, 1.5), std::nullopt, std::nullopt, std::nullopt};
  const std::vector<SemanticClass> classes{{3, "building"}, {8, "car"}};
  try {
    ResolveMaterialClasses(c, classes);
    FAIL();
  } catch (const InvalidField& e) {
    EXPECT_EQ(e.field(), "materials.classes[1]");
    EXPECT_NE(e.problem().find("did you mean 'building'"), std::string::npos) << e.problem();
  }
  c.materials->classes = {"car", "building"};
  EXPECT_EQ(ResolveMaterialClasses(c, classes), (std::vector<std::uint8_t>{8, 3}));
  // Checked: a class named twice, no class, no range, a range out of its bounds.
  const auto field_of = [](const DomainRandomizationConfig& config) {
    try {
      config.Validate();
    } catch (const InvalidField& e) {
      return e.field();
    }
    return std::string("valid");
  };
  c.materials->classes = {"car", "car"};
  EXPECT_EQ(field_of(c), "materials.classes[1]");
  c.materials->classes = {};
  EXPECT_EQ(field_of(c), "materials.classes");
  c.materials =
      MaterialRandomizationConfig{{"car"}, std::nullopt, std::nullopt, std::nullopt, std::nullopt};
  EXPECT_EQ(field_of(c), "materials.classes");
  c.materials->roughness = Eigen::Vector2d(0.2, 1.2);
  EXPECT_EQ(field_of(c), "materials.roughness[1]");
  c.materials->roughness.reset();
  c.materials->pattern_scale = Eigen::Vector2d(0.1, 2.0);
  EXPECT_EQ(field_of(c), "materials.pattern_scale[0]");
  c.materials->pattern_scale = Eigen::Vector2d(0.5, 2.0);
  EXPECT_EQ(field_of(c), "valid");
  EXPECT_EQ(DomainColumns(c), (std::vector<std::string>{"material_car_pattern_scale"}));
}

// The weather draws overcast with the share given, the conditions then ask for the overcast sky;
// the full well is drawn in its range and passed on.
TEST(DomainRandomizationTest, OvercastShareAndFullWell) {
  DomainRandomizationConfig c;
  c.overcast_share = 0.3;
  c.full_well_e = Eigen::Vector2d(2000.0, 9000.0);
  c.Validate();
  EXPECT_TRUE(c.any());
  EXPECT_EQ(DomainColumns(c), (std::vector<std::string>{"full_well_e", "overcast"}));
  const SceneLighting scene;
  int overcast = 0;
  const int n = 400;
  for (int k = 1; k <= n; ++k) {
    const DomainDraw d = DrawDomain(c, 2, k * kFrame, scene);
    const FrameConditions f = d.ToFrameConditions();
    ASSERT_TRUE(d.overcast);
    EXPECT_EQ(f.sky.has_value(), *d.overcast);
    if (f.sky) {
      EXPECT_EQ(*f.sky, SkyModel::kOvercast);
    }
    overcast += *d.overcast ? 1 : 0;
    EXPECT_GE(*f.full_well_e, 2000.0);
    EXPECT_LT(*f.full_well_e, 9000.0);
    EXPECT_EQ(DomainValues(c, d)[1], *d.overcast ? 1.0 : 0.0);
  }
  // Binomial(400, 0.3): mean 120, standard deviation 9.2; five of them either way.
  EXPECT_NEAR(overcast, 120, 46);
  c.overcast_share = 0.0;
  EXPECT_FALSE(*DrawDomain(c, 2, kFrame, scene).overcast);
  c.overcast_share = 1.0;
  EXPECT_TRUE(*DrawDomain(c, 2, kFrame, scene).overcast);
  c.overcast_share = 1.5;
  EXPECT_THROW(c.Validate(), InvalidField);
}

// The sun direction in NED: a sun due east at 30 degrees lights along -east and down.
TEST(DomainRandomizationTest, SunDirectionClosedForm) {
  const Eigen::Vector3d d = CalcSunDirection_W(90.0, 30.0);
  EXPECT_NEAR(d.x(), 0.0, 1e-12);
  EXPECT_NEAR(d.y(), -std::cos(M_PI / 6), 1e-12);
  EXPECT_NEAR(d.z(), 0.5, 1e-12);
  double az = 0.0, el = 0.0;
  CalcSunAngles(d, az, el);
  EXPECT_NEAR(az, 90.0, 1e-9);
  EXPECT_NEAR(el, 30.0, 1e-9);
}

TEST(DomainRandomizationTest, ValidateNamesTheRange) {
  DomainRandomizationConfig c;
  c.fog_distance_m = Eigen::Vector2d(500.0, 100.0);
  try {
    c.Validate();
    FAIL();
  } catch (const InvalidField& e) {
    EXPECT_EQ(e.field(), "fog_distance_m");
  }
  c = {};
  c.sun_elevation_deg = Eigen::Vector2d(0.0, 95.0);
  try {
    c.Validate();
    FAIL();
  } catch (const InvalidField& e) {
    EXPECT_EQ(e.field(), "sun_elevation_deg[1]");
  }
  c = {};
  c.fog_distance_m = Eigen::Vector2d(100.0, 200.0);
  c.visibility_m = Eigen::Vector2d(400.0, 800.0);
  try {
    c.Validate();
    FAIL();
  } catch (const InvalidField& e) {
    EXPECT_EQ(e.field(), "visibility_m");
  }
  c = {};
  c.turbidity = Eigen::Vector2d(1.0, 4.0);
  try {
    c.Validate();
    FAIL();
  } catch (const InvalidField& e) {
    EXPECT_EQ(e.field(), "turbidity[0]");
  }
  c = {};
  c.rain_mm_per_h = Eigen::Vector2d(10.0, 500.0);
  try {
    c.Validate();
    FAIL();
  } catch (const InvalidField& e) {
    EXPECT_EQ(e.field(), "rain_mm_per_h[1]");
  }
  EXPECT_FALSE(DomainRandomizationConfig{}.any());
}

TEST(DomainRandomizationTest, VisibilityTurbidityAndRainReachTheFrame) {
  // GIVEN visibility, turbidity and rain ranges
  DomainRandomizationConfig c;
  c.visibility_m = Eigen::Vector2d(300.0, 3000.0);
  c.turbidity = Eigen::Vector2d(2.0, 9.0);
  c.rain_mm_per_h = Eigen::Vector2d(0.0, 50.0);
  const SceneLighting scene;
  EXPECT_EQ(DomainColumns(c),
            (std::vector<std::string>{"visibility_m", "turbidity", "rain_mm_per_h"}));
  for (int k = 1; k <= 50; ++k) {
    const DomainDraw d = DrawDomain(c, 11, k * kFrame, scene);
    // THEN each frame's drawn values are in range, written as drawn, and the frame's fog is the
    // visibility's (Koschmieder: fog distance = V / 3.912) with the drawn turbidity
    ASSERT_TRUE(d.visibility_m && d.turbidity && d.fog_distance_m && d.rain_mm_per_h);
    EXPECT_GE(*d.rain_mm_per_h, 0.0);
    EXPECT_LT(*d.rain_mm_per_h, 50.0);
    EXPECT_GE(*d.visibility_m, 300.0);
    EXPECT_LT(*d.visibility_m, 3000.0);
    EXPECT_GE(*d.turbidity, 2.0);
    EXPECT_LT(*d.turbidity, 9.0);
    EXPECT_EQ(DomainValues(c, d),
              (std::vector<double>{*d.visibility_m, *d.turbidity, *d.rain_mm_per_h}));
    const FrameConditions f = d.ToFrameConditions();
    EXPECT_DOUBLE_EQ(*f.fog_distance_m, *d.visibility_m / 3.912);
    EXPECT_EQ(f.turbidity, d.turbidity);
    EXPECT_EQ(f.rain_mm_per_h, d.rain_mm_per_h);
  }
}

}  // namespace
}  // namespace airis::engine
