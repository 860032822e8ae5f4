// The rigid rim: a block whose every node is tied to the rim is a rigid body; a torque about the
// axle and a vertical force then give omega = T t / I and v = F t / M, with I and M summed by hand
// from the lumped nodal masses and the rim's own mass and inertia, and the kinetic energy equals
// the work of the loads.

#include <cmath>

#include <gtest/gtest.h>

#include "fe/fe_test_util.h"
#include "hotlap/fe/explicit_solver.h"
#include "hotlap/fe/mesh.h"

namespace hotlap::fe {
namespace {

TEST(FeRim, TorqueAndForceAccelerateATiedBodyAsARigidBody) {
  const double h = 0.01;
  Mesh mesh = MakeBlockMesh(2 * h, 2 * h, 2 * h, 2, 2, 2);
  for (size_t a = 0; a < mesh.nodes.size(); ++a) mesh.rim_nodes.push_back(static_cast<int>(a));
  ExplicitSolver s(mesh, {testing::Tread()}, {}, SolverOptions{});
  RimSettings rim;
  rim.centre = Eigen::Vector3d(h, h, h);
  rim.mass_kg = 0.05;
  rim.inertia_kgm2 = 2e-5;
  rim.x_mode = RimDofMode::kPrescribedVelocity;
  rim.z_mode = RimDofMode::kFree;
  rim.spin_mode = RimDofMode::kFree;
  s.SetRim(rim);
  double mass = rim.mass_kg, inertia = rim.inertia_kgm2;
  for (size_t a = 0; a < mesh.nodes.size(); ++a) {
    const Eigen::Vector3d r = mesh.nodes[a] - rim.centre;
    mass += s.node_masses()[a];
    inertia += s.node_masses()[a] * (r.x() * r.x() + r.z() * r.z());
  }
  const double torque = 0.02, force = -3.0;
  s.rim_loads().torque_Nm = torque;
  s.rim_loads().force_z_N = force;
  const int n = 2000;
  for (int k = 0; k < n; ++k) s.Step();
  const double t = n * s.time_step();
  EXPECT_NEAR(s.rim_state().spin_rad_per_s, torque * t / inertia, 1e-9 * torque * t / inertia);
  EXPECT_NEAR(s.rim_state().velocity.z(), force * t / mass, 1e-9 * std::abs(force * t / mass));
  EXPECT_NEAR(s.rim_state().velocity.x(), 0.0, 1e-15);
  // Tied nodes move rigidly: the distance between two opposite corners is unchanged.
  const auto& x = s.positions();
  EXPECT_NEAR((x[0] - x[x.size() - 1]).norm(), std::sqrt(12.0) * h, 1e-12);
  // No strain, so the work of the loads is all kinetic energy.
  const Energies& e = s.energies();
  EXPECT_NEAR(e.internal, 0.0, 1e-12);
  EXPECT_NEAR(e.kinetic, e.external_work, 1e-6 * e.external_work);
}

}  // namespace
}  // namespace hotlap::fe
