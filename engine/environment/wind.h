#pragma once

#include <span>

#include "engine/core/clock.h"
#include "engine/core/config.h"
#include "engine/core/frames.h"
#include "engine/core/random.h"

namespace airis::engine {

/// Gust model added to the mean wind.
enum class GustModel {
  kNone,         ///< steady wind only
  kGaussMarkov,  ///< each axis an independent first-order Gauss-Markov process (seeded)
  kDryden,       ///< MIL-F-8785C Dryden turbulence spectra, one sigma and scale length (seeded)
};
/// Spellings of GustModel in files: none, gauss_markov, dryden.
std::span<const EnumName<GustModel>> EnumNames(GustModel);

/// Description of the wind: a constant mean vector plus optional gusts.
struct WindConfig {
  Vec3 mean_ned_m_s = Vec3::Zero();   ///< mean wind velocity (the velocity of the air), world NED
  GustModel gust = GustModel::kNone;  ///< gust model added to the mean
  double gust_sigma_m_s = 1.0;        ///< stationary standard deviation of each gust component
  double gust_correlation_s = 2.0;    ///< Gauss-Markov correlation time
  /// Dryden turbulence scale length (low altitude: about the altitude, at least 20 m).
  double dryden_length_m = 200.0;

  template <class V>
  void Visit(V& v) {
    v.Field("mean_ned_m_s", mean_ned_m_s, "mean air velocity [north, east, down] (m/s)");
    v.Field("gust", gust, "none, gauss_markov or dryden");
    v.Field("gust_sigma_m_s", gust_sigma_m_s, "gust standard deviation per axis (m/s)");
    v.Field("gust_correlation_s", gust_correlation_s, "Gauss-Markov correlation time (s)");
    v.Field("dryden_length_m", dryden_length_m, "Dryden scale length (m)");
  }
  /// Throws InvalidField for a non-finite mean, a negative sigma, or a non-positive correlation
  /// time or scale length.
  void Validate() const;
};

/// Wind velocity in the world. Gusts are a function of simulated time only (spatially uniform),
/// advanced once per tick by the Simulation; the same seed gives the same gusts. Both gust models
/// start in their stationary distribution (the gust has its configured sigma from time 0) and are
/// discretised exactly for any step:
///  - Gauss-Markov, per world axis: x_{k+1} = a x_k + sigma sqrt(1 - a^2) n_k,
///    a = exp(-dt / tau), n_k ~ N(0, 1); autocorrelation sigma^2 exp(-|t| / tau).
///  - Dryden (MIL-F-8785C), with T = L / V: the longitudinal component (along the horizontal
///    mean-wind direction; north in calm air) is first order, sigma sqrt(2T) / (1 + T s),
///    autocorrelation sigma^2 exp(-|t| / T); the lateral (horizontal, to the right) and vertical
///    components are second order, sigma sqrt(T) (1 + sqrt(3) T s) / (1 + T s)^2, autocorrelation
///    sigma^2 exp(-|t| / T) (1 - |t| / 2T).
class Wind {
 public:
  /// Airspeed below which the Dryden time scale L / V stops growing (m/s).
  static constexpr double kMinDrydenAirspeed_m_s = 1.0;
  /// Airspeed at which the Dryden state is drawn at construction (m/s), the default of Advance.
  static constexpr double kDefaultAirspeed_m_s = 10.0;

  /// Throws InvalidField when `config` fails Validate().
  Wind(const WindConfig& config, RandomStream stream);

  /// Advances the gust state to `now_ns` (monotonic; steps of any size, exact discretisation).
  /// `airspeed_m_s` sets the Dryden filters' time scale (L / V); ignored by the other models.
  /// A time before the last Advance is a programming error (AIRIS_DEMAND).
  void Advance(TimeNs now_ns, double airspeed_m_s = kDefaultAirspeed_m_s);
  /// Wind velocity (m/s, world NED) at `p_W` at the time of the last Advance: the same everywhere
  /// (the models have no spatial structure), worked out once per Advance, not per vehicle.
  Vec3 CalcVelocity_W(const Vec3& p_W) const {
    (void)p_W;
    return velocity_W_;
  }
  /// Gust part of the wind (m/s, world NED) at the time of the last Advance.
  const Vec3& gust_W() const { return gust_now_W_; }
  /// Replaces the mean wind (mission step `set_wind`); the gust state is kept.
  void set_mean_ned_m_s(const Vec3& mean) {
    config_.mean_ned_m_s = mean;
    UpdateVelocity();
  }
  /// The description, with the current mean wind.
  const WindConfig& config() const { return config_; }

 private:
  // Exact transition of the second-order Dryden shaping filter over one step, and its process noise
  // as a lower-triangular Cholesky factor.
  struct DrydenStep {
    double decay = 0.0;  // exp(-p dt)
    double shear = 0.0;  // dt exp(-p dt)
    double l11 = 0.0, l21 = 0.0, l22 = 0.0;
  };
  static DrydenStep MakeDrydenStep(double rate_1_s, double dt_s);
  void AdvanceGaussMarkov(double dt_s);
  void AdvanceDryden(double dt_s, double airspeed_m_s);
  void StepSecondOrder(const DrydenStep& step, Eigen::Vector2d& z);
  // The gust and the wind velocity from the models' state and the mean wind.
  Vec3 CalcGust_W() const;
  void UpdateVelocity();

  WindConfig config_;
  RandomStream stream_;
  TimeNs last_ns_ = 0;
  Vec3 gust_W_ = Vec3::Zero();  // Gauss-Markov state, world NED (m/s)
  // Dryden state: longitudinal component (m/s) and the two states (z1, z2) of each second-order
  // filter.
  double dryden_u_m_s_ = 0.0;
  Eigen::Vector2d dryden_lateral_ = Eigen::Vector2d::Zero();
  Eigen::Vector2d dryden_vertical_ = Eigen::Vector2d::Zero();
  double dryden_rate_1_s_ = 0.0;  // p = V / L of the last step
  // Cached coefficients for the last step size (steps are usually all equal).
  double cached_dt_s_ = -1.0;
  double cached_rate_1_s_ = -1.0;
  double gm_decay_ = 0.0, gm_noise_ = 0.0;
  double dryden_u_decay_ = 0.0, dryden_u_noise_ = 0.0;
  DrydenStep dryden_step_;
  Vec3 gust_now_W_ = Vec3::Zero();  // CalcGust_W() of the current state
  Vec3 velocity_W_ = Vec3::Zero();  // mean + gust
};

}  // namespace airis::engine
