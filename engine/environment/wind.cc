#include "engine/environment/wind.h"

#include <array>
#include <cmath>
#include <limits>

#include "engine/core/error.h"

namespace airis::engine {
namespace {

constexpr double kSqrt3 = 1.7320508075688772;

// 1 - exp(-x) sum_{j=0..n} x^j / j!, the probability that a Poisson variable of mean x exceeds n,
// accurate for small x too (where the direct form cancels): there it is exp(-x) sum_{j>n} x^j / j!.
double PoissonTail(int n, double x) {
  if (std::isinf(x)) return 1.0;
  if (x < 0.5) {
    double term = 1.0;
    for (int j = 1; j <= n + 1; ++j) term *= x / j;  // x^(n+1) / (n+1)!
    double sum = 0.0;
    for (int j = n + 2; j < n + 30 && term > sum * 1e-18; ++j) {
      sum += term;
      term *= x / j;
    }
    return std::exp(-x) * sum;
  }
  double term = 1.0, sum = 1.0;
  for (int j = 1; j <= n; ++j) {
    term *= x / j;
    sum += term;
  }
  return 1.0 - std::exp(-x) * sum;
}

}  // namespace

std::span<const EnumName<GustModel>> EnumNames(GustModel) {
  static constexpr std::array<EnumName<GustModel>, 3> kNames{{
      {GustModel::kNone, "none"},
      {GustModel::kGaussMarkov, "gauss_markov"},
      {GustModel::kDryden, "dryden"},
  }};
  return kNames;
}

void WindConfig::Validate() const {
  RequireFinite("mean_ned_m_s", mean_ned_m_s);
  RequireNonNegative("gust_sigma_m_s", gust_sigma_m_s);
  RequirePositive("gust_correlation_s", gust_correlation_s);
  RequirePositive("dryden_length_m", dryden_length_m);
}

Wind::Wind(const WindConfig& config, RandomStream stream) : config_(config), stream_(stream) {
  config_.Validate();
  const double inf = std::numeric_limits<double>::infinity();
  // Start in the stationary distribution: a step of infinite length from rest.
  if (config_.gust == GustModel::kGaussMarkov) {
    AdvanceGaussMarkov(inf);
  } else if (config_.gust == GustModel::kDryden) {
    AdvanceDryden(inf, kDefaultAirspeed_m_s);
  }
  cached_dt_s_ = -1.0;
  UpdateVelocity();
}

void Wind::Advance(TimeNs now_ns, double airspeed_m_s) {
  AIRIS_DEMAND(now_ns >= last_ns_);
  const double dt_s = ToSeconds(now_ns - last_ns_);
  last_ns_ = now_ns;
  if (dt_s == 0.0) return;
  if (config_.gust == GustModel::kGaussMarkov) {
    AdvanceGaussMarkov(dt_s);
  } else if (config_.gust == GustModel::kDryden) {
    AdvanceDryden(dt_s, airspeed_m_s);
  } else {
    return;  // steady: the velocity stays the mean wind
  }
  UpdateVelocity();
}

void Wind::AdvanceGaussMarkov(double dt_s) {
  if (dt_s != cached_dt_s_) {
    // Exact discretisation of dx = -x / tau dt + sigma sqrt(2 / tau) dW: a = exp(-dt / tau) and
    // innovation sigma sqrt(1 - a^2), so the stationary standard deviation is sigma for any step.
    const double x = dt_s / config_.gust_correlation_s;
    gm_decay_ = std::exp(-x);
    gm_noise_ = config_.gust_sigma_m_s * std::sqrt(-std::expm1(-2.0 * x));
    cached_dt_s_ = dt_s;
  }
  for (int i = 0; i < 3; ++i) gust_W_[i] = gm_decay_ * gust_W_[i] + gm_noise_ * stream_.Gaussian();
}

Wind::DrydenStep Wind::MakeDrydenStep(double rate_1_s, double dt_s) {
  // States z1 = xi / (s + p), z2 = z1 / (s + p) driven by unit white noise xi: over a step dt the
  // transition is exp(-p dt) [[1, 0], [dt, 1]] and the noise covariance Q = [[I0, I1], [I1, I2]]
  // with Ik = integral_0^dt tau^k exp(-2 p tau) dtau, written through Poisson tails to stay exact
  // for tiny p dt.
  DrydenStep step;
  const double c = 2.0 * rate_1_s;
  const double x = c * dt_s;
  const double i0 = PoissonTail(0, x) / c;
  const double i1 = PoissonTail(1, x) / (c * c);
  const double i2 = 2.0 * PoissonTail(2, x) / (c * c * c);
  if (std::isinf(dt_s)) {
    step.decay = 0.0;
    step.shear = 0.0;
  } else {
    step.decay = std::exp(-rate_1_s * dt_s);
    step.shear = dt_s * step.decay;
  }
  step.l11 = std::sqrt(i0);
  step.l21 = i1 / step.l11;
  step.l22 = std::sqrt(std::max(0.0, i2 - step.l21 * step.l21));
  return step;
}

void Wind::StepSecondOrder(const DrydenStep& step, Eigen::Vector2d& z) {
  const double n1 = stream_.Gaussian(), n2 = stream_.Gaussian();
  const double z1 = step.decay * z.x() + step.l11 * n1;
  const double z2 = step.decay * z.y() + step.shear * z.x() + step.l21 * n1 + step.l22 * n2;
  z = Eigen::Vector2d(z1, z2);
}

void Wind::AdvanceDryden(double dt_s, double airspeed_m_s) {
  const double v =
      std::max(std::isfinite(airspeed_m_s) ? airspeed_m_s : 0.0, kMinDrydenAirspeed_m_s);
  const double rate = v / config_.dryden_length_m;  // p = 1 / T = V / L
  if (dt_s != cached_dt_s_ || rate != cached_rate_1_s_) {
    const double x = dt_s * rate;
    dryden_u_decay_ = std::isinf(dt_s) ? 0.0 : std::exp(-x);
    dryden_u_noise_ = config_.gust_sigma_m_s * std::sqrt(-std::expm1(-2.0 * x));
    dryden_step_ = MakeDrydenStep(rate, dt_s);
    cached_dt_s_ = dt_s;
    cached_rate_1_s_ = rate;
  }
  dryden_rate_1_s_ = rate;
  dryden_u_m_s_ = dryden_u_decay_ * dryden_u_m_s_ + dryden_u_noise_ * stream_.Gaussian();
  StepSecondOrder(dryden_step_, dryden_lateral_);
  StepSecondOrder(dryden_step_, dryden_vertical_);
}

Vec3 Wind::CalcGust_W() const {
  switch (config_.gust) {
    case GustModel::kNone:
      return Vec3::Zero();
    case GustModel::kGaussMarkov:
      return gust_W_;
    case GustModel::kDryden: {
      // Output of sigma sqrt(T) (1 + sqrt(3) T s) / (1 + T s)^2 = sigma sqrt(T) (sqrt(3) p z1 + (1
      // - sqrt(3)) p^2 z2) with T = 1 / p.
      const double p = dryden_rate_1_s_;
      const double gain = config_.gust_sigma_m_s / std::sqrt(p);
      const auto second_order = [&](const Eigen::Vector2d& z) {
        return gain * (kSqrt3 * p * z.x() + (1.0 - kSqrt3) * p * p * z.y());
      };
      const double u = dryden_u_m_s_, lateral = second_order(dryden_lateral_);
      const double vertical = second_order(dryden_vertical_);
      // Wind axes: longitudinal along the horizontal mean wind (north when calm), lateral to its
      // right.
      const Vec3& mean = config_.mean_ned_m_s;
      const double horizontal = std::hypot(mean.x(), mean.y());
      const double c = horizontal > 0.0 ? mean.x() / horizontal : 1.0;
      const double s = horizontal > 0.0 ? mean.y() / horizontal : 0.0;
      return Vec3(c * u - s * lateral, s * u + c * lateral, vertical);
    }
  }
  return Vec3::Zero();
}

void Wind::UpdateVelocity() {
  gust_now_W_ = CalcGust_W();
  velocity_W_ = config_.mean_ned_m_s + gust_now_W_;
}

}  // namespace airis::engine
