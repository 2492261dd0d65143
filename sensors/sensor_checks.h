#pragma once

#include <string>
#include <string_view>

#include "engine/core/error.h"
#include "engine/core/limits.h"

namespace airis::sensors {

/// Standard gravity, for converting data-sheet figures in g, mg and ug (ISO 80000-3).
inline constexpr double kStandardGravity_m_s2 = 9.80665;

/// Peak of the Allan deviation of a first-order Gauss-Markov process as a fraction of its
/// stationary sigma: sigma_A(T)^2 = 2 sigma^2 (tau_c / T) [1 - tau_c / (2T) (3 - 4 exp(-T/tau_c) +
/// exp(-2T/tau_c))] (IEEE Std 952-1997, annex C) is largest at T = 1.8926 tau_c, where sigma_A =
/// 0.617364 sigma. Sensors map a data sheet's bias instability B to the sigma whose Allan peak is
/// the flicker floor 0.664 B: sigma = kFlickerAllanFloor B / this = 1.076 B.
inline constexpr double kGaussMarkovAllanPeak = 0.6173642831;

/// Allan deviation of flicker (1/f) bias noise as a fraction of the bias instability B that a data
/// sheet gives: IEEE Std 952-1997 (annex C) reads B off the flat floor of the Allan curve, where
/// sigma_A = B sqrt(2 ln 2 / pi) = 0.664 B. Sensors put their bias model's Allan plateau there.
inline constexpr double kFlickerAllanFloor = 0.66428247026796;

/// Throws InvalidField(field) unless kMinRate_hz <= rate_hz <= physics_rate_hz: a sensor cannot
/// sample more often than the physics tick that produces its truth.
void RequireRateWithinPhysics(std::string_view field, double rate_hz, double physics_rate_hz);

/// Runs `config.Validate()` and prefixes the field of any InvalidField with `prefix` and a dot
/// (e.g. "mount.roll_deg"), so a nested struct's error names its full path.
template <class Config>
void ValidateNested(std::string_view prefix, const Config& config) {
  try {
    config.Validate();
  } catch (const engine::InvalidField& e) {
    throw engine::InvalidField(std::string(prefix) + "." + e.field(), e.problem());
  }
}

}  // namespace airis::sensors
