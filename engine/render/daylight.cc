#include "engine/render/daylight.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace airis::engine {
namespace daylight {
namespace {

constexpr double kPi = std::numbers::pi;
// The views of a clear sky stop this far short of the horizon: F's 1 / cos(theta) term diverges
// there (Preetham's fits are for the sky above it).
constexpr double kMaxViewZenith_rad = 0.5 * kPi - 0.01;
// Wavelengths (um) that stand for the R, G and B channels.
constexpr double kWavelength_um[3] = {0.65, 0.55, 0.45};

}  // namespace

double CalcRelativeAirMass(double zenith_rad) {
  const double z_rad = std::clamp(zenith_rad, 0.0, 0.5 * kPi);
  const double z_deg = z_rad * 180.0 / kPi;
  return 1.0 / (std::cos(z_rad) + 0.50572 * std::pow(96.07995 - z_deg, -1.6364));
}

double CalcRayleighOpticalDepth(double wavelength_um) {
  const double l2 = wavelength_um * wavelength_um;
  const double l4 = l2 * l2;
  return 0.008569 / l4 * (1.0 + 0.0113 / l2 + 0.00013 / l4);
}

Eigen::Vector3d CalcSunTransmittance(double elevation_rad, double turbidity) {
  if (elevation_rad <= 0.0) return Eigen::Vector3d::Zero();
  const double m = CalcRelativeAirMass(0.5 * kPi - elevation_rad);
  const double beta = std::max(0.0, 0.04608 * turbidity - 0.04586);
  Eigen::Vector3d t;
  for (int c = 0; c < 3; ++c) {
    const double lambda = kWavelength_um[c];
    const double tau = CalcRayleighOpticalDepth(lambda) + beta * std::pow(lambda, -1.3);
    t[c] = std::exp(-m * tau);
  }
  return t;
}

Eigen::Vector3d XyYToLinearSrgb(double x, double y, double Y) {
  if (!(y > 0.0)) return Eigen::Vector3d::Zero();
  const double X = x / y * Y;
  const double Z = (1.0 - x - y) / y * Y;
  // IEC 61966-2-1 (sRGB): XYZ -> linear RGB, D65.
  return Eigen::Vector3d(3.2406 * X - 1.5372 * Y - 0.4986 * Z,
                         -0.9689 * X + 1.8758 * Y + 0.0415 * Z,
                         0.0557 * X - 0.2040 * Y + 1.0570 * Z);
}

ClearSky::ClearSky(double turbidity, double sun_zenith_rad)
    : sun_zenith_rad_(std::clamp(sun_zenith_rad, 0.0, 0.5 * kPi)) {
  const double T = turbidity;
  // Preetham et al. 1999, appendix: the Perez coefficients of Y, x and y.
  perez_[0] = {0.1787 * T - 1.4630, -0.0193 * T - 0.2592, -0.0167 * T - 0.2608};
  perez_[1] = {-0.3554 * T + 0.4275, -0.0665 * T + 0.0008, -0.0950 * T + 0.0092};
  perez_[2] = {-0.0227 * T + 5.3251, -0.0004 * T + 0.2125, -0.0079 * T + 0.2102};
  perez_[3] = {0.1206 * T - 2.5771, -0.0641 * T - 0.8989, -0.0441 * T - 1.6537};
  perez_[4] = {-0.0670 * T + 0.3703, -0.0033 * T + 0.0452, -0.0109 * T + 0.0529};
  // Zenith luminance (kcd/m^2 in the paper) and chromaticity.
  const double s = sun_zenith_rad_;
  const double chi = (4.0 / 9.0 - T / 120.0) * (kPi - 2.0 * s);
  const double Yz_kcd = (4.0453 * T - 4.9710) * std::tan(chi) - 0.2155 * T + 2.4192;
  const Eigen::Vector4d th(s * s * s, s * s, s, 1.0);
  const Eigen::Vector3d tt(T * T, T, 1.0);
  const Eigen::Vector3d xz(Eigen::Vector4d(0.00166, -0.00375, 0.00209, 0.0).dot(th),
                           Eigen::Vector4d(-0.02903, 0.06377, -0.03202, 0.00394).dot(th),
                           Eigen::Vector4d(0.11693, -0.21196, 0.06052, 0.25886).dot(th));
  const Eigen::Vector3d yz(Eigen::Vector4d(0.00275, -0.00610, 0.00317, 0.0).dot(th),
                           Eigen::Vector4d(-0.04214, 0.08970, -0.04153, 0.00516).dot(th),
                           Eigen::Vector4d(0.15346, -0.26756, 0.06670, 0.26688).dot(th));
  zenith_Yxy_ = Eigen::Vector3d(std::max(0.0, 1000.0 * Yz_kcd), tt.dot(xz), tt.dot(yz));
  zenith_perez_ = CalcPerez(0.0, s);
}

Eigen::Vector3d ClearSky::CalcPerez(double theta_rad, double gamma_rad) const {
  const double cos_theta = std::cos(std::min(theta_rad, kMaxViewZenith_rad));
  const double cos_gamma = std::cos(gamma_rad);
  Eigen::Vector3d f;
  for (int c = 0; c < 3; ++c) {
    f[c] = (1.0 + perez_[0][c] * std::exp(perez_[1][c] / cos_theta)) *
           (1.0 + perez_[2][c] * std::exp(perez_[3][c] * gamma_rad) +
            perez_[4][c] * cos_gamma * cos_gamma);
  }
  return f;
}

Eigen::Vector3d ClearSky::CalcYxy(double theta_rad, double gamma_rad) const {
  return zenith_Yxy_.cwiseProduct(CalcPerez(theta_rad, gamma_rad)).cwiseQuotient(zenith_perez_);
}

Eigen::Vector3d ClearSky::CalcDisplayRgb(double theta_rad, double gamma_rad) const {
  const Eigen::Vector3d Yxy = CalcYxy(theta_rad, gamma_rad);
  return XyYToLinearSrgb(Yxy[1], Yxy[2], Yxy[0]) / kSkyLuminanceScale_cd_m2;
}

double CalcOvercastZenithLuminance(double elevation_rad) {
  const double illuminance_lux = 300.0 + 21000.0 * std::max(0.0, std::sin(elevation_rad));
  return 9.0 * illuminance_lux / (7.0 * kPi);
}

}  // namespace daylight

