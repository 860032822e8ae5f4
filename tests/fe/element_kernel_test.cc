// The element loop's two compilations (ElementKernel): the portable x86-64 baseline and AVX2 with
// fused multiply-adds. A tumbling, struck, pressurised block with crossed cords in every element
// (rubber, cords in tension and compression, hourglass, bulk viscosity) run for 400 steps on each:
// the same motion and energies to round-off (FMA rounds once, so not bit for bit); each kernel is
// deterministic; the kernel is chosen by name (ParseElementKernel), by default the best.

#include <cmath>
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "fe/fe_test_util.h"
#include "hotlap/common/error.h"
#include "hotlap/fe/explicit_solver.h"
#include "hotlap/fe/mesh.h"

namespace hotlap::fe {
namespace {

constexpr int kNx = 12, kNy = 8, kNz = 6;
constexpr double kH = 0.002;

struct Result {
  std::vector<Eigen::Vector3d> x, v;
  Energies energies;
  double energy_scale = 0.0;
};

Result RunBlock(ElementKernel kernel, int threads) {
  Mesh mesh = MakeBlockMesh(kNx * kH, kNy * kH, kNz * kH, kNx, kNy, kNz);
  testing::AddBlockPressureFaces(mesh, kNx, kNy, kNz, /*top=*/false);
  // Two crossed cord layers in every element, one tension-only, one linear.
  const double c = std::cos(0.4), s = std::sin(0.4);
  for (int e = 0; e < static_cast<int>(mesh.elements.size()); ++e) {
    mesh.fibres.push_back({e, 0, Eigen::Vector3d(c, s, 0.0), 0.01});
    mesh.fibres.push_back({e, 1, Eigen::Vector3d(c, -s, 0.0), 0.01});
  }
  RebarMaterial cord;
  cord.youngs_modulus_Pa = 4e9;
  cord.density_kg_per_m3 = 1400.0;
  cord.area_m2 = 1e-7;
  cord.spacing_m = 1e-3;
  RebarMaterial linear = cord;
  linear.response = FibreResponse::kLinear;
  ExplicitSolver solver(mesh, {testing::Tread()}, {cord, linear}, SolverOptions{});
  solver.set_element_kernel(kernel);
  solver.set_threads(threads);
  solver.SetInitialVelocity(testing::SpinStretchNoiseVelocities(
      mesh.nodes, Eigen::Vector3d(0.5 * kNx * kH, 0.5 * kNy * kH, 0.5 * kNz * kH), 7));
  solver.set_pressure(50e3);
  Result out;
  for (int k = 0; k < 400; ++k) {
    solver.applied_forces().back() =
        k < 100 ? Eigen::Vector3d(0.3, -0.15, 0.45) : Eigen::Vector3d::Zero();
    solver.Step();
    const Energies& e = solver.energies();
    out.energy_scale =
        std::max({out.energy_scale, e.external_work + e.initial_kinetic, e.internal, e.kinetic});
  }
  out.x = solver.positions();
  out.v = solver.velocities();
  out.energies = solver.energies();
  return out;
}

double MaxDifference(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b) {
  double d = 0.0;
  for (size_t k = 0; k < a.size(); ++k) d = std::max(d, (a[k] - b[k]).cwiseAbs().maxCoeff());
  return d;
}

TEST(FeElementKernel, Avx2AndPortableAgreeToRoundOff) {
  if (!ElementKernelSupported(ElementKernel::kAvx2)) {
    GTEST_SKIP() << "this CPU has no AVX2 and FMA";
  }
  for (const int threads : {1, 2}) {
    const Result portable = RunBlock(ElementKernel::kPortable, threads);
    const Result avx2 = RunBlock(ElementKernel::kAvx2, threads);
    // Each is deterministic.
    const Result again = RunBlock(ElementKernel::kAvx2, threads);
    EXPECT_EQ(MaxDifference(avx2.x, again.x), 0.0);
    EXPECT_EQ(avx2.energies.internal, again.energies.internal);
    // The block is 24 mm; its nodes move by millimetres and at metres per second.
    const double dx = MaxDifference(portable.x, avx2.x), dv = MaxDifference(portable.v, avx2.v);
    EXPECT_LT(dx, 1e-10 * kNx * kH) << threads << " threads";
    EXPECT_LT(dv, 1e-9) << threads << " threads";
    EXPECT_GT(dx + dv, 0.0) << "expected the fused multiply-adds to change the last bits";
    const double scale = portable.energy_scale;
    EXPECT_LT(std::abs(portable.energies.internal - avx2.energies.internal), 1e-9 * scale);
    EXPECT_LT(std::abs(portable.energies.kinetic - avx2.energies.kinetic), 1e-9 * scale);
    EXPECT_LT(std::abs(portable.energies.bulk_viscous - avx2.energies.bulk_viscous), 1e-9 * scale);
    EXPECT_LT(std::abs(portable.energies.BalanceError()), 1e-3 * scale);
    EXPECT_LT(std::abs(avx2.energies.BalanceError()), 1e-3 * scale);
    std::printf("%d threads: max |dx| %.3g m, max |dv| %.3g m/s, internal %.12g / %.12g J\n",
                threads, dx, dv, portable.energies.internal, avx2.energies.internal);
  }
}

// The kernel is an option (StepOptions::kernel), chosen by name: the library reads no
// environment variable (the command does: `hotlap fe --kernel`, else HOTLAP_FE_KERNEL).
TEST(FeElementKernel, ParseNamesTheKernelAndTheDefaultIsTheBest) {
  const bool avx2 = ElementKernelSupported(ElementKernel::kAvx2);
  const ElementKernel best = avx2 ? ElementKernel::kAvx2 : ElementKernel::kPortable;
  EXPECT_EQ(BestElementKernel(), best);
  EXPECT_EQ(StepOptions{}.kernel, best);
  EXPECT_EQ(ParseElementKernel("auto", "--kernel"), best);
  EXPECT_EQ(ParseElementKernel("portable", "--kernel"), ElementKernel::kPortable);
  const Mesh mesh = MakeBlockMesh(0.01, 0.01, 0.01, 1, 1, 1);
  EXPECT_EQ(ExplicitSolver(mesh, {testing::Tread()}, {}, SolverOptions{}).element_kernel(), best);
  if (avx2) {
    EXPECT_EQ(ParseElementKernel("avx2", "--kernel"), ElementKernel::kAvx2);
  } else {
    EXPECT_THROW(ParseElementKernel("avx2", "--kernel"), InputError);
  }
  try {
    ParseElementKernel("sse9", "--kernel");
    ADD_FAILURE() << "sse9 accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--kernel 'sse9': use portable, avx2 or auto"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace hotlap::fe
