#include "engine/core/standard_normal.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace airis::engine {
namespace {

double NormalCdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

TEST(StandardNormalTest, MomentsMatchTheNormalDistribution) {
  // GIVEN 4 million draws
  RandomStream stream(123);
  const int n = 4'000'000;
  double s1 = 0, s2 = 0, s3 = 0, s4 = 0;
  for (int i = 0; i < n; ++i) {
    const double x = StandardNormal(stream);
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

TEST(StandardNormalTest, DistributionAndTailsMatchTheNormalCdf) {
  RandomStream stream(7);
  const int n = 1'000'000;
  std::vector<double> x(n);
  for (double& v : x) v = StandardNormal(stream);
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

TEST(StandardNormalTest, SameStreamSameDraws) {
  RandomStream a(5);
  RandomStream b(5);
  for (int i = 0; i < 1000; ++i) ASSERT_EQ(StandardNormal(a), StandardNormal(b));
}

}  // namespace
}  // namespace airis::engine
