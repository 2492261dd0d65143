// The daylight model (engine/render/daylight.h) against published values and the properties of the
// models it cites: Kasten and Young's air mass table, the Rayleigh optical depth, Preetham's clear
// sky, the CIE overcast sky.
#include "engine/render/daylight.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace airis::engine {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

TEST(DaylightTest, AirMassIsKastenAndYoungs) {
  // 1 overhead; the plane-parallel 1 / cos z where the Earth's curvature hardly matters (60 deg:
  // within 0.3%), a little below it at 80 deg (curvature: within 4%, and below); 37.92 at the
  // horizon, the value Kasten and Young give for their formula there.
  EXPECT_NEAR(daylight::CalcRelativeAirMass(0.0), 1.0, 1e-3);
  EXPECT_NEAR(daylight::CalcRelativeAirMass(60.0 * kDeg), 2.0, 0.003 * 2.0);
  const double plane80 = 1.0 / std::cos(80.0 * kDeg);
  EXPECT_LT(daylight::CalcRelativeAirMass(80.0 * kDeg), plane80);
  EXPECT_GT(daylight::CalcRelativeAirMass(80.0 * kDeg), 0.96 * plane80);
  EXPECT_NEAR(daylight::CalcRelativeAirMass(90.0 * kDeg), 37.92, 0.01);
  // Below the horizon it stays at the horizon's.
  EXPECT_EQ(daylight::CalcRelativeAirMass(95.0 * kDeg), daylight::CalcRelativeAirMass(90.0 * kDeg));
}

TEST(DaylightTest, RayleighOpticalDepthIsThePublishedOne) {
  // Hansen and Travis (1974): 0.0973 at 550 nm, growing as about lambda^-4 toward the blue.
  EXPECT_NEAR(daylight::CalcRayleighOpticalDepth(0.55), 0.0973, 0.0002);
  EXPECT_NEAR(daylight::CalcRayleighOpticalDepth(0.45) / daylight::CalcRayleighOpticalDepth(0.55),
              std::pow(0.55 / 0.45, 4.0), 0.05 * std::pow(0.55 / 0.45, 4.0));
}

TEST(DaylightTest, TheSunReddensAndDimsTowardTheHorizon) {
  const Eigen::Vector3d noon = daylight::CalcSunTransmittance(90.0 * kDeg, 3.0);
  const Eigen::Vector3d low = daylight::CalcSunTransmittance(5.0 * kDeg, 3.0);
  // Overhead: exp(-(tau_R + tau_A)) per channel, the closed form at air mass 1.
  const double beta = 0.04608 * 3.0 - 0.04586;
  EXPECT_NEAR(noon[1],
              std::exp(-(daylight::CalcRayleighOpticalDepth(0.55) + beta * std::pow(0.55, -1.3)) *
                       daylight::CalcRelativeAirMass(0.0)),
              1e-12);
  // Low: dimmer in every channel, and blue loses most (red / blue grows).
  for (int c = 0; c < 3; ++c) EXPECT_LT(low[c], noon[c]);
  EXPECT_GT(low[0] / low[2], 2.0 * noon[0] / noon[2]);
  // Hazier air dims it more; below the horizon there is none.
  EXPECT_LT(daylight::CalcSunTransmittance(30.0 * kDeg, 8.0)[1],
            daylight::CalcSunTransmittance(30.0 * kDeg, 2.0)[1]);
  EXPECT_EQ(daylight::CalcSunTransmittance(-1.0 * kDeg, 3.0), Eigen::Vector3d::Zero());
}

TEST(DaylightTest, D65WhiteIsEqualRgb) {
  // The sRGB white point (x 0.3127, y 0.3290) at luminance 1 is R = G = B = 1 (IEC 61966-2-1),
  // to the 4 digits of the matrix.
  const Eigen::Vector3d rgb = daylight::XyYToLinearSrgb(0.3127, 0.3290, 1.0);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(rgb[c], 1.0, 2e-3);
}

