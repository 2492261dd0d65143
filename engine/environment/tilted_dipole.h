#pragma once

#include "engine/environment/magnetic_field.h"

namespace airis::engine {

/// Description of the paper's tilted-dipole geomagnetic field (paper 3.2.2).
struct TiltedDipoleConfig {
  double pole_latitude_deg = 80.31;     ///< geomagnetic north pole (geographic latitude)
  double pole_longitude_deg = -72.62;   ///< geomagnetic north pole (east positive)
  double equatorial_field_t = 3.12e-5;  ///< B0: field at the magnetic equator, surface (tesla)
  double earth_radius_m = 6371000.0;    ///< Re: field falls off as (Re / (Re + h))^3

  template <class V>
  void Visit(V& v) {
    v.Field("pole_latitude_deg", pole_latitude_deg, "geomagnetic north pole latitude (deg)");
    v.Field("pole_longitude_deg", pole_longitude_deg,
            "geomagnetic north pole longitude (deg, east +)");
    v.Field("equatorial_field_t", equatorial_field_t, "B0 at the magnetic equator, surface (T)");
    v.Field("earth_radius_m", earth_radius_m, "Re (m)");
  }
  /// Throws InvalidField for a pole latitude outside [-90, 90], a longitude outside [-180, 180], or
  /// a non-positive B0 or radius.
  void Validate() const;
};

/// A centred dipole whose axis passes through the configured geomagnetic pole, derived from dipole
/// physics (docs/models.md). The Earth is the sphere of radius Re: latitude and longitude are taken
/// as spherical coordinates and the point lies at r = Re + h. With m the unit vector toward the
/// geomagnetic north pole and theta_m the magnetic co-latitude (cos theta_m = m . r_hat), the field
/// of the Earth's dipole (moment along -m) is
///   B = B0 (Re/r)^3 (m - 3 (m . r_hat) r_hat),
/// so B_radial = -2 B0 (Re/r)^3 cos(theta_m) (downward in the north), the horizontal part has
/// magnitude B0 (Re/r)^3 sin(theta_m) and points toward the geomagnetic pole, |B| = B0 (Re/r)^3
/// sqrt(1 + 3 cos^2 theta_m) and tan(I) = 2 cot(theta_m). Independent of date.
class TiltedDipoleField final : public MagneticFieldModel {
 public:
  /// Throws InvalidField when `config` fails Validate().
  explicit TiltedDipoleField(const TiltedDipoleConfig& config = {});
  /// Field (NED, nT) at `where`; `decimal_year` is ignored. Throws std::out_of_range for a
  /// non-finite position or an altitude at or below -Re.
  Vec3 CalcField_nT(const GeodeticPosition& where, double decimal_year) const override;
  std::string name() const override { return "dipole"; }
  /// The description this model was built from.
  const TiltedDipoleConfig& config() const { return config_; }

 private:
  TiltedDipoleConfig config_;
  Vec3 pole_axis_E_;  // unit vector toward the geomagnetic north pole, Earth-fixed axes
  double b0_nt_;      // B0 in nanotesla
};

}  // namespace airis::engine
