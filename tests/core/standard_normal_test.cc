#include "engine/core/standard_normal.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

namespace airis::engine {
namespace {

double NormalCdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

// n draws of one of the two generators: StandardNormal one at a time, or StandardNormals in the
// IMU's blocks of twelve (an odd block of seven every tenth block, which uses a low half alone).
enum class Generator { kOneAtATime, kTwoPerDraw };

std::vector<double> Draw(Generator generator, std::uint64_t seed, int n) {
  RandomStream stream(seed);
  std::vector<double> x(n);
  if (generator == Generator::kOneAtATime) {
    for (double& v : x) v = StandardNormal(stream);
    return x;
  }
  std::size_t k = 0;
  for (int block = 0; k < x.size(); ++block) {
    const std::size_t size = std::min<std::size_t>(block % 10 == 9 ? 7 : 12, x.size() - k);
    StandardNormals(stream, std::span<double>(x).subspan(k, size));
    k += size;
  }
  return x;
}

class StandardNormalTest : public ::testing::TestWithParam<Generator> {};

INSTANTIATE_TEST_SUITE_P(BothGenerators, StandardNormalTest,
                         ::testing::Values(Generator::kOneAtATime, Generator::kTwoPerDraw),
                         [](const auto& info) {
                           return info.param == Generator::kOneAtATime ? "OneAtATime"
                                                                       : "TwoPerDraw";
                         });

TEST_P(StandardNormalTest, MomentsMatchTheNormalDistribution) {
  // GIVEN 4 million draws
  const int n = 4'000'000;
  const std::vector<double> draws = Draw(GetParam(), 123, n);
  double s1 = 0, s2 = 0, s3 = 0, s4 = 0;
  for (const double x : draws) {
    s1 += x;
    s2 += x * x;
    s3 += x * x * x;
    s4 += x * x * x * x;
  }
  // THEN mean 0, variance 1, skewness 0, kurtosis 3. Standard errors for n = 4e6: mean 5e-4,
  // variance 7e-4, skewness 1.2e-3, kurtosis 2.4e-3; tolerances are about 5 of them.
  EXPECT_NEAR(s1 / n, 0.0, 0.0025);
  EXPECT_NEAR(s2 / n, 1.0, 0.0035);
  EXPECT_NEAR(s3 / n, 0.0, 0.006);
  EXPECT_NEAR(s4 / n, 3.0, 0.012);
}

TEST_P(StandardNormalTest, DistributionAndTailsMatchTheNormalCdf) {
  const int n = 1'000'000;
  std::vector<double> x = Draw(GetParam(), 7, n);
  std::sort(x.begin(), x.end());
  // Kolmogorov-Smirnov distance: the 0.1% critical value for n = 1e6 is 1.95 / sqrt(n) = 0.00195.
  double d = 0.0;
  for (int i = 0; i < n; ++i) {
    const double cdf = NormalCdf(x[i]);
    d = std::max({d, std::abs(cdf - double(i) / n), std::abs(cdf - double(i + 1) / n)});
  }
  EXPECT_LT(d, 0.00195);
  // The tail beyond r = 3.654 comes from a separate branch: P(|x| > 4) = 6.33e-5, ~63 of 1e6
  // (Poisson sd 8); P(|x| > 3) = 2.70e-3 (2700, sd 52).
  const auto beyond = [&](double t) {
    return std::count_if(x.begin(), x.end(), [t](double v) { return std::abs(v) > t; });
  };
  EXPECT_NEAR(static_cast<double>(beyond(4.0)), 63.3, 40.0);
  EXPECT_NEAR(static_cast<double>(beyond(3.0)), 2700.0, 260.0);
}

TEST_P(StandardNormalTest, SameStreamSameDraws) {
  EXPECT_EQ(Draw(GetParam(), 5, 1000), Draw(GetParam(), 5, 1000));
  EXPECT_NE(Draw(GetParam(), 5, 1000), Draw(GetParam(), 6, 1000));
}

TEST_P(StandardNormalTest, SuccessiveDrawsAreUncorrelated) {
  // The two halves of one 64-bit draw (StandardNormals) must be independent, as must successive
  // draws: lag-1 and lag-2 correlations of 1e6 draws have a standard error of 1e-3.
  const int n = 1'000'000;
  const std::vector<double> x = Draw(GetParam(), 11, n);
  for (const int lag : {1, 2}) {
    double even = 0.0, odd = 0.0;  // pairs starting at even indices (one 64-bit draw) and odd ones
    for (int i = 0; i + lag < n; ++i) (i % 2 == 0 ? even : odd) += x[i] * x[i + lag];
    EXPECT_NEAR(even / (n / 2), 0.0, 0.005) << "lag " << lag;
    EXPECT_NEAR(odd / (n / 2), 0.0, 0.005) << "lag " << lag;
  }
}

TEST(StandardNormalsTest, MagnitudeBoundsAgreeWithTheFloatingPointTest) {
  // The integer compare of the 32-bit draws decides as StandardNormal's compare of the point with
  // the layer's next edge would, for the magnitudes on both sides of every layer's bound.
  for (std::size_t i = 0; i < 255; ++i) {
    const std::uint32_t k = ziggurat::kMagnitudeBounds[i];
    ASSERT_GT(k, 0u) << "layer " << i;
    EXPECT_LT((k - 1) * ziggurat::kMagnitudeScales[i], ziggurat::kLayerEdges[i + 1]) << i;
    EXPECT_GE(k * ziggurat::kMagnitudeScales[i], ziggurat::kLayerEdges[i + 1]) << i;
  }
  EXPECT_EQ(ziggurat::kMagnitudeBounds[255], 0u);  // the top layer is all wedge
}

}  // namespace
}  // namespace airis::engine
