#include "sensors/magnetometer.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/sensors/sensor_test_util.h"

namespace airis::sensors {
namespace {

using engine::Vec3;
using testing::Truth;

constexpr engine::TimeNs kFirstSample = 20'000'000;  // one period of the 50 Hz default after t = 0

MagnetometerConfig NoiselessConfig() {
  MagnetometerConfig c;
  c.noise_gauss = 0.0;
  return c;
}

TEST(MagnetometerTest, NoiselessEqualsEnvironmentFieldInBodyAxes) {
  for (auto kind : {engine::MagneticModelKind::kWmm, engine::MagneticModelKind::kDipole}) {
    const engine::Environment env = testing::MakeEnvironment(kind);
    Magnetometer mag("mag", NoiselessConfig(), engine::RandomStream(1));
    Truth truth;
    truth.state.p_W = Vec3(100, -50, -30);
    truth.state.q_WB = engine::QuatFromEuler({0.2, -0.1, 0.7});
    mag.Update(truth.At(kFirstSample, env));
    const Vec3 expected_G =
        1e-5 * (truth.state.q_WB.conjugate() * env.CalcMagneticField_nT(truth.state.p_W));
    EXPECT_NEAR((mag.latest().field_S_gauss - expected_G).norm(), 0.0, 1e-15);
    EXPECT_GT(expected_G.norm(), 0.2);  // Earth's field is 0.25-0.65 G
  }
}

TEST(MagnetometerTest, NinetyDegreeYawSwapsNorthAndEast) {
  // GIVEN the field B = (N, E, D) at the origin and a vehicle yawed 90 deg (nose east)
  const engine::Environment env = testing::MakeEnvironment();
  Magnetometer mag("mag", NoiselessConfig(), engine::RandomStream(1));
  Truth truth;
  truth.state.q_WB = engine::QuatFromEuler({0.0, 0.0, engine::DegToRad(90.0)});
  mag.Update(truth.At(kFirstSample, env));
  const Vec3 B = 1e-5 * env.CalcMagneticField_nT(Vec3::Zero());
  // THEN forward reads east, right (south) reads -north, down reads down
  EXPECT_NEAR(mag.latest().field_S_gauss.x(), B.y(), 1e-12);
  EXPECT_NEAR(mag.latest().field_S_gauss.y(), -B.x(), 1e-12);
  EXPECT_NEAR(mag.latest().field_S_gauss.z(), B.z(), 1e-12);
}

TEST(MagnetometerTest, CalibrationErrorsApplyInOrder) {
  // m = K diag(s) B_S + h
  const engine::Environment env = testing::MakeEnvironment();
  MagnetometerConfig c = NoiselessConfig();
  c.scale_factor = Vec3(1.1, 0.9, 1.0);
  c.hard_iron_gauss = Vec3(0.05, -0.02, 0.1);
  c.soft_iron = {1.0, 0.1, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.2};
  Magnetometer mag("mag", c, engine::RandomStream(1));
  Truth truth;
  mag.Update(truth.At(kFirstSample, env));
  const Vec3 B = 1e-5 * env.CalcMagneticField_nT(Vec3::Zero());
  engine::Mat3 K;
  K << 1.0, 0.1, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.2;
  const Vec3 expected = K * Vec3(1.1 * B.x(), 0.9 * B.y(), B.z()) + c.hard_iron_gauss;
  EXPECT_NEAR((mag.latest().field_S_gauss - expected).norm(), 0.0, 1e-15);
}

TEST(MagnetometerTest, FieldIsReevaluatedAfterMovingTheConfiguredDistance) {
  // GIVEN the dipole (whose field changes measurably over kilometres) and a 10 m update distance
  const engine::Environment env = testing::MakeEnvironment(engine::MagneticModelKind::kDipole);
  Magnetometer mag("mag", NoiselessConfig(), engine::RandomStream(1));
  Truth truth;
  mag.Update(truth.At(kFirstSample, env));
  const Vec3 at_origin = mag.latest().field_S_gauss;
  // WHEN it moves 5 km in one step THEN the field is the one at the new place
  truth.state.p_W = Vec3(5000, 0, 0);
  mag.Update(truth.At(40'000'000, env));
  const Vec3 there = 1e-5 * env.CalcMagneticField_nT(truth.state.p_W);
  EXPECT_NEAR((mag.latest().field_S_gauss - there).norm(), 0.0, 1e-15);
  EXPECT_GT((there - at_origin).norm(),
            1e-4);  // the move is visible: the test can tell the two apart
  // AND a further 5 m move keeps it (cached), differing from the exact field by far less than the
  // noise
  truth.state.p_W = Vec3(5005, 0, 0);
  mag.Update(truth.At(60'000'000, env));
  EXPECT_EQ(mag.latest().field_S_gauss, there);
  EXPECT_LT((mag.latest().field_S_gauss - 1e-5 * env.CalcMagneticField_nT(truth.state.p_W)).norm(),
            1e-5);
}

TEST(MagnetometerTest, WhiteNoiseHasConfiguredSigma) {
  const engine::Environment env = testing::MakeEnvironment();
  Magnetometer mag("mag", {}, engine::RandomStream(4));
  Truth truth;
  const Vec3 B = 1e-5 * env.CalcMagneticField_nT(Vec3::Zero());
  double ss = 0.0;
  const int n = 10000;
  for (int k = 1; k <= n; ++k) {
    mag.Update(truth.At(static_cast<engine::TimeNs>(k) * 20'000'000, env));
    ss += (mag.latest().field_S_gauss - B).squaredNorm();
  }
  // 30,000 axis samples: relative standard error of sigma 0.4%; 5% tolerance.
  EXPECT_NEAR(std::sqrt(ss / (3 * n)) / 0.005, 1.0, 0.05);
}

TEST(MagnetometerTest, BadConfigurationNamesTheField) {
  MagnetometerConfig c;
  c.soft_iron = {1.0, 2.0};
  try {
    c.Validate();
    FAIL();
  } catch (const engine::InvalidField& e) {
    EXPECT_EQ(e.field(), "soft_iron");
  }
  c = MagnetometerConfig{};
  c.noise_gauss = -0.1;
  EXPECT_THROW(Magnetometer("mag", c, engine::RandomStream(1)), engine::InvalidField);
}

}  // namespace
}  // namespace airis::sensors
