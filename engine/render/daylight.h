#pragma once

#include <Eigen/Core>

#include "engine/scene/static_scene.h"

namespace airis::engine {

/// Daylight for the renderer: the sky's radiance by direction, the sun's colour after the
/// atmosphere, and the colours the scene's sky light and fog take from them. Pure CPU code (no GL):
/// the renderer passes its results to the shaders (shaders/sky.frag evaluates the same
/// distributions per pixel), the tests check it against the published formulas.
///
/// Display units: the renderer's linear RGB is relative, 1.0 the brightest white a surface lit by
/// the default sun reflects. Sky luminances in cd/m^2 are divided by kSkyLuminanceScale_cd_m2 to
/// get there (a clear noon zenith of about 8,000 cd/m^2 becomes 0.4, as the gradient sky's default
/// zenith colour is).
namespace daylight {

/// cd/m^2 that display as 1.0.
constexpr double kSkyLuminanceScale_cd_m2 = 20000.0;

/// Relative optical air mass at zenith angle `zenith_rad` (0 overhead, pi/2 at the horizon):
/// Kasten and Young, "Revised optical air mass tables and approximation formula", Applied Optics
/// 28(22), 1989: m = 1 / (cos z + 0.50572 (96.07995 - z_deg)^-1.6364); 1 overhead, 37.92 at the
/// horizon. Clamped to the horizon below it.
double CalcRelativeAirMass(double zenith_rad);

/// Rayleigh optical depth of the whole atmosphere at `wavelength_um` (micrometres), sea level:
/// tau_R = 0.008569 lambda^-4 (1 + 0.0113 lambda^-2 + 0.00013 lambda^-4) (Hansen and Travis,
/// "Light scattering in planetary atmospheres", Space Sci. Rev. 16, 1974, eq. 2.29); 0.0973 at
/// 550 nm.
double CalcRayleighOpticalDepth(double wavelength_um);

/// The sun's direct-beam transmittance in linear R, G, B (at 650, 550, 450 nm) at `elevation_rad`
/// above the horizon through an atmosphere of Linke-style `turbidity` T: exp(-m (tau_R + tau_A)),
/// the aerosol's tau_A = beta lambda^-1.3 with Angstrom's beta = 0.04608 T - 0.04586 (Preetham et
/// al. 1999, appendix). Zero below the horizon.
Eigen::Vector3d CalcSunTransmittance(double elevation_rad, double turbidity);

/// The CIE 1931 chromaticity x, y and luminance Y (cd/m^2) -> linear sRGB (Rec. 709 primaries, D65
/// white), in cd/m^2.
Eigen::Vector3d XyYToLinearSrgb(double x, double y, double Y);

/// The clear sky of Preetham, Shirley and Smits, "A Practical Analytic Model for Daylight",
/// SIGGRAPH 1999: each of Y, x, y is its zenith value times F(theta, gamma) / F(0, theta_s), with
/// Perez et al.'s F(theta, gamma) = (1 + A e^(B / cos theta)) (1 + C e^(D gamma) + E cos^2 gamma),
/// theta the view's zenith angle, gamma its angle from the sun, theta_s the sun's zenith angle, and
/// A..E linear in the turbidity (the paper's appendix). Valid for turbidity 2 to 10 and the sun
/// above the horizon (the paper's fits); theta is clamped just short of the horizon.
class ClearSky {
 public:
  /// @param sun_zenith_rad 0 to pi/2 (the renderer clamps a sun below the horizon to it).
  ClearSky(double turbidity, double sun_zenith_rad);

  /// Y (cd/m^2), x, y of the sky at view zenith angle `theta_rad`, `gamma_rad` from the sun.
  Eigen::Vector3d CalcYxy(double theta_rad, double gamma_rad) const;
  /// The same as linear sRGB in display units.
  Eigen::Vector3d CalcDisplayRgb(double theta_rad, double gamma_rad) const;

  /// Perez coefficient k (0..4: A..E) for Y, x and y.
  const Eigen::Vector3d& perez(int k) const { return perez_[k]; }
  /// Zenith Y (cd/m^2), x, y: Preetham's fits.
  const Eigen::Vector3d& zenith_Yxy() const { return zenith_Yxy_; }
  /// F(0, theta_s) for Y, x, y: what the zenith values are divided by.
  const Eigen::Vector3d& zenith_perez() const { return zenith_perez_; }

 private:
  Eigen::Vector3d CalcPerez(double theta_rad, double gamma_rad) const;

  double sun_zenith_rad_;
  Eigen::Vector3d perez_[5];
  Eigen::Vector3d zenith_Yxy_;
  Eigen::Vector3d zenith_perez_;
};

/// Zenith luminance (cd/m^2) of the CIE standard overcast sky (Moon and Spencer 1942, CIE S 011)
/// with the sun `elevation_rad` above the horizon: L_z = 9 E_h / (7 pi) for the diffuse horizontal
/// illuminance E_h = 300 + 21,000 sin h lux (Krochmann and Seidl 1974); the sky's luminance at
/// zenith angle theta is L_z (1 + 2 cos theta) / 3, a third of the zenith's at the horizon.
double CalcOvercastZenithLuminance(double elevation_rad);

}  // namespace daylight

/// What the shaders need of the sky for one frame (CalcSkyShading).
struct SkyShading {
  SkyModel model = SkyModel::kGradient;
  Eigen::Vector3f sun_rgb = Eigen::Vector3f::Zero();     ///< direct sunlight (after the atmosphere)
  Eigen::Vector3f zenith_rgb = Eigen::Vector3f::Zero();  ///< sky overhead, display units
  Eigen::Vector3f horizon_rgb = Eigen::Vector3f::Zero();  ///< sky at the horizon, and the fog
  float ambient = 0.0f;  ///< fraction of the light from the sky (1 under an overcast sky)
  /// Clear sky only: Perez A..E for (Y, x, y), the zenith Yxy over F(0, theta_s) (Y in display
  /// units), for shaders/sky.frag.
  Eigen::Vector3f perez[5];
  Eigen::Vector3f zenith_over_perez = Eigen::Vector3f::Zero();
};

/// The sky of `lighting` for its sun: the gradient sky's colours as configured; a clear sky's
/// colours from ClearSky at the scene's turbidity (zenith, and the horizon averaged over azimuth
/// 2 degrees up), its sun the configured colour times CalcSunTransmittance relative to a sun
/// overhead; an overcast sky grey by CalcOvercastZenithLuminance, with no direct sun.
SkyShading CalcSkyShading(const SceneLighting& lighting);

}  // namespace airis::engine
