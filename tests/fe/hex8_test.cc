// The one-point hexahedron: its reference volume and mean gradients on a distorted element, that
// rigid motion makes no force, and the patch test on a distorted 3x3x3 patch.

#include "hotlap/fe/hex8.h"

#include <algorithm>
#include <random>

#include <gtest/gtest.h>

#include "fe/fe_test_util.h"
#include "hotlap/fe/explicit_solver.h"
#include "hotlap/fe/mesh.h"

namespace hotlap::fe {
namespace {

using Mat83 = Eigen::Matrix<double, 8, 3>;

// A hexahedron whose top face is sheared and tapered: a prism of known volume.
TEST(FeHex8, VolumeAndMeanGradientOfADistortedElement) {
  Mat83 x;
  // Bottom: unit square. Top: the same square shifted by (0.3, 0.2) at height 2.
  x << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.3, 0.2, 2, 1.3, 0.2, 2, 1.3, 1.2, 2, 0.3, 1.2, 2;
  const Hex8Reference ref = CalcHex8Reference(x);
  EXPECT_NEAR(ref.volume_m3, 2.0, 1e-12);  // a parallelepiped: base 1, height 2
  // sum_a x_a B0_a^T = I for any hexahedron (linear completeness), sum_a B0_a = 0.
  EXPECT_TRUE((x.transpose() * ref.grad).isApprox(Eigen::Matrix3d::Identity(), 1e-12));
  EXPECT_LT(ref.grad.colwise().sum().norm(), 1e-12);
  // Hourglass vectors are orthogonal to constants and to the coordinates.
  EXPECT_LT((ref.hourglass * Eigen::Matrix<double, 8, 1>::Ones()).norm(), 1e-12);
  EXPECT_LT((ref.hourglass * x).norm(), 1e-12);
}

TEST(FeHex8, InvertedElementIsRejected) {
  Mat83 x;
  x << 0, 0, 0, 0, 1, 0, 1, 1, 0, 1, 0, 0, 0, 0, 1, 0, 1, 1, 1, 1, 1, 1, 0, 1;  // mirrored order
  EXPECT_THROW(CalcHex8Reference(x), std::exception);
}

Mesh DistortedPatch(double h, std::vector<int>* interior) {
  Mesh mesh = MakeBlockMesh(3 * h, 3 * h, 3 * h, 3, 3, 3);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.2 * h, 0.2 * h);
  for (int k = 0; k <= 3; ++k) {
    for (int j = 0; j <= 3; ++j) {
      for (int i = 0; i <= 3; ++i) {
        const int a = i + 4 * (j + 4 * k);
        const bool corner = (i % 3 == 0) && (j % 3 == 0) && (k % 3 == 0);
        if (!corner) mesh.nodes[a] += Eigen::Vector3d(u(rng), u(rng), u(rng));
        if (i > 0 && i < 3 && j > 0 && j < 3 && k > 0 && k < 3) interior->push_back(a);
      }
    }
  }
  return mesh;
}

Eigen::Matrix3d PatchF() {
  Eigen::Matrix3d f;
  f << 1.15, 0.08, -0.03, 0.02, 0.93, 0.05, -0.04, 0.06, 1.04;
  return f;
}

// Under a linear displacement field every element has the same stress and the interior nodes are
// in equilibrium: the residual force on them vanishes.
TEST(FePatch, DistortedPatchUnderLinearFieldHasUniformStressAndNoResidual) {
  const double h = 0.01;
  std::vector<int> interior;
  const Mesh mesh = DistortedPatch(h, &interior);
  ExplicitSolver s(mesh, {testing::Tread()}, {}, SolverOptions{});
  const Eigen::Matrix3d f = PatchF();
  std::vector<Eigen::Vector3d> x(mesh.nodes.size());
  for (size_t a = 0; a < x.size(); ++a) x[a] = f * mesh.nodes[a];
  s.SetPositions(x);
  const std::vector<Eigen::Vector3d> force = s.CalcElementForces();
  const Eigen::Matrix3d expected = CalcYeohCauchyStress(testing::Tread(), f);
  for (size_t e = 0; e < mesh.elements.size(); ++e) {
    EXPECT_TRUE(s.ElementStress(e).isApprox(expected, 1e-10)) << e;
  }
  // Force scale: stress times a face area.
  const double scale = expected.norm() * h * h;
  for (int a : interior) EXPECT_LT(force[a].norm(), 1e-9 * scale) << a;
}

// The same patch with its interior nodes displaced: driven only by the prescribed boundary and
// damped, they return to the linear field and the stress becomes uniform.
TEST(FePatch, DistortedPatchRelaxesToTheLinearField) {
  const double h = 0.01;
  std::vector<int> interior;
  const Mesh mesh = DistortedPatch(h, &interior);
  SolverOptions opt;
  opt.mass_damping_per_s = 4000.0;
  ExplicitSolver s(mesh, {testing::Tread()}, {}, opt);
  const Eigen::Matrix3d f = PatchF();
  std::vector<Eigen::Vector3d> x(mesh.nodes.size());
  for (size_t a = 0; a < x.size(); ++a) x[a] = f * mesh.nodes[a];
  for (int a : interior) x[a] += Eigen::Vector3d(0.1 * h, -0.08 * h, 0.05 * h);
  s.SetPositions(x);
  for (size_t a = 0; a < x.size(); ++a) {
    if (std::find(interior.begin(), interior.end(), int(a)) == interior.end()) {
      for (int d = 0; d < 3; ++d) s.Prescribe(a, d, 0.0);
    }
  }
  while (s.time() < 0.03) s.Step();
  for (int a : interior) {
    EXPECT_LT((s.positions()[a] - f * mesh.nodes[a]).norm(), 1e-6 * h) << a;
  }
  const Eigen::Matrix3d expected = CalcYeohCauchyStress(testing::Tread(), f);
  for (size_t e = 0; e < mesh.elements.size(); ++e) {
    EXPECT_TRUE(s.ElementStress(e).isApprox(expected, 1e-4)) << e;
  }
}

}  // namespace
}  // namespace hotlap::fe
