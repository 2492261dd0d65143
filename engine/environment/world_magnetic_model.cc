#include "engine/environment/world_magnetic_model.h"

#include <array>
#include <charconv>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "engine/core/config.h"
#include "engine/core/error.h"
#include "engine/core/geodetic.h"

namespace airis::engine {
namespace internal {
extern const std::string_view kWmm2025CofText;  // generated from data/wmm/WMM2025.COF
}  // namespace internal

namespace {

constexpr double kReferenceRadius_m =
    6371200.0;  // a, the geomagnetic reference radius (report, Table 2)
constexpr int kMaxTerms =
    (WorldMagneticModel::kMaxDegree + 1) * (WorldMagneticModel::kMaxDegree + 2) / 2;

constexpr int Index(int n, int m) { return n * (n + 1) / 2 + m; }

// Splits `line` at blanks into at most `max_fields` fields; returns how many it found.
int SplitFields(std::string_view line, std::string_view* fields, int max_fields) {
  int count = 0;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    if (i >= line.size()) break;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    if (count == max_fields) return max_fields + 1;
    fields[count++] = line.substr(start, i - start);
  }
  return count;
}

bool ParseDouble(std::string_view text, double& out) {
  const auto result = std::from_chars(text.data(), text.data() + text.size(), out);
  return result.ec == std::errc() && result.ptr == text.data() + text.size() && std::isfinite(out);
}

bool ParseInt(std::string_view text, int& out) {
  const auto result = std::from_chars(text.data(), text.data() + text.size(), out);
  return result.ec == std::errc() && result.ptr == text.data() + text.size();
}

}  // namespace

const WorldMagneticModel& WorldMagneticModel::Wmm2025() {
  static const WorldMagneticModel model =
      FromCofText(internal::kWmm2025CofText, "WMM2025.COF (built in)");
  return model;
}

WorldMagneticModel WorldMagneticModel::FromCofText(std::string_view text,
                                                   const std::string& source_name) {
  WorldMagneticModel model;
  model.g_.assign(kMaxTerms, 0.0);
  model.h_.assign(kMaxTerms, 0.0);
  model.g_dot_.assign(kMaxTerms, 0.0);
  model.h_dot_.assign(kMaxTerms, 0.0);
  std::array<bool, kMaxTerms> seen{};
  auto fail = [&](int line, const std::string& problem) -> ConfigError {
    return ConfigError({source_name, line, 0}, "", problem);
  };

  bool have_header = false, terminated = false;
  int line_number = 0;
  std::size_t pos = 0;
  while (pos < text.size() && !terminated) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    const std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++line_number;
    std::string_view f[7];
    const int count = SplitFields(line, f, 6);
    if (count == 0) continue;
    if (!have_header) {
      // "    2025.0            WMM-2025        11/13/2024": epoch, model name, release date.
      if (count < 2 || !ParseDouble(f[0], model.epoch_)) {
        throw fail(line_number,
                   "expected the header 'EPOCH MODEL-NAME DATE' (got '" + std::string(line) + "')");
      }
      model.model_name_ = std::string(f[1]);
      have_header = true;
      continue;
    }
    if (f[0].starts_with("9999")) {
      terminated = true;
      continue;
    }
    // "  n  m  g  h  g_dot  h_dot".
    int n = 0, m = 0;
    double g, h, g_dot, h_dot;
    if (count != 6 || !ParseInt(f[0], n) || !ParseInt(f[1], m) || !ParseDouble(f[2], g) ||
        !ParseDouble(f[3], h) || !ParseDouble(f[4], g_dot) || !ParseDouble(f[5], h_dot)) {
      throw fail(line_number, "expected 'n m g h g_dot h_dot' (got '" + std::string(line) + "')");
    }
    if (n < 1 || n > kMaxDegree || m < 0 || m > n) {
      throw fail(line_number, "degree n must be 1 to " + std::to_string(kMaxDegree) +
                                  " and order m 0 to n (got n = " + std::to_string(n) +
                                  ", m = " + std::to_string(m) + ")");
    }
    const int k = Index(n, m);
    if (seen[k]) {
      throw fail(line_number,
                 "duplicate coefficient n = " + std::to_string(n) + ", m = " + std::to_string(m));
    }
    seen[k] = true;
    model.g_[k] = g;
    model.h_[k] = h;
    model.g_dot_[k] = g_dot;
    model.h_dot_[k] = h_dot;
    model.degree_ = std::max(model.degree_, n);
  }
  if (!have_header) throw fail(0, "no header line: not a WMM coefficient file");
  for (int n = 1; n <= model.degree_; ++n) {
    for (int m = 0; m <= n; ++m) {
      if (!seen[Index(n, m)]) {
        throw fail(0,
                   "missing coefficient n = " + std::to_string(n) + ", m = " + std::to_string(m));
      }
    }
  }

  // Recursion constants of the Schmidt semi-normalised functions (report, section 1.2).
  model.recur_a_.assign(kMaxTerms, 0.0);
  model.recur_b_.assign(kMaxTerms, 0.0);
  model.diag_c_.assign(kMaxDegree + 1, 0.0);
  for (int n = 2; n <= kMaxDegree; ++n) {
    model.diag_c_[n] = std::sqrt((2.0 * n - 1.0) / (2.0 * n));
  }
  for (int n = 1; n <= kMaxDegree; ++n) {
    for (int m = 0; m < n; ++m) {
      const double root = std::sqrt(static_cast<double>(n * n - m * m));
      model.recur_a_[Index(n, m)] = (2.0 * n - 1.0) / root;
      model.recur_b_[Index(n, m)] =
          std::sqrt(static_cast<double>((n - 1) * (n - 1) - m * m)) / root;
    }
  }
  return model;
}