TEST(DaylightTest, ClearSkyIsPreethamsDistribution) {
  const double sun_zenith = 60.0 * kDeg;
  const daylight::ClearSky sky(3.0, sun_zenith);
  // At the zenith the model gives its zenith values exactly (F(0, theta_s) / F(0, theta_s)).
  const Eigen::Vector3d zenith = sky.CalcYxy(0.0, sun_zenith);
  EXPECT_NEAR(zenith[0], sky.zenith_Yxy()[0], 1e-9 * zenith[0]);
  // Preetham's zenith luminance fit at T = 3, theta_s = 60 deg, by hand:
  // chi = (4/9 - 3/120)(pi - 2 pi/3) = 0.439241, Y_z = 7.1649 tan(chi) + 1.7727 = 5.13916 kcd/m^2.
  EXPECT_NEAR(zenith[0], 5139.16, 0.01);
  // A clear sky's zenith is blue: chromaticity below D65's white in x and y.
  EXPECT_LT(zenith[1], 0.3127);
  EXPECT_LT(zenith[2], 0.3290);
  // Circumsolar brightening: 5 deg from the sun is several times as bright as 90 deg from it at the
  // sun's height.
  EXPECT_GT(sky.CalcYxy(sun_zenith, 5.0 * kDeg)[0], 3.0 * sky.CalcYxy(sun_zenith, 90.0 * kDeg)[0]);
  // The zenith brightens as the sun climbs, and a hazier sky is whiter (closer to D65).
  EXPECT_GT(daylight::ClearSky(3.0, 20.0 * kDeg).zenith_Yxy()[0],
            daylight::ClearSky(3.0, 70.0 * kDeg).zenith_Yxy()[0]);
  const auto whiteness = [](const Eigen::Vector3d& Yxy) {
    return std::hypot(Yxy[1] - 0.3127, Yxy[2] - 0.3290);
  };
  EXPECT_LT(whiteness(daylight::ClearSky(8.0, sun_zenith).zenith_Yxy()),
            whiteness(daylight::ClearSky(2.0, sun_zenith).zenith_Yxy()));
}

TEST(DaylightTest, OvercastZenithLuminanceFollowsTheCieSky) {
  // E_h = 300 + 21,000 sin h lux and L_z = 9 E_h / (7 pi): at h = 30 deg, 10,800 lux and 4,420
  // cd/m^2.
  EXPECT_NEAR(daylight::CalcOvercastZenithLuminance(30.0 * kDeg), 9.0 * 10800.0 / (7.0 * M_PI),
              1e-6);
  EXPECT_NEAR(daylight::CalcOvercastZenithLuminance(-5.0 * kDeg), 9.0 * 300.0 / (7.0 * M_PI), 1e-9);
}

TEST(DaylightTest, SkyShadingOfEachModel) {
  SceneLighting light;
  light.sun_direction_W = Eigen::Vector3d(0.0, -std::cos(40.0 * kDeg), std::sin(40.0 * kDeg));
  // Gradient: what the scene configures.
  SkyShading g = CalcSkyShading(light);
  EXPECT_EQ(g.sun_rgb, light.sun_color_rgb);
  EXPECT_EQ(g.zenith_rgb, light.sky_zenith_rgb);
  EXPECT_EQ(g.ambient, light.ambient);
  // Clear: a blue zenith, a paler horizon, a sun a little dimmer than the noon colour.
  light.sky = SkyModel::kClear;
  const SkyShading c = CalcSkyShading(light);
  EXPECT_GT(c.zenith_rgb[2], c.zenith_rgb[0]);
  EXPECT_GT(c.horizon_rgb[0] / c.horizon_rgb[2], c.zenith_rgb[0] / c.zenith_rgb[2]);
  for (int k = 0; k < 3; ++k) {
    EXPECT_LT(c.sun_rgb[k], light.sun_color_rgb[k]);
    EXPECT_GT(c.sun_rgb[k], 0.5f * light.sun_color_rgb[k]);
  }
  // Overcast: no sun, all light from the sky, the horizon a third of the zenith.
  light.sky = SkyModel::kOvercast;
  const SkyShading o = CalcSkyShading(light);
  EXPECT_EQ(o.sun_rgb, Eigen::Vector3f::Zero());
  EXPECT_EQ(o.ambient, 1.0f);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(o.horizon_rgb[k], o.zenith_rgb[k] / 3.0f, 1e-6);
}

}  // namespace
}  // namespace airis::engine
