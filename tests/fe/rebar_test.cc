// Smeared cords: the fibre stress against the hand-written St Venant-Kirchhoff cord law,
// tension-only against linear under compression, no stress under a rigid rotation, and the
// element's Cauchy stress carrying phi E E_f lambda^2 / J along the deformed cord.

#include "hotlap/fe/rebar.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "fe/fe_test_util.h"
#include "hotlap/fe/explicit_solver.h"
#include "hotlap/fe/mesh.h"

namespace hotlap::fe {
namespace {

RebarMaterial Cord(FibreResponse response) {
  RebarMaterial r;
  r.youngs_modulus_Pa = 4.93515e9;  // 002 Table 2, ply
  r.density_kg_per_m3 = 1068;
  r.response = response;
  return r;
}

TEST(FeRebar, FibreStressFollowsTheCordLaw) {
  const FibreLayer layer{0, 0, Eigen::Vector3d::UnitX(), 0.02};
  const double e = 4.93515e9, phi = 0.02;
  for (double stretch : {1.05, 0.95}) {
    Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
    F(0, 0) = stretch;
    const double ef = 0.5 * (stretch * stretch - 1.0);
    Eigen::Matrix3d p_lin = Eigen::Matrix3d::Zero(), p_ten = Eigen::Matrix3d::Zero();
    const double w_lin = AddFibreStress(Cord(FibreResponse::kLinear), layer, F, p_lin);
    const double w_ten = AddFibreStress(Cord(FibreResponse::kTensionOnly), layer, F, p_ten);
    EXPECT_NEAR(p_lin(0, 0), phi * e * ef * stretch, 1e-9 * phi * e);  // P = F S
    EXPECT_NEAR(w_lin, 0.5 * phi * e * ef * ef, 1e-9 * phi * e * ef * ef);
    if (stretch > 1.0) {
      EXPECT_EQ(p_ten, p_lin);
      EXPECT_EQ(w_ten, w_lin);
    } else {
      EXPECT_EQ(p_ten.norm(), 0.0);  // a cord carries no compression
      EXPECT_EQ(w_ten, 0.0);
      EXPECT_LT(p_lin(0, 0), 0.0);
    }
  }
  // A rigid rotation does not stretch the cord.
  const Eigen::Matrix3d r = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).matrix();
  Eigen::Matrix3d p = Eigen::Matrix3d::Zero();
  AddFibreStress(Cord(FibreResponse::kLinear), layer, r, p);
  EXPECT_LT(p.norm(), 1e-6 * phi * e);
}

// One element with a cord at 30 deg in the x-y plane, sheared: the cord part of the element's
// Cauchy stress is phi E E_f lambda^2 / J along the deformed cord a = F a0 / lambda.
TEST(FeRebar, ElementStressCarriesTheCordAlongItsDeformedDirection) {
  const double l = 0.01, phi = 0.05, e = 4.93515e9;
  Mesh mesh = MakeBlockMesh(l, l, l, 1, 1, 1);
  const Eigen::Vector3d a0(std::cos(std::numbers::pi / 6), std::sin(std::numbers::pi / 6), 0.0);
  mesh.fibres.push_back({0, 0, a0, phi});
  ExplicitSolver with(mesh, {testing::Tread()}, {Cord(FibreResponse::kTensionOnly)}, {});
  mesh.fibres.clear();
  ExplicitSolver without(mesh, {testing::Tread()}, {}, {});
  Eigen::Matrix3d F;
  F << 1.1, 0.2, 0.0, 0.0, 0.97, 0.0, 0.0, 0.0, 1.0;
  std::vector<Eigen::Vector3d> x;
  for (const auto& p : mesh.nodes) x.push_back(F * p);
  with.SetPositions(x);
  without.SetPositions(x);
  const Eigen::Vector3d fa = F * a0;
  const double lambda = fa.norm(), ef = 0.5 * (lambda * lambda - 1.0);
  const Eigen::Vector3d a = fa / lambda;
  const Eigen::Matrix3d expected =
      phi * e * ef * lambda * lambda / F.determinant() * a * a.transpose();
  EXPECT_GT(ef, 0.0);
  EXPECT_TRUE((with.ElementStress(0) - without.ElementStress(0)).isApprox(expected, 1e-9));
}

}  // namespace
}  // namespace hotlap::fe
