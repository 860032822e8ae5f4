// CalcMagicFormulaBatch against CalcMagicFormula: the same equations, one point per SIMD lane, so
// the same bits on the same instruction set, whatever branches the points in one batch take.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/tyre/magic_formula.h"
#include "hotlap/tyre/magic_formula_math.h"
#include "hotlap/tyre/tyre_force_model.h"
#include "test_util.h"

namespace hotlap::tyre {
namespace {

MagicFormulaParams<double> LoadTestTir(const std::string& name) {
  return LoadMagicFormula(test::SourcePath("tests/data/tir/mfeval/" + name + ".tir"));
}

TyreOperatingPoint<double> Point(double fz, double kappa, double alpha, double gamma, double vx,
                                 double pressure = 0.0) {
  TyreOperatingPoint<double> op;
  op.fz = fz;
  op.slip_ratio = kappa;
  op.slip_angle = alpha;
  op.camber = gamma;
  op.speed = vx;
  op.pressure = pressure;
  return op;
}

// The inputs of an mfeval oracle file (tests/data/mf_reference/README.md).
std::vector<TyreOperatingPoint<double>> OraclePoints(const std::string& tir, int use_mode) {
  std::istringstream in(test::ReadTextFile(test::SourcePath(
      "tests/data/mf_reference/mfeval431_" + tir + "_mode" + std::to_string(use_mode) + ".csv")));
  const auto split = [](const std::string& text) {
    std::vector<std::string> cells;
    std::stringstream s(text);
    std::string cell;
    while (std::getline(s, cell, ',')) cells.push_back(cell);
    return cells;
  };
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> names = split(line);
  const auto column = [&](const std::string& name) {
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end()) throw std::runtime_error("oracle: no column " + name);
    return static_cast<size_t>(it - names.begin());
  };
  const size_t fz = column("Fz_in"), kappa = column("kappa_in"), alpha = column("alpha_in"),
               gamma = column("gamma_in"), vx = column("Vx_in"), pressure = column("P_in");
  std::vector<TyreOperatingPoint<double>> points;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const auto cells = split(line);
    const auto at = [&](size_t i) { return std::strtod(cells.at(i).c_str(), nullptr); };
    points.push_back(Point(at(fz), at(kappa), at(alpha), at(gamma), at(vx), at(pressure)));
  }
  return points;
}

// Operating points over and beyond the files' ranges, shuffled so that neighbours (lanes of one
// batch) take different branches: loads below zero, zero and up to twice FNOMIN, slip ratios to
// +-1.2, slip angles to +-80 deg, speeds from -10 to 70 m/s with standstill and low speed,
// pressures around INFLPRES or 0 (= INFLPRES), exact zeros of slip and camber.
std::vector<TyreOperatingPoint<double>> RandomPoints(const MagicFormulaParams<double>& p, int n,
                                                     unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<TyreOperatingPoint<double>> points;
  for (int i = 0; i < n; ++i) {
    TyreOperatingPoint<double> op;
    op.fz = p.FNOMIN * (2.1 * unit(rng) - 0.1);
    op.slip_ratio = (2.0 * unit(rng) - 1.0) * (i % 3 == 0 ? 1.2 : 0.3);
    op.slip_angle = (2.0 * unit(rng) - 1.0) * (i % 5 == 0 ? 1.4 : 0.3);
    op.camber = (2.0 * unit(rng) - 1.0) * 0.12;
    op.speed = i % 7 == 0 ? 4.0 * unit(rng) - 2.0 : 80.0 * unit(rng) - 10.0;
    op.pressure = i % 2 == 1 ? 0.0 : p.INFLPRES * (0.7 + 0.6 * unit(rng));
    if (i % 11 == 0) op.camber = 0.0;
    if (i % 13 == 0) op.slip_angle = 0.0;
    if (i % 17 == 0) op.slip_ratio = 0.0;
    if (i % 19 == 0) op.speed = 0.0;
    if (i % 23 == 0) op.fz = 0.0;
    points.push_back(op);
  }
  std::shuffle(points.begin(), points.end(), rng);
  return points;
}

