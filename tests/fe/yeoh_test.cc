// Yeoh rubber: the constants the paper implies (mu0, K, nu), P = dW/dF, and single hexahedra in
// uniaxial tension and simple shear driven through the explicit solver, their nodal forces turned
// into stresses and compared with the Yeoh stress computed by hand in fe_test_util.h.

#include "hotlap/fe/yeoh.h"

#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "fe/fe_test_util.h"
#include "hotlap/fe/explicit_solver.h"
#include "hotlap/fe/mesh.h"

namespace hotlap::fe {
namespace {

using testing::HandW1;
using testing::kC10;
using testing::Tread;

TEST(FeYeoh, CubeRootAgreesWithCbrtToRoundOff) {
  for (double x = 1e-12; x < 1e12; x *= 1.0137) {
    for (double y : {x, 1.0 + (x - 1.0) * 1e-9}) {
      EXPECT_NEAR(fe::CubeRoot(y), std::cbrt(y), 8e-16 * std::cbrt(y)) << y;
    }
  }
  EXPECT_EQ(fe::CubeRoot(8.0), 2.0);
  EXPECT_NEAR(fe::CubeRoot(1e-310), std::cbrt(1e-310), 1e-118);
}

TEST(FeYeoh, BulkToShearTwentyGivesPoissonNearPoint475) {
  const YeohMaterial m = Tread();
  EXPECT_DOUBLE_EQ(InitialShearModulus(m), 2.0 * kC10);
  EXPECT_DOUBLE_EQ(m.bulk_modulus_Pa, 40.0 * kC10);
  EXPECT_NEAR(InitialPoissonRatio(m), 58.0 / 122.0, 1e-12);  // (3*20 - 2) / (2 (3*20 + 1))
  EXPECT_NEAR(InitialPoissonRatio(m), 0.475, 1e-3);
}

TEST(FeYeoh, FirstPiolaIsTheDerivativeOfTheEnergy) {
  const YeohMaterial m = Tread();
  Eigen::Matrix3d F;
  F << 1.3, 0.2, -0.1, 0.05, 0.85, 0.15, -0.02, 0.1, 0.95;
  const Eigen::Matrix3d P = CalcYeohFirstPiola(m, F);
  const double h = 1e-7;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      Eigen::Matrix3d fp = F, fm = F;
      fp(i, j) += h;
      fm(i, j) -= h;
      const double fd = (CalcYeohEnergyDensity(m, fp) - CalcYeohEnergyDensity(m, fm)) / (2 * h);
      EXPECT_NEAR(P(i, j), fd, 1e-6 * P.norm()) << i << "," << j;
    }
  }
}

