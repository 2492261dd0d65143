#include "engine/physics/rigid_body.h"

#include <Eigen/Eigenvalues>
#include <cmath>

namespace airis::engine {

void RigidBodyConfig::Validate() const {
  RequirePositive("mass_kg", mass_kg);
  for (int i = 0; i < 3; ++i) {
    RequirePositive("box_size_m[" + std::to_string(i) + "]", box_size_m[i]);
    for (int j = 0; j < 3; ++j) {
      RequireFinite("inertia_B_kg_m2", inertia_B_kg_m2(i, j));
    }
  }
  const double scale = inertia_B_kg_m2.cwiseAbs().maxCoeff();
  Require((inertia_B_kg_m2 - inertia_B_kg_m2.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * scale,
          "inertia_B_kg_m2", "must be symmetric");
  const Vec3 eig = Eigen::SelfAdjointEigenSolver<Mat3>(inertia_B_kg_m2).eigenvalues();
  Require(eig.minCoeff() > 0.0, "inertia_B_kg_m2",
          "must be positive definite (got smallest principal moment " +
              FormatNumber(eig.minCoeff()) + ")");
  // Principal moments of a real body obey the triangle inequality (I1 + I2 >= I3).
  Require(eig[0] + eig[1] >= eig[2] * (1.0 - 1e-9), "inertia_B_kg_m2",
          "principal moments violate the triangle inequality (not a physical body)");
  RequireNonNegative("linear_drag_coefficient", linear_drag_coefficient);
  RequireNonNegative("angular_drag_coefficient", angular_drag_coefficient);
  RequireInRange("restitution", restitution, 0.0, 1.0);
  RequireNonNegative("friction", friction);
}

RigidBodyModel::RigidBodyModel(const RigidBodyConfig& config) : config_(config) {
  config_.Validate();
  inverse_mass_1_kg_ = 1.0 / config_.mass_kg;
  inverse_inertia_B_ = config_.inertia_B_kg_m2.inverse();
  Mat3 off_diagonal = config_.inertia_B_kg_m2;
  off_diagonal.diagonal().setZero();
  principal_axes_ = off_diagonal.isZero(0.0);
  const Vec3& s = config_.box_size_m;
  cross_section_m2_ = Vec3(s.y() * s.z(), s.x() * s.z(), s.x() * s.y());
  linear_drag_factor_m2_ = 0.5 * config_.linear_drag_coefficient * cross_section_m2_;
  // Quadratic pressure drag on the faces of a box spinning about one axis, integrated over the
  // faces that advance into the air (see drag.h): factor_z = C * sz * (sx^4 + sy^4) / 64, and
  // cyclically.
  const Vec3 s4 = s.array().pow(4.0);
  angular_drag_factor_m5_ =
      config_.angular_drag_coefficient / 64.0 *
      Vec3(s.x() * (s4.y() + s4.z()), s.y() * (s4.x() + s4.z()), s.z() * (s4.x() + s4.y()));
  bounding_radius_m_ = 0.5 * s.norm();
  min_half_extent_m_ = 0.5 * s.minCoeff();
}

Mat3 CalcBoxAndPointMassInertia(double box_mass_kg, const Vec3& box_size_m, double point_mass_kg,
                                const std::vector<Vec3>& points_B) {
  const Vec3 s2 = box_size_m.cwiseProduct(box_size_m);
  Mat3 inertia = Mat3::Zero();
  inertia.diagonal() = box_mass_kg / 12.0 * Vec3(s2.y() + s2.z(), s2.x() + s2.z(), s2.x() + s2.y());
  for (const Vec3& p : points_B) {
    inertia += point_mass_kg * (p.squaredNorm() * Mat3::Identity() - p * p.transpose());
  }
  return inertia;
}

}  // namespace airis::engine