void WorldMagneticModel::CheckValidity(const GeodeticPosition& where, double decimal_year) const {
  if (!(decimal_year >= epoch_ && decimal_year < epoch_ + kValidityYears)) {
    throw std::out_of_range(model_name_ + ": date " + FormatNumber(decimal_year) +
                            " is outside the model's validity [" + FormatNumber(epoch_) + ", " +
                            FormatNumber(epoch_ + kValidityYears) + ") (decimal year)");
  }
  if (!(where.altitude_m >= kMinAltitude_m && where.altitude_m <= kMaxAltitude_m)) {
    throw std::out_of_range(
        model_name_ + ": altitude " + FormatNumber(where.altitude_m) +
        " m is outside the model's range [-1000, 850000] m above the ellipsoid");
  }
  // The tolerance admits 90 degrees converted to radians with rounding.
  if (!(std::abs(where.latitude_rad) <= 0.5 * std::numbers::pi + 1e-12) ||
      !std::isfinite(where.longitude_rad)) {
    throw std::out_of_range(model_name_ + ": latitude " + FormatNumber(where.latitude_rad) +
                            " rad / longitude " + FormatNumber(where.longitude_rad) +
                            " rad is not a valid position");
  }
}

Vec3 WorldMagneticModel::CalcField_nT(const GeodeticPosition& where, double decimal_year) const {
  CheckValidity(where, decimal_year);
  return Synthesize(where, 1.0, decimal_year - epoch_);
}

Vec3 WorldMagneticModel::CalcSecularVariation_nT_yr(const GeodeticPosition& where,
                                                    double decimal_year) const {
  CheckValidity(where, decimal_year);
  return Synthesize(where, 0.0, 1.0);
}

