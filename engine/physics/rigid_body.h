#pragma once

#include <vector>

#include "engine/core/config.h"
#include "engine/core/frames.h"

namespace airis::engine {

/// Mass, inertia and the body box of a rigid vehicle (paper 3.1: mass m, 3x3 inertia I,
/// cross-section areas A = [Ax, Ay, Az] of the box), plus its drag coefficients and contact
/// material. The box is centred on the centre of mass and aligned with the body axes (FRD).
struct RigidBodyConfig {
  double mass_kg = 1.0;
  /// Inertia tensor about the centre of mass, body axes (kg m^2); symmetric positive definite.
  Mat3 inertia_B_kg_m2 = Vec3(0.0067212, 0.0080407, 0.0142789).asDiagonal();
  Vec3 box_size_m = Vec3(0.180, 0.110, 0.040);  ///< body box edge lengths along body x, y, z (m)
  double linear_drag_coefficient = 0.325;       ///< C_lin of paper 3.3.1, per face of the box
  double angular_drag_coefficient = 0.325;  ///< drag coefficient of the faces of the spinning box
  double restitution = 0.55;                ///< contact restitution of the body, [0, 1]
  double friction = 0.5;                    ///< Coulomb friction coefficient of the body, >= 0

  /// Throws InvalidField on a non-positive mass or box edge, a non-symmetric or
  /// non-positive-definite inertia, negative drag coefficients, or a material outside its range.
  void Validate() const;
};

/// A validated RigidBodyConfig with the constants the integrator needs precomputed.
class RigidBodyModel {
 public:
  /// Validates `config` (throws InvalidField).
  explicit RigidBodyModel(const RigidBodyConfig& config);

  const RigidBodyConfig& config() const { return config_; }
  double mass_kg() const { return config_.mass_kg; }
  double inverse_mass_1_kg() const { return inverse_mass_1_kg_; }
  const Mat3& inertia_B() const { return config_.inertia_B_kg_m2; }
  const Mat3& inverse_inertia_B() const { return inverse_inertia_B_; }
  /// True when the body axes are principal axes (no products of inertia): the integrator then uses
  /// the diagonal form of Euler's equation.
  bool principal_axes() const { return principal_axes_; }
  /// Cross-section areas of the box seen along body x, y, z: [sy*sz, sx*sz, sx*sy] (m^2).
  const Vec3& cross_section_m2() const { return cross_section_m2_; }
  /// 1/2 C_lin A per axis (m^2): linear drag force is -rho * this * v|v| per body axis.
  const Vec3& linear_drag_factor_m2() const { return linear_drag_factor_m2_; }
  /// Angular drag factor per axis (m^5): drag torque is -rho * this * w|w| per body axis (see
  /// drag.h).
  const Vec3& angular_drag_factor_m5() const { return angular_drag_factor_m5_; }
  /// Radius of the sphere around the box (m), for motion bounds.
  double bounding_radius_m() const { return bounding_radius_m_; }
  /// Half of the shortest box edge (m).
  double min_half_extent_m() const { return min_half_extent_m_; }

 private:
  RigidBodyConfig config_;
  double inverse_mass_1_kg_;
  Mat3 inverse_inertia_B_;
  bool principal_axes_;
  Vec3 cross_section_m2_;
  Vec3 linear_drag_factor_m2_;
  Vec3 angular_drag_factor_m5_;
  double bounding_radius_m_;
  double min_half_extent_m_;
};

/// Inertia about the centre of mass (body axes, kg m^2) of a solid box of `box_mass_kg` and edges
/// `box_size_m`, centred on the body origin, plus point masses `point_mass_kg` at each of
/// `points_B`: I = m_box/12 diag(sy^2+sz^2, sx^2+sz^2, sx^2+sy^2) + sum m_p ([p]^T [p])
/// (parallel-axis theorem). This is how the reference implementation computes a multirotor's
/// inertia (box body plus motors).
Mat3 CalcBoxAndPointMassInertia(double box_mass_kg, const Vec3& box_size_m, double point_mass_kg,
                                const std::vector<Vec3>& points_B);

}  // namespace airis::engine