// Points that take different branches, to be put side by side in one batch: standstill, low
// speed, reversing, zero and negative load, loads beyond FZMAX and below FZMIN, slips beyond the
// limits, zero slip angle, exact zeros of either sign, NaN and infinite inputs.
std::vector<TyreOperatingPoint<double>> BranchPoints(const MagicFormulaParams<double>& p) {
  const double fz = p.FNOMIN;
  const double inf = std::numeric_limits<double>::infinity();
  return {
      Point(fz, 0.05, 0.05, 0.02, 20.0),
      Point(fz, 0.05, 0.05, 0.02, 0.0),
      Point(fz, 0.05, 0.05, 0.02, 0.3 * p.VXLOW),
      Point(fz, -0.05, -0.05, -0.02, -15.0),
      Point(0.0, 0.1, 0.1, 0.0, 20.0),
      Point(-100.0, 0.1, 0.1, 0.0, 20.0),
      Point(3.0 * p.FZMAX, 0.1, -0.1, 0.0, 20.0),
      Point(0.5 * p.FZMIN, 0.1, -0.1, 0.0, 20.0),
      Point(fz, 2.0, 1.5, 0.3, 20.0),
      Point(fz, -2.0, -1.5, -0.3, 20.0),
      Point(fz, 0.0, 0.0, 0.0, 20.0),
      Point(fz, -0.0, -0.0, -0.0, 20.0),
      Point(fz, -0.1, -0.2, -0.0, 0.0),
      Point(fz, -1.0, 0.0, 0.0, 1e-3),
      Point(fz, 0.02, 0.0, 0.0, 20.0, 1.3 * p.INFLPRES),
      Point(fz, std::nan(""), 0.05, 0.0, 20.0),
      Point(std::nan(""), 0.05, 0.05, 0.0, 20.0),
      Point(fz, 0.05, inf, 0.0, 20.0),
  };
}

std::array<double, 5> Outputs(const TyreForces<double>& f) {
  return {f.fx, f.fy, f.mx, f.my, f.mz};
}

// Bit for bit, NaN equal to NaN.
void ExpectSameBits(const TyreForces<double>& got, const TyreForces<double>& want,
                    const std::string& what) {
  const auto g = Outputs(got), w = Outputs(want);
  for (size_t k = 0; k < 5; ++k) {
    if (std::isnan(w[k])) {
      EXPECT_TRUE(std::isnan(g[k])) << what << " output " << k;
    } else {
      EXPECT_EQ(std::memcmp(&g[k], &w[k], sizeof(double)), 0)
          << what << " output " << k << ": " << g[k] << " vs " << w[k];
    }
  }
}

std::vector<internal::MathIsa> SupportedIsas() {
  std::vector<internal::MathIsa> isas;
  for (const auto isa : {internal::MathIsa::kGeneric, internal::MathIsa::kAvx2}) {
    if (internal::MathIsaSupported(isa)) isas.push_back(isa);
  }
  return isas;
}

// Every point through the batch, in batches of `size` (the last one short), against one by one.
void ExpectBatchMatchesSingle(const MagicFormulaParams<double>& p,
                              const std::vector<TyreOperatingPoint<double>>& points,
                              const MagicFormulaOptions& options, size_t size,
                              const std::string& what) {
  std::vector<TyreForces<double>> batch(points.size());
  for (size_t i = 0; i < points.size(); i += size) {
    const size_t m = std::min(size, points.size() - i);
    CalcMagicFormulaBatch(p, std::span(points).subspan(i, m), options,
                          std::span(batch).subspan(i, m));
  }
  for (size_t i = 0; i < points.size(); ++i) {
    ExpectSameBits(batch[i], CalcMagicFormula(p, points[i], options),
                   what + " batch size " + std::to_string(size) + " point " + std::to_string(i));
  }
}

struct Case {
  const char* tir;
  int use_mode;
};

std::string CaseName(const ::testing::TestParamInfo<Case>& info) {
  return std::string(info.param.tir) + "_mode" + std::to_string(info.param.use_mode);
}

class MagicFormulaBatchTest : public ::testing::TestWithParam<Case> {
 protected:
  void TearDown() override { internal::SetMathIsa(initial_isa_); }
  const internal::MathIsa initial_isa_ = internal::ActiveMathIsa();
};

TEST_P(MagicFormulaBatchTest, RandomPointsGiveTheSingleResultsBitForBit) {
  const auto p = LoadTestTir(GetParam().tir);
  const auto options = MagicFormulaOptions::FromUseMode(GetParam().use_mode);
  const auto points = RandomPoints(p, 5000, 11 + GetParam().use_mode);
  for (const auto isa : SupportedIsas()) {
    ASSERT_TRUE(internal::SetMathIsa(isa));
    for (const size_t size : {size_t{1}, size_t{3}, size_t{4}, size_t{7}, points.size()}) {
      ExpectBatchMatchesSingle(p, points, options, size, internal::MathIsaName(isa));
    }
  }
}

