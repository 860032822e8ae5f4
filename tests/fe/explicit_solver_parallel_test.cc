// The explicit solver on several threads (OpenMP): the element colours share no node; a tumbling,
// pressurised block run on 1 and 2 threads with the coloured assembly gives the same result bit
// for bit; the per-thread-buffer assembly (the default) is deterministic for a thread count and
// its 2-thread run agrees with the serial one to round-off; the energy balance closes on 2 threads;
// an inverted element found inside the parallel loop is reported as a NumericalError, not a crash.

#include <cmath>
#include <set>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "fe/fe_test_util.h"
#include "hotlap/common/error.h"
#include "hotlap/fe/explicit_solver.h"
#include "hotlap/fe/mesh.h"

namespace hotlap::fe {
namespace {

// 12 x 8 x 6 elements of 2 mm: 576 elements and 819 nodes, more than one block of the solver's
// fixed-block sums (512) in both, so the sums' order is exercised too.
constexpr int kBlockNx = 12, kBlockNy = 8, kBlockNz = 6;
constexpr double kBlockH = 0.002;

Mesh Block() {
  Mesh mesh = MakeBlockMesh(kBlockNx * kBlockH, kBlockNy * kBlockH, kBlockNz * kBlockH, kBlockNx,
                            kBlockNy, kBlockNz);
  testing::AddBlockPressureFaces(mesh, kBlockNx, kBlockNy, kBlockNz, /*top=*/true);
  return mesh;
}

struct ParallelResult {
  std::vector<Eigen::Vector3d> x, v;
  Energies energies;
  double worst_balance = 0.0;  // max |balance error| / energy scale over the run
};

// A spinning, stretching block with random nodal velocities, squeezed by 50 kPa on two faces and
// struck on a corner (0.3 x (2, -1, 3) N for 100 steps: a 1 N push on one 2 mm corner is so
// violent that the O(dt^2) balance error of the nonlinear motion reaches 3e-3): every force kind of
// the element loop is active (rubber, hourglass, bulk viscosity in compression and tension).
ParallelResult RunBlock(int threads, Assembly assembly, double pulse_N = 0.3, int steps = 400,
                        const SolverOptions& options = {}) {
  const Mesh mesh = Block();
  ExplicitSolver s(mesh, {testing::Tread()}, {}, options);
  s.set_threads(threads);
  s.set_assembly(assembly);
  EXPECT_EQ(s.threads(), threads);
  s.SetInitialVelocity(testing::SpinStretchNoiseVelocities(
      mesh.nodes,
      Eigen::Vector3d(0.5 * kBlockNx * kBlockH, 0.5 * kBlockNy * kBlockH, 0.5 * kBlockNz * kBlockH),
      5));
  s.set_pressure(50e3);
  ParallelResult out;
  double scale = 0.0;
  for (int k = 0; k < steps; ++k) {
    s.applied_forces().back() = k < 100 ? Eigen::Vector3d(pulse_N * Eigen::Vector3d(2.0, -1.0, 3.0))
                                        : Eigen::Vector3d::Zero();
    s.Step();
    const Energies& e = s.energies();
    scale = std::max({scale, e.external_work + e.initial_kinetic, e.internal, e.kinetic});
    out.worst_balance = std::max(out.worst_balance, std::abs(e.BalanceError()));
  }
  out.worst_balance /= scale;
  out.x = s.positions();
  out.v = s.velocities();
  out.energies = s.energies();
  return out;
}

TEST(FeParallel, ColoursShareNoNodeAndCoverEveryElementOnce) {
  const Mesh mesh = Block();
  ExplicitSolver s(mesh, {testing::Tread()}, {}, SolverOptions{});
  EXPECT_EQ(s.colours(), 8);  // a structured hexahedral mesh: the 2 x 2 x 2 parity classes
  std::vector<int> seen(mesh.elements.size(), 0);
  for (int c = 0; c < s.colours(); ++c) {
    std::set<int> nodes;
    for (int e : s.ColourElements(c)) {
      ++seen[e];
      for (int n : mesh.elements[e]) EXPECT_TRUE(nodes.insert(n).second) << "colour " << c;
    }
  }
  for (int count : seen) EXPECT_EQ(count, 1);
}

// Coloured assembly: each node receives one element's force per colour, the colours in a fixed
// order, and every sum runs over fixed blocks; so the thread count cannot change a single bit.
TEST(FeParallel, ColouredRunIsBitIdenticalOnOneAndTwoThreads) {
  const ParallelResult one = RunBlock(1, Assembly::kColoured),
                       two = RunBlock(2, Assembly::kColoured);
  ASSERT_EQ(one.x.size(), two.x.size());
  for (size_t a = 0; a < one.x.size(); ++a) {
    ASSERT_EQ(one.x[a], two.x[a]) << "node " << a;
    ASSERT_EQ(one.v[a], two.v[a]) << "node " << a;
  }
  EXPECT_EQ(one.energies.internal, two.energies.internal);
  EXPECT_EQ(one.energies.kinetic, two.energies.kinetic);
  EXPECT_EQ(one.energies.Hourglass(), two.energies.Hourglass());
  EXPECT_EQ(one.energies.bulk_viscous, two.energies.bulk_viscous);
  EXPECT_EQ(one.energies.external_work, two.energies.external_work);
  // The run did something: the block moved and deformed, and the balance closes on 2 threads.
  EXPECT_GT(two.energies.internal, 1e-4 * two.energies.kinetic);
  EXPECT_GT(two.energies.bulk_viscous, 0.0);
  EXPECT_LT(two.worst_balance, 1e-3);
}

// Per-thread buffers: the same thread count gives the same bits; against the serial run (one
// thread: the elements in order) the nodal force sums are associated differently, which changes the
// last bits of each step's forces (relative 1e-16); over 400 steps of this smooth, stable motion
// such differences grow to no more than about 1e-13 of the block's size. The tolerances (1e-10 of
// the size for positions, 1e-9 of the energy scale) are far above that and far below any real error
// (a lost or doubled element force moves nodes by about 1e-6 of the size in one step here).
TEST(FeParallel, ThreadBuffersAreDeterministicAndAgreeToRoundOff) {
  const ParallelResult a = RunBlock(2, Assembly::kThreadBuffers),
                       b = RunBlock(2, Assembly::kThreadBuffers);
  const ParallelResult ref = RunBlock(1, Assembly::kThreadBuffers);
  double max_dx = 0.0;
  bool any_difference = false;
  for (size_t n = 0; n < a.x.size(); ++n) {
    ASSERT_EQ(a.x[n], b.x[n]) << "node " << n;
    max_dx = std::max(max_dx, (a.x[n] - ref.x[n]).norm());
    any_difference = any_difference || a.x[n] != ref.x[n];
  }
  const double size = kBlockNx * kBlockH;
  EXPECT_LT(max_dx, 1e-10 * size);
  const double scale = ref.energies.external_work + ref.energies.initial_kinetic;
  EXPECT_NEAR(a.energies.internal, ref.energies.internal, 1e-9 * scale);
  EXPECT_NEAR(a.energies.kinetic, ref.energies.kinetic, 1e-9 * scale);
  EXPECT_NEAR(a.energies.bulk_viscous, ref.energies.bulk_viscous, 1e-9 * scale);
  EXPECT_LT(a.worst_balance, 1e-3);
  std::printf("2 threads vs serial: max |dx| = %.3g m (%.3g of the size), differ: %d\n", max_dx,
              max_dx / size, any_difference);
}

// Viscous hourglass control (off by default, so its forces and per-thread buffers are skipped
// then): on 2 threads with per-thread buffers it dissipates as on one, and the balance closes.
TEST(FeParallel, ThreadBuffersCarryTheViscousHourglassForces) {
  SolverOptions options;
  options.hourglass_viscous = 0.1;
  const ParallelResult a = RunBlock(2, Assembly::kThreadBuffers, 0.3, 400, options);
  const ParallelResult ref = RunBlock(1, Assembly::kThreadBuffers, 0.3, 400, options);
  const double scale = ref.energies.external_work + ref.energies.initial_kinetic;
  EXPECT_GT(ref.energies.hourglass_dissipated, 1e-6 * scale);
  EXPECT_NEAR(a.energies.hourglass_dissipated, ref.energies.hourglass_dissipated, 1e-9 * scale);
  double max_dx = 0.0;
  for (size_t n = 0; n < a.x.size(); ++n) max_dx = std::max(max_dx, (a.x[n] - ref.x[n]).norm());
  EXPECT_LT(max_dx, 1e-10 * kBlockNx * kBlockH);
  EXPECT_LT(a.worst_balance, 1e-3);
}

// An element inverted inside the parallel loop: the error leaves the OpenMP region as a
// NumericalError naming the lowest inverted element, on any thread count and either assembly.
TEST(FeParallel, InvertedElementIsReportedFromTheParallelLoop) {
  for (Assembly assembly : {Assembly::kColoured, Assembly::kThreadBuffers}) {
    const Mesh mesh = Block();
    ExplicitSolver s(mesh, {testing::Tread()}, {}, SolverOptions{});
    s.set_threads(2);
    s.set_assembly(assembly);
    std::vector<Eigen::Vector3d> x = mesh.nodes;
    // Element 300 turned inside out: its top face pushed below its bottom face.
    for (int a = 4; a < 8; ++a) x[mesh.elements[300][a]].z() -= 2.0 * kBlockH;
    s.SetPositions(x);
    try {
      s.Step();
      ADD_FAILURE() << "no error";
    } catch (const NumericalError& e) {
      EXPECT_NE(std::string(e.what()).find("inverted"), std::string::npos) << e.what();
    }
  }
}

// The default (0) is OpenMP's, capped at one thread per 1000 elements; a count given is used.
TEST(FeParallel, ThreadCountDefaultAndChoice) {
  ExplicitSolver s(Block(), {testing::Tread()}, {}, SolverOptions{});
  EXPECT_THROW(s.set_threads(-1), InputError);
  EXPECT_EQ(s.threads(), 1);  // 576 elements
  s.set_threads(3);
  EXPECT_EQ(s.threads(), 3);
  ExplicitSolver big(MakeBlockMesh(1, 1, 1, 40, 10, 10), {testing::Tread()}, {}, SolverOptions{});
  EXPECT_EQ(big.threads(), std::min(4, DefaultThreadCount()));
}

}  // namespace
}  // namespace hotlap::fe
