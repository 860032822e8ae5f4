// Magic Formula speed: combined-slip evaluations (Fx, Fy, Mx, My, Mz) per second on one core, in
// double and with derivatives with respect to kappa and alpha (ceres::Jet<double, 2>), one point
// per call (CalcMagicFormula) and several (CalcMagicFormulaBatch, one point per SIMD lane). Each
// single-point iteration evaluates one of 256 operating points spread over loads, slips and
// cambers, so that nothing is folded away; each batch iteration evaluates the first N of them.
// Reports items_per_second (evaluations per second); the label names the instruction set of
// libmvec's lanes (magic_formula_math.h). One point is latency-bound (some seven dependent
// transcendental steps per evaluation), so a loaded machine (other processes on the sibling
// hyperthread) slows it markedly: compare runs taken at the same load.
//
// Run: ./build/magic_formula_bench --benchmark_min_time=1

#include <benchmark/benchmark.h>

#include <filesystem>
#include <numbers>
#include <string>
#include <type_traits>
#include <vector>

#include "hotlap/common/scalar.h"
#include "hotlap/tyre/magic_formula.h"
#include "hotlap/tyre/magic_formula_math.h"
#include "hotlap/tyre/tyre_force_model.h"

namespace {

using namespace hotlap;
using namespace hotlap::tyre;

std::filesystem::path TirPath(const std::string& name) {
  return std::filesystem::path(HOTLAP_SOURCE_DIR) / "tests/data/tir/mfeval" / name;
}

// 256 combined-slip points: load 0.5..1.5 FNOMIN, kappa -0.2..0.2, alpha -10..10 deg, camber
// -3..3 deg, 10..40 m/s.
template <class T>
std::vector<TyreOperatingPoint<T>> Points(double fnomin) {
  std::vector<TyreOperatingPoint<T>> points;
  for (int i = 0; i < 256; ++i) {
    TyreOperatingPoint<T> op;
    op.fz = T(fnomin * (0.5 + (i % 7) / 6.0));
    op.slip_ratio = T(-0.2 + 0.4 * ((i * 5) % 17) / 16.0);
    op.slip_angle = T((-10.0 + 20.0 * ((i * 3) % 13) / 12.0) * 3.14159265358979 / 180.0);
    op.camber = T((-3.0 + 6.0 * (i % 5) / 4.0) * 3.14159265358979 / 180.0);
    op.speed = T(10.0 + 30.0 * (i % 4) / 3.0);
    if constexpr (!std::is_same_v<T, double>) {
      op.slip_ratio.v[0] = 1.0;
      op.slip_angle.v[1] = 1.0;
    }
    points.push_back(op);
  }
  return points;
}

// Runs the benchmark with the lanes on `isa` (the widest this machine has if it lacks `isa`).
class ScopedIsa {
 public:
  explicit ScopedIsa(internal::MathIsa isa) { internal::SetMathIsa(isa); }
  ~ScopedIsa() { internal::SetMathIsa(initial_); }
  ScopedIsa(const ScopedIsa&) = delete;
  ScopedIsa& operator=(const ScopedIsa&) = delete;