// Each branch point next to each other in a batch of two and of four (every lane position).
TEST_P(MagicFormulaBatchTest, LanesTakingDifferentBranchesGiveTheSingleResults) {
  const auto p = LoadTestTir(GetParam().tir);
  const auto options = MagicFormulaOptions::FromUseMode(GetParam().use_mode);
  const auto branch = BranchPoints(p);
  std::vector<TyreOperatingPoint<double>> points;
  for (size_t a = 0; a < branch.size(); ++a) {
    for (size_t b = 0; b < branch.size(); ++b) {
      points.push_back(branch[a]);
      points.push_back(branch[b]);
      points.push_back(branch[(a + b) % branch.size()]);
      points.push_back(branch[(a + 2 * b + 1) % branch.size()]);
    }
  }
  for (const auto isa : SupportedIsas()) {
    ASSERT_TRUE(internal::SetMathIsa(isa));
    ExpectBatchMatchesSingle(p, points, options, points.size(), internal::MathIsaName(isa));
  }
}

INSTANTIATE_TEST_SUITE_P(
    Mfeval431, MagicFormulaBatchTest,
    ::testing::Values(
        Case{"MagicFormula52_Parameters", 111}, Case{"MagicFormula52_Parameters", 121},
        Case{"MagicFormula52_Parameters", 211}, Case{"MagicFormula52_Parameters", 221},
        Case{"MagicFormula61_Parameters", 111}, Case{"MagicFormula61_Parameters", 121},
        Case{"MagicFormula61_Parameters", 211}, Case{"MagicFormula61_Parameters", 221},
        Case{"MagicFormula62_Parameters", 111}, Case{"MagicFormula62_Parameters", 121},
        Case{"MagicFormula62_Parameters", 211}, Case{"MagicFormula62_Parameters", 221},
        Case{"PacejkaBook_Defaults", 111}, Case{"PacejkaBook_Defaults", 221}),
    CaseName);

// The mfeval oracle's inputs (every file and mode it has), in one batch.
TEST(MagicFormulaBatchOracleTest, OracleInputsGiveTheSingleResultsBitForBit) {
  const internal::MathIsa initial = internal::ActiveMathIsa();
  for (const char* tir : {"MagicFormula52_Parameters", "MagicFormula61_Parameters",
                          "MagicFormula62_Parameters", "PacejkaBook_Defaults"}) {
    const auto p = LoadTestTir(tir);
    for (const int use_mode : {111, 121}) {
      const auto points = OraclePoints(tir, use_mode);
      ASSERT_GT(points.size(), 400u);
      const auto options = MagicFormulaOptions::FromUseMode(use_mode);
      for (const auto isa : SupportedIsas()) {
        ASSERT_TRUE(internal::SetMathIsa(isa));
        ExpectBatchMatchesSingle(
            p, points, options, points.size(),
            std::string(tir) + " " + std::to_string(use_mode) + " " + internal::MathIsaName(isa));
      }
    }
  }
  internal::SetMathIsa(initial);
}

TEST(MagicFormulaBatchOracleTest, SizesMustMatch) {
  const auto p = LoadTestTir("MagicFormula61_Parameters");
  const std::vector<TyreOperatingPoint<double>> points(5, Point(4000, 0.1, 0.1, 0.0, 20.0));
  std::vector<TyreForces<double>> out(4);
  EXPECT_THROW(CalcMagicFormulaBatch(p, points, {}, out), std::invalid_argument);
  CalcMagicFormulaBatch(p, {}, {}, {});  // nothing to do
}

// Through the variant: a Magic Formula in batches, the other models one by one.
TEST(TyreForcesBatchTest, EveryModelGivesTheSingleResults) {
  for (const char* path : {"tests/data/tir/mfeval/MagicFormula62_Parameters.tir",
                           "data/tyres/brush_example.yaml", "data/tyres/unitire_example.yaml"}) {
    const TyreForceModel<double> model = LoadTyreForceModel(test::SourcePath(path));
    std::vector<TyreOperatingPoint<double>> points;
    for (int i = 0; i < 37; ++i) {
      TyreOperatingPoint<double> op =
          Point(2000.0 + 100.0 * i, -0.2 + 0.011 * i, 0.15 - 0.008 * i, 0.001 * i, 5.0 + i);
      op.tread_temp = 330.0 + i;
      points.push_back(op);
    }
    std::vector<TyreForces<double>> out(points.size());
    CalcTyreForcesBatch(model, points, out);
    for (size_t i = 0; i < points.size(); ++i) {
      ExpectSameBits(out[i], CalcTyreForces(model, points[i]),
                     std::string(path) + " point " + std::to_string(i));
    }
    out.pop_back();
    EXPECT_THROW(CalcTyreForcesBatch(model, points, out), std::invalid_argument) << path;
  }
}

}  // namespace
}  // namespace hotlap::tyre