Vec3 WorldMagneticModel::Synthesize(const GeodeticPosition& where, double field_scale,
                                    double dt_years) const {
  using namespace wgs84;
  // Geodetic to geocentric spherical (report, equations 7-8): p and z of the ECEF point, r and
  // phi'.
  const double sin_lat = std::sin(where.latitude_rad), cos_lat = std::cos(where.latitude_rad);
  const double rc = kSemiMajorAxis_m / std::sqrt(1.0 - kEccentricitySq * sin_lat * sin_lat);
  const double p = (rc + where.altitude_m) * cos_lat;
  const double z = (rc * (1.0 - kEccentricitySq) + where.altitude_m) * sin_lat;
  const double r = std::hypot(p, z);
  const double x = z / r;  // sin(phi') = cos(theta), theta the geocentric co-latitude
  const double s = p / r;  // cos(phi') = sin(theta); > 0 for |latitude| <= 90 deg in floating point

  // Schmidt semi-normalised P_n^m(sin phi') and their derivatives with respect to theta.
  std::array<double, kMaxTerms> pnm, dpnm;
  pnm[0] = 1.0;
  dpnm[0] = 0.0;
  for (int n = 1; n <= degree_; ++n) {
    for (int m = 0; m < n; ++m) {
      const int k = Index(n, m);
      const double p1 = pnm[Index(n - 1, m)], dp1 = dpnm[Index(n - 1, m)];
      double p2 = 0.0, dp2 = 0.0;
      if (n - 2 >= m) {
        p2 = pnm[Index(n - 2, m)];
        dp2 = dpnm[Index(n - 2, m)];
      }
      pnm[k] = recur_a_[k] * x * p1 - recur_b_[k] * p2;
      dpnm[k] = recur_a_[k] * (x * dp1 - s * p1) - recur_b_[k] * dp2;
    }
    const int k = Index(n, n);
    if (n == 1) {
      pnm[k] = s;
      dpnm[k] = x;
    } else {
      const int kd = Index(n - 1, n - 1);
      pnm[k] = diag_c_[n] * s * pnm[kd];
      dpnm[k] = diag_c_[n] * (s * dpnm[kd] + x * pnm[kd]);
    }
  }

  // cos(m lambda), sin(m lambda) by the angle-addition recurrence.
  std::array<double, kMaxDegree + 1> cos_ml, sin_ml;
  cos_ml[0] = 1.0;
  sin_ml[0] = 0.0;
  cos_ml[1] = std::cos(where.longitude_rad);
  sin_ml[1] = std::sin(where.longitude_rad);
  for (int m = 2; m <= degree_; ++m) {
    cos_ml[m] = cos_ml[m - 1] * cos_ml[1] - sin_ml[m - 1] * sin_ml[1];
    sin_ml[m] = sin_ml[m - 1] * cos_ml[1] + cos_ml[m - 1] * sin_ml[1];
  }

  // Field in geocentric spherical components (report, equations 10-12). With d/dphi' = -d/dtheta:
  //   X' =  sum (a/r)^(n+2) sum (g cos + h sin) dP/dtheta
  //   Y' =  sum (a/r)^(n+2) sum m (g sin - h cos) P / cos(phi')
  //   Z' = -sum (n+1) (a/r)^(n+2) sum (g cos + h sin) P
  const double ratio = kReferenceRadius_m / r;
  double radial_power = ratio * ratio;  // (a/r)^(n+2), advanced per degree
  double x_sph = 0.0, y_sph = 0.0, z_sph = 0.0;
  for (int n = 1; n <= degree_; ++n) {
    radial_power *= ratio;
    double sx = 0.0, sy = 0.0, sz = 0.0;
    for (int m = 0; m <= n; ++m) {
      const int k = Index(n, m);
      const double g = field_scale * g_[k] + dt_years * g_dot_[k];
      const double h = field_scale * h_[k] + dt_years * h_dot_[k];
      const double cos_term = g * cos_ml[m] + h * sin_ml[m];
      const double sin_term = g * sin_ml[m] - h * cos_ml[m];
      sx += cos_term * dpnm[k];
      sy += m * sin_term * pnm[k];
      sz += cos_term * pnm[k];
    }
    x_sph += radial_power * sx;
    y_sph += radial_power * sy;
    z_sph -= (n + 1) * radial_power * sz;
  }
  y_sph /= s;

  // Rotate from geocentric to geodetic north and down (report, equation 17).
  // cos and sin of phi' - phi from the angle-difference identities (no further trigonometric
  // calls).
  const double cd = s * cos_lat + x * sin_lat;
  const double sd = x * cos_lat - s * sin_lat;
  return Vec3(x_sph * cd - z_sph * sd, y_sph, x_sph * sd + z_sph * cd);
}

}  // namespace airis::engine
