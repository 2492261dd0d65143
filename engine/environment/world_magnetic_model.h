#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "engine/environment/magnetic_field.h"

namespace airis::engine {

/// The World Magnetic Model (NOAA/BGS): spherical harmonics of degree and order N (12 for WMM2025)
/// with linear secular variation, evaluated at geodetic WGS84 positions. Reproduces NOAA's test
/// values to their printed precision. Source: "The US/UK World Magnetic Model for 2025-2030:
/// Technical Report", NOAA NCEI, 2024 (equations 7-12 and 17-19: geodetic to geocentric spherical
/// coordinates, the field in spherical components from the Schmidt semi-normalised associated
/// Legendre functions, and the rotation back to the geodetic north-east-down frame). A call costs
/// well under a microsecond and allocates nothing.
class WorldMagneticModel final : public MagneticFieldModel {
 public:
  /// Highest degree a model may have (the WMM's 12; the high-resolution WMMHR is not supported).
  static constexpr int kMaxDegree = 12;
  /// The model's altitude range (height above the WGS84 ellipsoid), from the technical report.
  static constexpr double kMinAltitude_m = -1000.0;
  static constexpr double kMaxAltitude_m = 850000.0;
  /// Years of validity after the epoch.
  static constexpr double kValidityYears = 5.0;

  /// WMM2025, from the coefficient file compiled into the airis library (data/wmm/WMM2025.COF).
  static const WorldMagneticModel& Wmm2025();

  /// A model from the text of a NOAA `.COF` coefficient file. `source_name` names the file in
  /// errors. Throws ConfigError with the line of a malformed record (or a degree above kMaxDegree).
  static WorldMagneticModel FromCofText(std::string_view text, const std::string& source_name);

  /// Field (NED, nT) at geodetic `where` on `decimal_year`. Throws std::out_of_range for a date
  /// outside [epoch, epoch + 5), an altitude outside [-1 km, 850 km], a latitude outside [-pi/2,
  /// pi/2] or a non-finite input. Longitude may be any finite angle.
  Vec3 CalcField_nT(const GeodeticPosition& where, double decimal_year) const override;
  /// Secular variation: the rate of change of the field (NED, nT per year) at `where` on
  /// `decimal_year`. Same validity and errors as CalcField_nT.
  Vec3 CalcSecularVariation_nT_yr(const GeodeticPosition& where, double decimal_year) const;
  std::string name() const override { return model_name_; }
  /// Decimal year of the coefficients (2025.0 for WMM2025).
  double epoch() const { return epoch_; }
  /// Degree and order N of the expansion.
  int degree() const { return degree_; }

 private:
  WorldMagneticModel() = default;
  // Throws std::out_of_range when (where, decimal_year) is outside the model's validity.
  void CheckValidity(const GeodeticPosition& where, double decimal_year) const;
  // The field of Gauss coefficients g + dt_years * g_dot, h + dt_years * h_dot (field_scale = 1) or
  // of the rates alone (field_scale = 0, dt_years = 1).
  Vec3 Synthesize(const GeodeticPosition& where, double field_scale, double dt_years) const;

  std::string model_name_;
  double epoch_ = 0.0;
  int degree_ = 0;
  // Schmidt semi-normalised Gauss coefficients g, h (nT) and their rates (nT/yr), indexed n*(n+1)/2
  // + m.
  std::vector<double> g_, h_, g_dot_, h_dot_;
  // Recursion constants of the Legendre functions, same index: P_n^m = a P_{n-1}^m x - b P_{n-2}^m
  // for m < n, and c_n = sqrt((2n - 1) / 2n) for the diagonal P_n^n = c_n s P_{n-1}^{n-1} (n >= 2).
  std::vector<double> recur_a_, recur_b_;
  std::vector<double> diag_c_;
};

}  // namespace airis::engine