 private:
  const internal::MathIsa initial_ = internal::ActiveMathIsa();
};

template <class T>
void RunCombined(benchmark::State& state, const std::string& file, int use_mode,
                 internal::MathIsa isa = internal::MathIsa::kAvx2) {
  const ScopedIsa scoped(isa);
  const MagicFormulaParams<double> params = LoadMagicFormula(TirPath(file));
  const MagicFormulaParams<T> p = params.Cast<T>();
  const auto points = Points<T>(params.FNOMIN);
  const MagicFormulaOptions options = MagicFormulaOptions::FromUseMode(use_mode);
  size_t i = 0;
  for (auto _ : state) {
    const TyreForces<T> f = CalcMagicFormula(p, points[i++ & 255], options);
    benchmark::DoNotOptimize(f);
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
  state.SetLabel(internal::MathIsaName(internal::ActiveMathIsa()));
}

void BM_MagicFormula61Combined(benchmark::State& state) {
  RunCombined<double>(state, "MagicFormula61_Parameters.tir", 111);
}
BENCHMARK(BM_MagicFormula61Combined);

void BM_MagicFormula61CombinedTangent(benchmark::State& state) {
  RunCombined<double>(state, "MagicFormula61_Parameters.tir", 121);
}
BENCHMARK(BM_MagicFormula61CombinedTangent);

void BM_MagicFormula52Combined(benchmark::State& state) {
  RunCombined<double>(state, "MagicFormula52_Parameters.tir", 111);
}
BENCHMARK(BM_MagicFormula52Combined);

// The baseline instruction set's two lanes (SSE2 on x86-64): what a machine without AVX2 gets.
void BM_MagicFormula61CombinedGeneric(benchmark::State& state) {
  RunCombined<double>(state, "MagicFormula61_Parameters.tir", 111, internal::MathIsa::kGeneric);
}
BENCHMARK(BM_MagicFormula61CombinedGeneric);

// Through the tyre force model's variant (CalcTyreForces), as the vehicle uses it.
void BM_MagicFormula61ViaTyreForceModel(benchmark::State& state) {
  const TyreForceModel<double> model = LoadTyreForceModel(TirPath("MagicFormula61_Parameters.tir"));
  const auto points =
      Points<double>(LoadMagicFormula(TirPath("MagicFormula61_Parameters.tir")).FNOMIN);
  size_t i = 0;
  for (auto _ : state) {
    const TyreForces<double> f = CalcTyreForces(model, points[i++ & 255]);
    benchmark::DoNotOptimize(f);
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
  state.SetLabel(internal::MathIsaName(internal::ActiveMathIsa()));
}
BENCHMARK(BM_MagicFormula61ViaTyreForceModel);

// The first state.range(0) points per call through CalcMagicFormulaBatch.
void RunBatch(benchmark::State& state, const std::string& file, int use_mode,
              internal::MathIsa isa = internal::MathIsa::kAvx2) {
  const ScopedIsa scoped(isa);
  const MagicFormulaParams<double> params = LoadMagicFormula(TirPath(file));
  const auto all = Points<double>(params.FNOMIN);
  const std::vector<TyreOperatingPoint<double>> points(all.begin(), all.begin() + state.range(0));
  std::vector<TyreForces<double>> out(points.size());
  const MagicFormulaOptions options = MagicFormulaOptions::FromUseMode(use_mode);
  for (auto _ : state) {
    CalcMagicFormulaBatch(params, points, options, out);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * points.size()));
  state.SetLabel(internal::MathIsaName(internal::ActiveMathIsa()));
}

void BM_MagicFormula61CombinedBatch(benchmark::State& state) {
  RunBatch(state, "MagicFormula61_Parameters.tir", 111);
}
BENCHMARK(BM_MagicFormula61CombinedBatch)->Arg(4)->Arg(16)->Arg(256);

void BM_MagicFormula61CombinedTangentBatch(benchmark::State& state) {
  RunBatch(state, "MagicFormula61_Parameters.tir", 121);
}
BENCHMARK(BM_MagicFormula61CombinedTangentBatch)->Arg(256);

void BM_MagicFormula52CombinedBatch(benchmark::State& state) {
  RunBatch(state, "MagicFormula52_Parameters.tir", 111);
}
BENCHMARK(BM_MagicFormula52CombinedBatch)->Arg(256);

// Two SSE2 lanes: what a machine without AVX2 gets.
void BM_MagicFormula61CombinedBatchGeneric(benchmark::State& state) {
  RunBatch(state, "MagicFormula61_Parameters.tir", 111, internal::MathIsa::kGeneric);
}
BENCHMARK(BM_MagicFormula61CombinedBatchGeneric)->Arg(256);

// Through the tyre force model's variant (CalcTyreForcesBatch), as `hotlap tyre eval --sweep`.
void BM_MagicFormula61BatchViaTyreForceModel(benchmark::State& state) {
  const TyreForceModel<double> model = LoadTyreForceModel(TirPath("MagicFormula61_Parameters.tir"));
  const auto points =
      Points<double>(LoadMagicFormula(TirPath("MagicFormula61_Parameters.tir")).FNOMIN);
  std::vector<TyreForces<double>> out(points.size());
  for (auto _ : state) {
    CalcTyreForcesBatch(model, points, out);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * points.size()));
  state.SetLabel(internal::MathIsaName(internal::ActiveMathIsa()));
}
BENCHMARK(BM_MagicFormula61BatchViaTyreForceModel);

// 2^20 points of the Gen-7-like car's left.tir through CalcTyreForcesBatch, already operating
// points in SI (nothing converted or copied): the C++ batch rate that bench/python_tyre_bench.py
// compares hotlap.tyre_forces with (its points are the same).
void BM_TyreForcesMillionPoints(benchmark::State& state) {
  const TyreForceModel<double> model = LoadTyreForceModel(std::filesystem::path(HOTLAP_SOURCE_DIR) /
                                                          "data/cars/gen7/tyres/left.tir");
  const size_t n = size_t{1} << 20;
  std::vector<TyreOperatingPoint<double>> points(n);
  for (size_t i = 0; i < n; ++i) {
    TyreOperatingPoint<double>& op = points[i];
    op.fz = 2000.0 + 8000.0 * static_cast<double>(i % 1000) / 999.0;
    op.slip_angle =
        (-10.0 + 20.0 * static_cast<double>((i * 7) % 1001) / 1000.0) * std::numbers::pi / 180.0;
    op.slip_ratio = -0.2 + 0.4 * static_cast<double>((i * 13) % 1003) / 1002.0;
    op.speed = 20.0;
    op.tread_temp = 25.0 + 273.15;
  }
  std::vector<TyreForces<double>> out(n);
  for (auto _ : state) {
    CalcTyreForcesBatch(model, points, out);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * n));
}
BENCHMARK(BM_TyreForcesMillionPoints)->Unit(benchmark::kMillisecond);

// Value and d/dkappa, d/dalpha of all five outputs.
void BM_MagicFormula61CombinedJet2(benchmark::State& state) {
  RunCombined<Jet2>(state, "MagicFormula61_Parameters.tir", 111);
}
BENCHMARK(BM_MagicFormula61CombinedJet2);

}  // namespace
