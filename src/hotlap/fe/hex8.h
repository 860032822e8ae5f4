#pragma once
/// @file
/// The 8-node hexahedron with one-point (mean-gradient) integration and Flanagan-Belytschko
/// hourglass vectors (Flanagan & Belytschko 1981, Int. J. Numer. Meth. Eng. 17).
///
/// Node order: the bottom face (zeta = -1) counter-clockwise seen from +zeta, then the top face
/// in the same order, as in VTK_HEXAHEDRON and Abaqus C3D8R.
///
/// The element is total-Lagrangian: its mean gradient operator B0 (dN_a/dX averaged over the
/// reference volume, computed exactly by 2x2x2 Gauss quadrature) gives the volume-averaged
/// deformation gradient F = sum_a x_a B0_a^T, and the nodal forces f_a = -V0 P(F) B0_a are the
/// exact derivatives of the element energy V0 W(F). The hourglass shape vectors gamma_alpha
/// (alpha = 1..4) are orthogonal to every linear field, so rigid motion and uniform strain make
/// no hourglass force (they pass the patch test).

#include <array>

#include <Eigen/Core>

namespace hotlap::fe {

/// Reference geometry of one hexahedron, computed once.
struct Hex8Reference {
  double volume_m3 = 0.0;  ///< V0, m^3
  /// B0: row a is mean dN_a/dX, 1/m (row-major: the solver reads it a row at a time).
  Eigen::Matrix<double, 8, 3, Eigen::RowMajor> grad;
  Eigen::Matrix<double, 4, 8> hourglass;  ///< gamma: row alpha is the FB shape vector, 1
  double length_m = 0.0;                  ///< L_e = sqrt(1.5 / sum_a |B0_a|^2), m (cube: edge)
};

/// The node sign table (xi_a, eta_a, zeta_a) of the reference element.
const std::array<Eigen::Vector3d, 8>& Hex8NodeSigns();

/// B0, V0, gamma and L_e of a hexahedron with reference node positions `x` (row a = node a).
/// Throws NumericalError if the Jacobian is not positive at a Gauss point (inverted element).
Hex8Reference CalcHex8Reference(const Eigen::Matrix<double, 8, 3>& x);

/// Mean deformation gradient F = sum_a x_a B0_a^T from current node positions.
inline Eigen::Matrix3d CalcMeanDeformationGradient(const Eigen::Matrix<double, 8, 3>& x,
                                                   const Hex8Reference& ref) {
  return x.transpose() * ref.grad;
}

}  // namespace hotlap::fe
