#pragma once
// Shared helpers of the finite-element tests: the paper's tread rubber and hand-written Yeoh
// formulas that do not call the code under test.

#include <cmath>
#include <random>
#include <vector>

#include <Eigen/Geometry>

#include "hotlap/fe/mesh.h"
#include "hotlap/fe/yeoh.h"

namespace hotlap::fe::testing {

// 002 Table 1, tread: C1, C2, C3 (N/m^2) and density (kg/m^3).
inline constexpr double kC10 = 7.77561e5, kC20 = -2.76138e5, kC30 = 9.5427e4, kRho = 1178.0;

/// Adds the pressure faces of a MakeBlockMesh(.., nx, ny, nz) block: per cell of the bottom
/// (normal -z) and, with `top`, of the top (normal +z), right-hand normals out of the block.
inline void AddBlockPressureFaces(Mesh& mesh, int nx, int ny, int nz, bool top) {
  const auto id = [&](int i, int j, int k) { return i + (nx + 1) * (j + (ny + 1) * k); };
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      mesh.pressure_faces.push_back(
          {id(i, j, 0), id(i, j + 1, 0), id(i + 1, j + 1, 0), id(i + 1, j, 0)});
      if (top) {
        mesh.pressure_faces.push_back(
            {id(i, j, nz), id(i + 1, j, nz), id(i + 1, j + 1, nz), id(i, j + 1, nz)});
      }
    }
  }
}

inline YeohMaterial Tread() { return MakeYeohMaterial(kC10, kC20, kC30, kRho, 20.0); }

// dW/dI1b of the Yeoh energy W = C10 d + C20 d^2 + C30 d^3, d = I1b - 3, by hand.
inline double HandW1(double i1b) {
  const double d = i1b - 3.0;
  return kC10 + 2.0 * kC20 * d + 3.0 * kC30 * d * d;
}

// Cauchy stress of F = diag(l1, l2, l2), component 11 (axial) or 22 (lateral), with K = 40 C10:
// sigma_ii = (2/J) W1 (Bb_ii - I1b/3) + K (J - 1), Bb = J^(-2/3) B.
inline double HandUniaxialStress(double l1, double l2, bool axial) {
  const double k = 40.0 * kC10;
  const double j = l1 * l2 * l2;
  const double s = std::pow(j, -2.0 / 3.0);
  const double b11 = s * l1 * l1, b22 = s * l2 * l2;
  const double i1b = b11 + 2.0 * b22;
  const double bii = axial ? b11 : b22;
  return 2.0 / j * HandW1(i1b) * (bii - i1b / 3.0) + k * (j - 1.0);
}

// The lateral stretch that makes the lateral stress vanish (bisection).
inline double HandUniaxialLateralStretch(double l1) {
  double lo = 0.5, hi = 1.2;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (HandUniaxialStress(l1, mid, false) > 0.0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

// Nodal velocities of a block spinning at 40 rad/s about z through `centre`, stretching at 30 /s
// along x, plus N(0, 0.02 m/s) noise from `seed`: every mode, rigid and deforming, excited.
inline std::vector<Eigen::Vector3d> SpinStretchNoiseVelocities(
    const std::vector<Eigen::Vector3d>& nodes, const Eigen::Vector3d& centre, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> n(0.0, 0.02);
  std::vector<Eigen::Vector3d> v(nodes.size());
  for (size_t a = 0; a < v.size(); ++a) {
    const Eigen::Vector3d r = nodes[a] - centre;
    v[a] = Eigen::Vector3d(0, 0, 40.0).cross(r) + Eigen::Vector3d(30.0 * r.x(), 0, 0) +
           Eigen::Vector3d(n(rng), n(rng), n(rng));
  }
  return v;
}

}  // namespace hotlap::fe::testing
