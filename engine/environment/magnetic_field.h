#pragma once

#include <span>
#include <string>

#include "engine/core/config.h"
#include "engine/core/geodetic.h"

namespace airis::engine {

/// Earth's magnetic field at a point, in the local NED frame, nanotesla, with the derived angles.
struct MagneticFieldSample {
  Vec3 field_ned_nt = Vec3::Zero();  ///< north (X), east (Y), down (Z) components
  double declination_rad = 0.0;      ///< D = atan2(Y, X), east of true north positive
  double inclination_rad = 0.0;      ///< I = atan2(Z, H), downward positive
  double horizontal_nt = 0.0;        ///< H = sqrt(X^2 + Y^2)
  double total_intensity_nt = 0.0;   ///< F = |B|
};

/// The derived angles and intensities of a NED field vector (any unit; nT by convention).
MagneticFieldSample DescribeField(const Vec3& field_ned_nt);

/// A model of the geomagnetic field. Implementations are immutable and cheap to call at sensor
/// rates.
class MagneticFieldModel {
 public:
  virtual ~MagneticFieldModel() = default;
  /// Field at geodetic position `where` (WGS84) on `decimal_year` (e.g. 2026.5). Throws
  /// std::out_of_range for a date or altitude outside the model's validity.
  virtual Vec3 CalcField_nT(const GeodeticPosition& where, double decimal_year) const = 0;
  /// Short name for logs and manifests ("dipole", "WMM-2025").
  virtual std::string name() const = 0;
};

/// Which magnetic model a scene uses.
enum class MagneticModelKind {
  kDipole,  ///< the paper's tilted dipole (TiltedDipoleField)
  kWmm,     ///< World Magnetic Model 2025 (WorldMagneticModel::Wmm2025)
};
/// Spellings of MagneticModelKind in files: dipole, wmm.
std::span<const EnumName<MagneticModelKind>> EnumNames(MagneticModelKind);

}  // namespace airis::engine
