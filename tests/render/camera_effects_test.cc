#include "engine/render/camera_effects.h"

#include <gtest/gtest.h>

#include <cmath>

namespace airis::engine {
namespace {

double Srgb(double c) { return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1 / 2.4) - 0.055; }
double Linear(double e) { return e <= 0.04045 ? e / 12.92 : std::pow((e + 0.055) / 1.055, 2.4); }

Image<std::uint8_t> Flat(int w, int h, std::uint8_t code) {
  Image<std::uint8_t> im;
  im.Resize(w, h, 4);
  for (std::size_t i = 0; i < im.pixels.size(); ++i) im.pixels[i] = (i % 4 == 3) ? 255 : code;
  return im;
}

CameraIntrinsics Pinhole(int w, int h, double hfov_deg) {
  return CameraIntrinsics::FromHorizontalFov(w, h, hfov_deg);
}

// GIVEN a flat field of mean signal mu electrons WHEN sampled N times THEN the digital numbers'
// mean and variance are EMVA 1288's: K mu and K^2 (mu + r^2) + 1/12, K = (2^bits - 1) / full well.
// Bounds: 5 standard errors of the sample mean (sqrt(var / N)) and of the sample variance
// (sqrt((m4 - var^2) / N), m4 the sample's fourth central moment), so a correct model fails about
// once in 3 million runs and a model off by a few percent fails always.
TEST(CameraEffectsTest, FlatFieldMeanAndVarianceFollowPoissonGaussianModel) {
  struct Case {
    double mean_e, full_well_e, read_e;
    int bits;
  };
  // Exact Poisson (below 20 e-) and its normal approximation, unit and fractional gains.
  const Case cases[] = {{12.0, 1023.0, 2.0, 10},
                        {50.0, 4095.0, 3.0, 12},
                        {800.0, 10000.0, 5.0, 12},
                        {6000.0, 10000.0, 3.0, 10},
                        {3000.0, 20000.0, 8.0, 16}};
  constexpr int kN = 200000;
  for (const Case& c : cases) {
    RandomStream rng(42);
    std::vector<double> dn(kN);
    double sum = 0.0;
    for (double& x : dn)
      sum += (x = SampleSensorDn(c.mean_e, c.full_well_e, c.read_e, c.bits, rng));
    const double mean = sum / kN;
    double m2 = 0.0, m4 = 0.0;
    for (double x : dn) {
      const double d2 = (x - mean) * (x - mean);
      m2 += d2;
      m4 += d2 * d2;
    }
    const double var = m2 / (kN - 1);
    m4 /= kN;
    const double gain = (std::ldexp(1.0, c.bits) - 1.0) / c.full_well_e;
    const double want_mean = gain * c.mean_e;
    const double want_var = gain * gain * (c.mean_e + c.read_e * c.read_e) + 1.0 / 12.0;
    SCOPED_TRACE("mean_e " + std::to_string(c.mean_e));
    EXPECT_NEAR(mean, want_mean, 5.0 * std::sqrt(want_var / kN));
    EXPECT_NEAR(var, want_var, 5.0 * std::sqrt((m4 - var * var) / kN));
  }
}

// The noise is Gaussian in shape, not only in its first two moments: with one DN per electron the
// share of draws beyond 3 sigma is the normal law's 0.27% (5 binomial standard errors).
TEST(CameraEffectsTest, NoiseTailsAreTheNormalLaws) {
  constexpr int kN = 400000;
  const double mean_e = 20000.0, full_well_e = 65535.0;  // 16 bits: 1 DN per electron
  RandomStream rng(9);
  int beyond = 0;
  for (int i = 0; i < kN; ++i) {
    const double z =
        (SampleSensorDn(mean_e, full_well_e, 0.0, 16, rng) - mean_e) / std::sqrt(mean_e);
    beyond += std::abs(z) > 3.0;
  }
  const double p = std::erfc(3.0 / std::sqrt(2.0));
  EXPECT_NEAR(beyond, kN * p, 5.0 * std::sqrt(kN * p * (1.0 - p)));
}

TEST(CameraEffectsTest, SignalClipsAtFullWell) {
  RandomStream rng(1);
  for (int i = 0; i < 1000; ++i) EXPECT_EQ(SampleSensorDn(5e4, 1e4, 3.0, 10, rng), 1023);
}

// cos^4 of the off-axis angle, from the pinhole closed form cos(theta) = 1 / |((u - cx) / fx,
// (v - cy) / fy, 1)|.
TEST(CameraEffectsTest, VignettingIsCosFourthOfTheOffAxisAngle) {
  const CameraIntrinsics k = Pinhole(640, 480, 90.0);
  for (const auto& [u, v] : {std::pair{0.0, 0.0}, {319.5, 239.5}, {639.0, 100.0}, {50.0, 479.0}}) {
    const double x = (u - k.cx_px) / k.fx_px, y = (v - k.cy_px) / k.fy_px;
    const double cos_theta = 1.0 / std::sqrt(x * x + y * y + 1.0);
    EXPECT_NEAR(CalcVignetting(k, u, v), std::pow(cos_theta, 4), 1e-12) << u << " " << v;
  }
  // A 90 degree lens: the edge's middle is 45 degrees off axis, so it gets a quarter.
  EXPECT_NEAR(CalcVignetting(k, k.cx_px + k.fx_px, k.cy_px), 0.25, 1e-12);
}

TEST(CameraEffectsTest, VignettedImageFollowsTheMap) {
  CameraEffectsConfig config;
  config.vignetting = true;
  const CameraIntrinsics k = Pinhole(64, 48, 100.0);
  const CameraEffects effects(config, k, 1);
  Image<std::uint8_t> im = Flat(64, 48, 200);
  effects.Apply(im, 0);
  for (const auto& [u, v] : {std::pair{0, 0}, {32, 24}, {63, 10}}) {
    const double want = 255.0 * Srgb(Linear(200 / 255.0) * CalcVignetting(k, u, v));
    EXPECT_NEAR(im.at(u, v, 1), want, 0.5 + 1e-9) << u << " " << v;
    EXPECT_EQ(im.at(u, v, 3), 255);
  }
}

// One stop more exposure doubles the linear signal; codes that would pass 1.0 saturate.
TEST(CameraEffectsTest, ExposureScalesLinearSignalByPowersOfTwo) {
  CameraEffectsConfig config;
  config.exposure_ev = 1.0;
  const CameraEffects effects(config, Pinhole(4, 4, 60.0), 1);
  for (int code : {0, 10, 60, 128, 200, 255}) {
    Image<std::uint8_t> im = Flat(4, 4, static_cast<std::uint8_t>(code));
    EXPECT_DOUBLE_EQ(effects.Apply(im, 0), 1.0);
    const double want = 255.0 * Srgb(std::min(1.0, 2.0 * Linear(code / 255.0)));
    EXPECT_NEAR(im.at(1, 1, 0), want, 0.5 + 1e-9) << code;
  }
}

TEST(CameraEffectsTest, AutoExposureBringsMeanLuminanceToTarget) {
  CameraEffectsConfig config;
  config.auto_exposure = true;
  config.auto_exposure_target = 0.18;
  const CameraEffects effects(config, Pinhole(8, 8, 60.0), 1);
  for (int code : {20, 90, 240}) {
    Image<std::uint8_t> im = Flat(8, 8, static_cast<std::uint8_t>(code));
    const double ev = effects.Apply(im, 0);
    EXPECT_NEAR(ev, std::log2(0.18 / Linear(code / 255.0)), 1e-6);
    // Within half an 8-bit step of the target, in linear terms.
    const double got = Linear(im.at(3, 3, 0) / 255.0);
    EXPECT_NEAR(got, 0.18, 0.5 / 255.0 / 0.5) << code;
  }
}

// The noise of a frame depends on the seed and its time only.
TEST(CameraEffectsTest, NoiseIsReproducibleFromSeedAndTime) {
  CameraEffectsConfig config;
  config.noise = true;
  const CameraIntrinsics k = Pinhole(32, 24, 60.0);
  const CameraEffects a(config, k, 7), b(config, k, 7), other(config, k, 8);
  auto noisy = [](const CameraEffects& e, TimeNs t) {
    Image<std::uint8_t> im = Flat(32, 24, 120);
    e.Apply(im, t);
    return im.pixels;
  };
  const auto first = noisy(a, 1000);
  noisy(a, 2000);  // another frame in between changes nothing
  EXPECT_EQ(noisy(a, 1000), first);
  EXPECT_EQ(noisy(b, 1000), first);
  EXPECT_NE(noisy(a, 2000), first);
  EXPECT_NE(noisy(other, 1000), first);
  EXPECT_NE(first, Flat(32, 24, 120).pixels);
}

// A frame's adjusted full well renders as a camera configured with it: the same bytes, noise
// turned on by the adjustment.
TEST(CameraEffectsTest, AnAdjustedFullWellIsTheConfiguredOne) {
  const CameraIntrinsics k = Pinhole(32, 24, 60.0);
  CameraEffectsConfig configured;
  configured.noise = true;
  configured.full_well_e = 1500.0;
  const CameraEffects with_it(configured, k, 7);
  const CameraEffects plain(CameraEffectsConfig{}, k, 7);
  CameraEffectsAdjustment adjustment;
  adjustment.full_well_e = 1500.0;
  EXPECT_TRUE(plain.active(adjustment));
  Image<std::uint8_t> a = Flat(32, 24, 120), b = Flat(32, 24, 120);
  with_it.Apply(a, 1000);
  plain.Apply(b, 1000, adjustment);
  EXPECT_EQ(a.pixels, b.pixels);
  EXPECT_NE(a.pixels, Flat(32, 24, 120).pixels);
}

TEST(CameraEffectsTest, AllOffByDefault) {
  EXPECT_FALSE(CameraEffectsConfig{}.any());
  EXPECT_FALSE(CameraEffects(CameraEffectsConfig{}, Pinhole(4, 4, 60.0), 1).active());
  EXPECT_TRUE(CameraEffects(CameraEffectsConfig{}, Pinhole(4, 4, 60.0), 1)
                  .active({0.0, std::optional<double>(2.0), std::nullopt}));
}

TEST(CameraEffectsTest, ValidateNamesTheField) {
  CameraEffectsConfig config;
  config.adc_bits = 20;
  try {
    config.Validate();
    FAIL();
  } catch (const InvalidField& e) {
    EXPECT_EQ(e.field(), "adc_bits");
  }
  config = {};
  config.read_noise_e = -1.0;
  EXPECT_THROW(config.Validate(), InvalidField);
}

}  // namespace
}  // namespace airis::engine