// A cube of edge 10 mm on three symmetry planes, its +x face pulled to stretch 1.5 slowly and
// held while mass damping removes the motion. The axial stress is the +x face's reaction over the
// current face area; the lateral stretch is read from the nodes.
TEST(FeYeoh, SingleElementUniaxialTensionMatchesAnalytic) {
  const double l = 0.01, stretch = 1.5;
  Mesh mesh = MakeBlockMesh(l, l, l, 1, 1, 1);
  SolverOptions opt;
  opt.mass_damping_per_s = 3000.0;
  ExplicitSolver s(mesh, {Tread()}, {}, opt);
  for (int a = 0; a < 8; ++a) {
    const Eigen::Vector3d& x = mesh.nodes[a];
    if (x.x() == 0.0) s.Prescribe(a, 0, 0.0);
    if (x.y() == 0.0) s.Prescribe(a, 1, 0.0);
    if (x.z() == 0.0) s.Prescribe(a, 2, 0.0);
  }
  const double t_pull = 0.02, t_hold = 0.02;
  const int n_pull = static_cast<int>(std::round(t_pull / s.time_step()));
  for (int a = 0; a < 8; ++a) {
    if (mesh.nodes[a].x() == l) s.Prescribe(a, 0, (stretch - 1.0) * l / (n_pull * s.time_step()));
  }
  for (int k = 0; k < n_pull; ++k) s.Step();
  for (int a = 0; a < 8; ++a) {
    if (mesh.nodes[a].x() == l) s.Prescribe(a, 0, 0.0);
  }
  while (s.time() < t_pull + t_hold) s.Step();

  const auto& x = s.positions();
  const double l1 = x[1].x() / l;  // node 1 is (l, 0, 0)
  const double l2 = x[3].y() / l;  // node 3 is (0, l, 0)
  const double l3 = x[4].z() / l;  // node 4 is (0, 0, l)
  ASSERT_NEAR(l1, stretch, 1e-9);
  EXPECT_NEAR(l2, l3, 1e-9);
  EXPECT_NEAR(l2, testing::HandUniaxialLateralStretch(l1), 2e-4);
  double force = 0.0;
  for (int a = 0; a < 8; ++a) {
    if (mesh.nodes[a].x() == l) force += s.reactions()[a].x();
  }
  const double measured = force / (l2 * l * l3 * l);
  const double analytic = testing::HandUniaxialStress(l1, testing::HandUniaxialLateralStretch(l1),
                                                      /*axial=*/true);
  std::printf(
      "uniaxial stretch %.4f: sigma_xx %.8g Pa (analytic %.8g, rel. error %.2e), lateral "
      "stretch %.7f (analytic %.7f)\n",
      l1, measured, analytic, measured / analytic - 1.0, l2,
      testing::HandUniaxialLateralStretch(l1));
  EXPECT_NEAR(measured, analytic, 5e-3 * analytic) << measured << " vs " << analytic;
  // The element's own stress: lateral components vanish against the axial one.
  const Eigen::Matrix3d sigma = s.ElementStress(0);
  EXPECT_LT(std::abs(sigma(1, 1)), 2e-3 * analytic);
  EXPECT_LT(std::abs(sigma(2, 2)), 2e-3 * analytic);
}

// Every node driven at v = gamma_dot * y (simple shear, isochoric). The top face's reaction gives
// sigma_xy = 2 W1 gamma and sigma_yy = -(2/3) W1 gamma^2 with I1b = 3 + gamma^2.
TEST(FeYeoh, SingleElementSimpleShearMatchesAnalytic) {
  const double l = 0.01, gamma_end = 0.8, t_end = 0.01;
  Mesh mesh = MakeBlockMesh(l, l, l, 1, 1, 1);
  SolverOptions opt;
  ExplicitSolver s(mesh, {Tread()}, {}, opt);
  for (int a = 0; a < 8; ++a) {
    s.Prescribe(a, 0, gamma_end / t_end * mesh.nodes[a].y());
    s.Prescribe(a, 1, 0.0);
    s.Prescribe(a, 2, 0.0);
  }
  while (s.time() < t_end) s.Step();
  // The last step's reactions are the element forces at the positions before that step.
  const double gamma =
      (s.positions()[2].x() - s.velocities()[2].x() * s.time_step()) / l;  // (0, l, 0)
  double fx = 0.0, fy = 0.0;
  for (int a = 0; a < 8; ++a) {
    if (mesh.nodes[a].y() == l) {
      fx += s.reactions()[a].x();
      fy += s.reactions()[a].y();
    }
  }
  const double w1 = HandW1(3.0 + gamma * gamma);
  const double sxy = 2.0 * w1 * gamma, syy = -2.0 / 3.0 * w1 * gamma * gamma;
  std::printf(
      "simple shear %.4f: sigma_xy %.10g Pa (analytic %.10g), sigma_yy %.10g (analytic "
      "%.10g)\n",
      gamma, fx / (l * l), sxy, fy / (l * l), syy);
  EXPECT_NEAR(fx / (l * l), sxy, 1e-6 * sxy) << gamma;
  EXPECT_NEAR(fy / (l * l), syy, 1e-6 * std::abs(sxy));
}

}  // namespace
}  // namespace hotlap::fe
