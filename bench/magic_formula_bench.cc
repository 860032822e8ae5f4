// Magic Formula speed: combined-slip evaluations (Fx, Fy, Mx, My, Mz) per second on one core, in
// double and with derivatives with respect to kappa and alpha (ceres::Jet<double, 2>). Each
// iteration evaluates one of 256 operating points spread over loads, slips and cambers, so that
// nothing is folded away. Reports items_per_second (evaluations per second).
//
// Run: ./build/magic_formula_bench --benchmark_min_time=1

#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>
#include <vector>

#include "hotlap/common/scalar.h"
#include "hotlap/tyre/magic_formula.h"

namespace {

using namespace hotlap;
using namespace hotlap::tyre;

MagicFormulaParams<double> Load(const std::string& name) {
  return LoadMagicFormula(std::filesystem::path(HOTLAP_SOURCE_DIR) / "tests/data/tir/mfeval" /
                          name);
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

template <class T>
void RunCombined(benchmark::State& state, const std::string& file, int use_mode) {
  const MagicFormulaParams<double> params = Load(file);
  const MagicFormulaParams<T> p = params.Cast<T>();
  const auto points = Points<T>(params.FNOMIN);
  const MagicFormulaOptions options = MagicFormulaOptions::FromUseMode(use_mode);
  size_t i = 0;
  for (auto _ : state) {
    const TyreForces<T> f = CalcMagicFormula(p, points[i++ & 255], options);
    benchmark::DoNotOptimize(f);
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
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

// Value and d/dkappa, d/dalpha of all five outputs.
void BM_MagicFormula61CombinedJet2(benchmark::State& state) {
  RunCombined<Jet2>(state, "MagicFormula61_Parameters.tir", 111);
}
BENCHMARK(BM_MagicFormula61CombinedJet2);

}  // namespace
