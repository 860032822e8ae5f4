#include "hotlap/fe/road_contact.h"

#include <algorithm>
#include <cmath>

namespace hotlap::fe {

double CalcFrictionCoefficient(const FrictionLaw& law, double slip_speed_mps) {
  return law.kinetic_coefficient + (law.static_coefficient - law.kinetic_coefficient) *
                                       std::exp(-law.decay_s_per_m * slip_speed_mps);  // (002:1)
}

Eigen::Vector2d ReturnMapFriction(double stiffness_N_per_m, double limit_N,
                                  Eigen::Vector2d& extension) {
  const double trial = stiffness_N_per_m * extension.norm();
  // Slip: shrink the extension (move the anchor) until the spring carries the limit force.
  if (trial > limit_N) extension *= std::max(limit_N, 0.0) / trial;
  return -stiffness_N_per_m * extension;
}

Eigen::Vector3d CalcFrictionForce(const FrictionLaw& law, double normal_force_N,
                                  const Eigen::Vector3d& slip_velocity,
                                  double stick_coefficient_N_s_per_m) {
  const Eigen::Vector3d vt(slip_velocity.x(), slip_velocity.y(), 0.0);
  const double s = vt.norm();
  if (s == 0.0 || normal_force_N <= 0.0) return Eigen::Vector3d::Zero();
  const double mu = CalcFrictionCoefficient(law, s);
  return -std::min(mu * normal_force_N / s, stick_coefficient_N_s_per_m) * vt;
}

double MaxStablePenaltyFactor(double safety) { return 4.0 * (1.0 - safety * safety); }

}  // namespace hotlap::fe