namespace {

// Neutral overcast grey, slightly blue (an overcast sky's colour temperature is about 6,500-7,000
// K: D65's white, a little bluer), as linear sRGB of luminance 1.
const Eigen::Vector3d kOvercastTint(0.96, 1.0, 1.07);

}  // namespace

SkyShading CalcSkyShading(const SceneLighting& lighting) {
  SkyShading out;
  out.model = lighting.sky;
  const Eigen::Vector3d to_sun_W = -lighting.sun_direction_W.normalized();
  const double elevation_rad = std::asin(std::clamp(-to_sun_W.z(), -1.0, 1.0));
  switch (lighting.sky) {
    case SkyModel::kGradient:
      out.sun_rgb = lighting.sun_color_rgb;
      out.zenith_rgb = lighting.sky_zenith_rgb;
      out.horizon_rgb = lighting.sky_horizon_rgb;
      out.ambient = lighting.ambient;
      return out;
    case SkyModel::kClear: {
      const double turbidity = lighting.turbidity;
      const daylight::ClearSky sky(turbidity, 0.5 * std::numbers::pi - elevation_rad);
      // The sun relative to one overhead: the configured colour is the noon sun's.
      const Eigen::Vector3d relative =
          daylight::CalcSunTransmittance(elevation_rad, turbidity)
              .cwiseQuotient(daylight::CalcSunTransmittance(0.5 * std::numbers::pi, turbidity));
      out.sun_rgb = lighting.sun_color_rgb.cwiseProduct(relative.cast<float>());
      const double sun_zenith = 0.5 * std::numbers::pi - std::max(0.0, elevation_rad);
      out.zenith_rgb = sky.CalcDisplayRgb(0.0, sun_zenith).cwiseMax(0.0).cast<float>();
      // The horizon 2 degrees up, averaged over 36 azimuths.
      const double theta = 0.5 * std::numbers::pi - 2.0 * std::numbers::pi / 180.0;
      Eigen::Vector3d horizon = Eigen::Vector3d::Zero();
      const double horizontal_sun = std::cos(std::max(0.0, elevation_rad));
      for (int k = 0; k < 36; ++k) {
        const double azimuth = 2.0 * std::numbers::pi * k / 36.0;
        const Eigen::Vector3d view(std::sin(theta) * std::cos(azimuth),
                                   std::sin(theta) * std::sin(azimuth), std::cos(theta));
        const Eigen::Vector3d sun(horizontal_sun, 0.0, std::sin(std::max(0.0, elevation_rad)));
        const double gamma = std::acos(std::clamp(view.dot(sun), -1.0, 1.0));
        horizon += sky.CalcDisplayRgb(theta, gamma).cwiseMax(0.0);
      }
      out.horizon_rgb = (horizon / 36.0).cast<float>();
      out.ambient = lighting.ambient;
      const double scale = 1.0 / daylight::kSkyLuminanceScale_cd_m2;
      for (int k = 0; k < 5; ++k) out.perez[k] = sky.perez(k).cast<float>();
      Eigen::Vector3d zenith = sky.zenith_Yxy().cwiseQuotient(sky.zenith_perez());
      zenith[0] *= scale;
      out.zenith_over_perez = zenith.cast<float>();
      return out;
    }
    case SkyModel::kOvercast: {
      const double zenith =
          daylight::CalcOvercastZenithLuminance(elevation_rad) / daylight::kSkyLuminanceScale_cd_m2;
      out.zenith_rgb = (zenith * kOvercastTint).cast<float>();
      out.horizon_rgb = (zenith / 3.0 * kOvercastTint).cast<float>();
      out.sun_rgb = Eigen::Vector3f::Zero();  // no direct sun through the cloud deck
      out.ambient = 1.0f;
      return out;
    }
  }
  return out;
}

}  // namespace airis::engine
