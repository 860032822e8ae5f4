#include "hotlap/fe/hex8.h"

#include <cmath>
#include <string>

#include <Eigen/LU>

#include "hotlap/common/error.h"

namespace hotlap::fe {

const std::array<Eigen::Vector3d, 8>& Hex8NodeSigns() {
  static const std::array<Eigen::Vector3d, 8> s = {
      Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(1, -1, -1), Eigen::Vector3d(1, 1, -1),
      Eigen::Vector3d(-1, 1, -1),  Eigen::Vector3d(-1, -1, 1), Eigen::Vector3d(1, -1, 1),
      Eigen::Vector3d(1, 1, 1),    Eigen::Vector3d(-1, 1, 1)};
  return s;
}

Hex8Reference CalcHex8Reference(const Eigen::Matrix<double, 8, 3>& x) {
  const auto& s = Hex8NodeSigns();
  Hex8Reference ref;
  ref.grad.setZero();
  const double g = 1.0 / std::sqrt(3.0);
  // 2x2x2 Gauss: exact for V0 and for the integral of dN/dX dV of a trilinear hexahedron.
  for (int gp = 0; gp < 8; ++gp) {
    const Eigen::Vector3d xi = g * s[gp];
    Eigen::Matrix<double, 8, 3> dn_dxi;
    for (int a = 0; a < 8; ++a) {
      const double n0 = 1 + s[a](0) * xi(0), n1 = 1 + s[a](1) * xi(1), n2 = 1 + s[a](2) * xi(2);
      dn_dxi(a, 0) = 0.125 * s[a](0) * n1 * n2;
      dn_dxi(a, 1) = 0.125 * s[a](1) * n0 * n2;
      dn_dxi(a, 2) = 0.125 * s[a](2) * n0 * n1;
    }
    const Eigen::Matrix3d jac = x.transpose() * dn_dxi;  // dX_i / dxi_j
    const double det = jac.determinant();
    if (!(det > 0.0)) {
      throw NumericalError("fe: hexahedron with non-positive Jacobian (" + std::to_string(det) +
                           "); check the node order or the mesh");
    }
    ref.volume_m3 += det;
    ref.grad += det * dn_dxi * jac.inverse();  // (dN/dX)^T rows = dN/dxi J^-1
  }
  ref.grad /= ref.volume_m3;
  // FB hourglass shape vectors: h = (eta zeta, xi zeta, xi eta, xi eta zeta) node signs, made
  // orthogonal to linear fields: gamma = h - B0 (X^T h).
  for (int alpha = 0; alpha < 4; ++alpha) {
    Eigen::Matrix<double, 8, 1> h;
    for (int a = 0; a < 8; ++a) {
      switch (alpha) {
        case 0:
          h(a) = s[a](1) * s[a](2);
          break;
        case 1:
          h(a) = s[a](0) * s[a](2);
          break;
        case 2:
          h(a) = s[a](0) * s[a](1);
          break;
        default:
          h(a) = s[a](0) * s[a](1) * s[a](2);
          break;
      }
    }
    const Eigen::Vector3d xh = x.transpose() * h;
    ref.hourglass.row(alpha) = (h - ref.grad * xh).transpose();
  }
  ref.length_m = std::sqrt(1.5 / ref.grad.squaredNorm());
  return ref;
}

}  // namespace hotlap::fe
