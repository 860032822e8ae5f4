#include "hotlap/fe/rebar.h"

namespace hotlap::fe {

double AddFibreStress(const RebarMaterial& rebar, const FibreLayer& layer, const Eigen::Matrix3d& F,
                      Eigen::Matrix3d& P) {
  const Eigen::Vector3d fa = F * layer.direction;
  const double strain = 0.5 * (fa.squaredNorm() - 1.0);  // Green-Lagrange along the cord
  if (strain < 0.0 && rebar.response == FibreResponse::kTensionOnly) return 0.0;
  const double s = layer.volume_fraction * rebar.youngs_modulus_Pa * strain;
  P.noalias() += s * fa * layer.direction.transpose();  // P = F S, S = s a0 a0^T
  return 0.5 * s * strain;
}

}  // namespace hotlap::fe
