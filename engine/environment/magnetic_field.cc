#include "engine/environment/magnetic_field.h"

#include <array>
#include <cmath>

namespace airis::engine {

MagneticFieldSample DescribeField(const Vec3& field_ned_nt) {
  MagneticFieldSample s;
  s.field_ned_nt = field_ned_nt;
  s.horizontal_nt = std::hypot(field_ned_nt.x(), field_ned_nt.y());
  s.total_intensity_nt = field_ned_nt.norm();
  s.declination_rad = std::atan2(field_ned_nt.y(), field_ned_nt.x());
  s.inclination_rad = std::atan2(field_ned_nt.z(), s.horizontal_nt);
  return s;
}

std::span<const EnumName<MagneticModelKind>> EnumNames(MagneticModelKind) {
  static constexpr std::array<EnumName<MagneticModelKind>, 2> kNames{{
      {MagneticModelKind::kDipole, "dipole"},
      {MagneticModelKind::kWmm, "wmm"},
  }};
  return kNames;
}

}  // namespace airis::engine
