// The scene's sun: placed by the time of day or by angles, never both, and recorded in the scene.
#include "engine/environment/sun.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "scenes/scene.h"
#include "scenes/scene_config.h"
#include "tests/scenes/scene_error_of.h"

namespace airis::scenes {
namespace {

using engine::ConfigError;

// GIVEN lighting with time_of_day_h and a sun angle
// WHEN the scene loads
// THEN it is refused, naming both keys; each way alone places the sun (angles as given, or from
//      the time, latitude and date) and the scene records where.
TEST(SunTest, TimeOfDayAndSunAnglesAreExclusive) {
  EXPECT_EQ(SceneErrorOf("scene:\n  lighting:\n    time_of_day_h: 20\n    sun_elevation_deg: 30\n"),
            "scenes/v.yaml:4:5: scene.lighting.sun_elevation_deg: give time_of_day_h or "
            "sun_elevation_deg, not both (time_of_day_h places the sun from the latitude and "
            "date)");
  EXPECT_EQ(SceneErrorOf("scene:\n  lighting: {sun_azimuth_deg: 10, time_of_day_h: 9}\n"),
            "scenes/v.yaml:2:14: scene.lighting.sun_azimuth_deg: give time_of_day_h or "
            "sun_azimuth_deg, not both (time_of_day_h places the sun from the latitude and date)");

  const Scene given = LoadSceneFromString(
      "scene:\n  lighting: {sun_azimuth_deg: 200, sun_elevation_deg: 12}\n", "scenes/v.yaml");
  EXPECT_FALSE(given.sun.time_of_day_h);
  EXPECT_NEAR(engine::RadToDeg(given.sun.azimuth_rad), 200.0, 1e-12);
  EXPECT_NEAR(engine::RadToDeg(given.sun.elevation_rad), 12.0, 1e-12);
  const Scene defaults = LoadSceneFromString("ground: {enabled: false}\n", "scenes/v.yaml");
  EXPECT_NEAR(engine::RadToDeg(defaults.sun.elevation_rad),
              LightingConfig::kDefaultSunElevation_deg, 1e-12);

  // Solar noon at the equinox declination's day: elevation 90 - |latitude - declination|.
  const Scene noon = LoadSceneFromString(
      "scene:\n"
      "  origin: {latitude_deg: 47.0, longitude_deg: 8.0, altitude_m: 400}\n"
      "  environment: {date_decimal_year: 2026.5}\n"
      "  lighting: {time_of_day_h: 12}\n",
      "scenes/v.yaml");
  ASSERT_TRUE(noon.sun.time_of_day_h);
  double azimuth = 0.0, elevation = 0.0;
  engine::CalcSolarAngles(47.0, 2026.5, 12.0, azimuth, elevation);
  EXPECT_DOUBLE_EQ(noon.sun.elevation_rad, engine::DegToRad(elevation));
  const double day = 1.0 + 0.5 * 365.0;
  const double declination_deg = 23.45 * std::sin(2.0 * M_PI * (284.0 + day) / 365.0);
  EXPECT_NEAR(engine::RadToDeg(noon.sun.elevation_rad), 90.0 - (47.0 - declination_deg), 1e-9);
  EXPECT_NEAR(std::abs(engine::RadToDeg(noon.sun.azimuth_rad)), 180.0, 1e-9);  // due south
}

}  // namespace
}  // namespace airis::scenes
