#include "hotlap/tyre/magic_formula.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "test_util.h"

namespace hotlap::tyre {
namespace {

MagicFormulaParams<double> MfLoadTestTir(const std::string& relative) {
  return LoadMagicFormula(test::SourcePath("tests/data/tir/" + relative));
}

TyreOperatingPoint<double> MfPoint(double fz, double kappa, double alpha, double gamma = 0.0,
                                   double vx = 16.6, double pressure = 0.0) {
  TyreOperatingPoint<double> op;
  op.fz = fz;
  op.slip_ratio = kappa;
  op.slip_angle = alpha;
  op.camber = gamma;
  op.speed = vx;
  op.pressure = pressure;
  return op;
}

// ---------------------------------------------------------------------------------------------
// mfeval 4.3.1 oracle: every row of every reference file (tests/data/mf_reference/README.md).

struct OracleCase {
  const char* tir;  // under tests/data/tir/mfeval/, without .tir
  int use_mode;
};

std::string OracleName(const ::testing::TestParamInfo<OracleCase>& info) {
  return std::string(info.param.tir) + "_mode" + std::to_string(info.param.use_mode);
}

// The oracle CSV: a header and rows of numbers; mfeval's extra outputs hold Inf and NaN, which
// hotlap's telemetry CSV reader rightly rejects, so the test reads it itself.
struct OracleTable {
  std::vector<std::string> names;
  std::vector<std::vector<double>> columns;

  const std::vector<double>& Column(const std::string& name) const {
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end()) throw std::runtime_error("oracle: no column " + name);
    return columns[static_cast<size_t>(it - names.begin())];
  }
};

OracleTable ReadOracle(const std::filesystem::path& path) {
  std::istringstream in(test::ReadTextFile(path));
  OracleTable table;
  std::string line;
  const auto split = [](const std::string& text) {
    std::vector<std::string> cells;
    std::stringstream s(text);
    std::string cell;
    while (std::getline(s, cell, ',')) cells.push_back(cell);
    return cells;
  };
  std::getline(in, line);
  table.names = split(line);
  table.columns.resize(table.names.size());
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const auto cells = split(line);
    if (cells.size() != table.names.size()) throw std::runtime_error("oracle: ragged row");
    for (size_t i = 0; i < cells.size(); ++i) {
      table.columns[i].push_back(std::strtod(cells[i].c_str(), nullptr));
    }
  }
  return table;
}

class MagicFormulaOracleTest : public ::testing::TestWithParam<OracleCase> {};

TEST_P(MagicFormulaOracleTest, MatchesMfevalOnEveryRow) {
  const OracleCase c = GetParam();
  const MagicFormulaParams<double> params = MfLoadTestTir(std::string("mfeval/") + c.tir + ".tir");
  const OracleTable table =
      ReadOracle(test::SourcePath("tests/data/mf_reference/mfeval431_" + std::string(c.tir) +
                                  "_mode" + std::to_string(c.use_mode) + ".csv"));
  const auto& fz = table.Column("Fz_in");
  const auto& kappa = table.Column("kappa_in");
  const auto& alpha = table.Column("alpha_in");
  const auto& gamma = table.Column("gamma_in");
  const auto& phit = table.Column("phit_in");
  const auto& vx = table.Column("Vx_in");
  const auto& pressure = table.Column("P_in");
  const auto& use_mode = table.Column("useMode");
  const std::array<const std::vector<double>*, 5> expected = {
      &table.Column("Fx"), &table.Column("Fy"), &table.Column("Mx"), &table.Column("My"),
      &table.Column("Mz")};
  const std::array<const char*, 5> names = {"Fx", "Fy", "Mx", "My", "Mz"};
  // Acceptance: 0.1 N / N m for Fx, Fy, Mx, 0.5 N m for Mz; My is met far more closely.
  const std::array<double, 5> tolerance = {0.1, 0.1, 0.1, 1e-3, 0.5};

  const MagicFormulaOptions options = MagicFormulaOptions::FromUseMode(c.use_mode);
  std::array<double, 5> max_error{};
  ASSERT_GT(fz.size(), 400u);
  for (size_t row = 0; row < fz.size(); ++row) {
    ASSERT_EQ(use_mode[row], c.use_mode);
    ASSERT_EQ(phit[row], 0.0);
    const TyreForces<double> f = CalcMagicFormula(
        params, MfPoint(fz[row], kappa[row], alpha[row], gamma[row], vx[row], pressure[row]),
        options);
    const std::array<double, 5> got = {f.fx, f.fy, f.mx, f.my, f.mz};
    for (size_t k = 0; k < 5; ++k) {
      const double error = std::abs(got[k] - (*expected[k])[row]);
      max_error[k] = std::max(max_error[k], error);
      EXPECT_LE(error, tolerance[k]) << names[k] << " at line " << row + 2;
    }
  }
  std::printf("[   info   ] %s mode %d max |error|: Fx %.2e Fy %.2e Mx %.2e My %.2e Mz %.2e\n",
              c.tir, c.use_mode, max_error[0], max_error[1], max_error[2], max_error[3],
              max_error[4]);
}

INSTANTIATE_TEST_SUITE_P(Mfeval431, MagicFormulaOracleTest,
                         ::testing::Values(OracleCase{"MagicFormula52_Parameters", 111},
                                           OracleCase{"MagicFormula52_Parameters", 121},
                                           OracleCase{"MagicFormula61_Parameters", 111},
                                           OracleCase{"MagicFormula61_Parameters", 121},
                                           OracleCase{"MagicFormula62_Parameters", 111},
                                           OracleCase{"MagicFormula62_Parameters", 121},
                                           OracleCase{"PacejkaBook_Defaults", 111},
                                           OracleCase{"PacejkaBook_Defaults", 121}),
                         OracleName);

TEST(MagicFormulaTest, SpotValuesOfMfeval) {
  const auto p = MfLoadTestTir("mfeval/MagicFormula61_Parameters.tir");
  const auto lateral = CalcMagicFormula(p, MfPoint(6752, 0.0, DegToRad(5.0)), {});
  EXPECT_NEAR(lateral.fy, -6526.979, 1e-3);
  EXPECT_NEAR(lateral.mz, 45.4756, 1e-4);
  const auto longitudinal = CalcMagicFormula(p, MfPoint(6752, 0.1, 0.0), {});
  EXPECT_NEAR(longitudinal.fx, 8306.088, 1e-3);
}

// ---------------------------------------------------------------------------------------------
// Chrono's PAC2002 / MF-Tyre 5.0 files: they load and give finite forces of the right sign.

class MagicFormulaChronoTest : public ::testing::TestWithParam<const char*> {};

TEST_P(MagicFormulaChronoTest, FiniteAndSignCorrect) {
  const auto p = MfLoadTestTir(std::string("chrono/") + GetParam());
  EXPECT_EQ(p.version, MagicFormulaVersion::kMf52);
  const double fz = p.FNOMIN;
  // Without limit checks (the 335/65R22.5 file's slip range is KPUMAX = 0: braking only).
  for (const auto limits : {MagicFormulaLimits::kNone, MagicFormulaLimits::kClamp}) {
    MagicFormulaOptions o;
    o.limits = limits;
    const auto drive = CalcMagicFormula(p, MfPoint(fz, 0.05, 0.0, 0.0, 20.0), o);
    const auto brake = CalcMagicFormula(p, MfPoint(fz, -0.05, 0.0, 0.0, 20.0), o);
    const auto left = CalcMagicFormula(p, MfPoint(fz, 0.0, DegToRad(3.0), 0.0, 20.0), o);
    const auto combined =
        CalcMagicFormula(p, MfPoint(fz, -0.05, DegToRad(3.0), DegToRad(2.0), 20.0), o);
    for (const auto& f : {drive, brake, left, combined}) {
      for (const double x : {f.fx, f.fy, f.mx, f.my, f.mz}) EXPECT_TRUE(std::isfinite(x));
    }
    if (limits == MagicFormulaLimits::kNone || p.KPUMAX >= 0.05) {
      EXPECT_GT(drive.fx, 0.0);
    }
    EXPECT_LT(brake.fx, 0.0);
    EXPECT_LT(left.fy, 0.0);
    EXPECT_GT(left.mz, 0.0);  // the aligning torque turns the wheel towards its motion
    EXPECT_LT(drive.my, 0.0 + 1e-12);
    EXPECT_LT(combined.fx, 0.0);
    EXPECT_LT(combined.fy, 0.0);
    // Combined slip reduces each force below its pure-slip value.
    EXPECT_LT(std::abs(combined.fx), std::abs(brake.fx));
  }
}

INSTANTIATE_TEST_SUITE_P(Chrono, MagicFormulaChronoTest,
                         ::testing::Values("HMMWV_Pac02Tire.tir", "Sedan_Pac02Tire.tir",
                                           "mf_185_80R14.tir", "335_65R22_5_G275MSA_60psi.tir"));

// ---------------------------------------------------------------------------------------------
// Options, limits and edge cases.

TEST(MagicFormulaTest, UseModesMapToOptions) {
  EXPECT_EQ(MagicFormulaOptions::FromUseMode(111).limits, MagicFormulaLimits::kClamp);
  EXPECT_EQ(MagicFormulaOptions::FromUseMode(111).slip_form, MagicFormulaSlipForm::kAngle);
  EXPECT_EQ(MagicFormulaOptions::FromUseMode(121).slip_form, MagicFormulaSlipForm::kTangent);
  EXPECT_EQ(MagicFormulaOptions::FromUseMode(211).limits, MagicFormulaLimits::kNone);
  EXPECT_EQ(MagicFormulaOptions::FromUseMode(221).slip_form, MagicFormulaSlipForm::kTangent);
  try {
    MagicFormulaOptions::FromUseMode(112);
    FAIL() << "turn slip accepted";
  } catch (const InputError& e) {
    EXPECT_TRUE(test::Contains(e.what(), "112"));
  }
}

TEST(MagicFormulaTest, LimitChecksClampToTheFileRanges) {
  const auto p = MfLoadTestTir("mfeval/MagicFormula61_Parameters.tir");
  MagicFormulaOptions none;
  none.limits = MagicFormulaLimits::kNone;
  // Load above FZMAX and slip angle above ALPMAX are clamped in 111, not in 211.
  const auto at_max = CalcMagicFormula(p, MfPoint(p.FZMAX, 0.0, p.ALPMAX), {});
  const auto above = CalcMagicFormula(p, MfPoint(p.FZMAX + 2000.0, 0.0, p.ALPMAX + 0.2), {});
  EXPECT_DOUBLE_EQ(above.fy, at_max.fy);
  EXPECT_DOUBLE_EQ(above.fx, at_max.fx);
  const auto above_none = CalcMagicFormula(p, MfPoint(p.FZMAX + 2000.0, 0.0, p.ALPMAX + 0.2), none);
  EXPECT_NE(above_none.fy, at_max.fy);
  // Camber and slip ratio too.
  EXPECT_DOUBLE_EQ(CalcMagicFormula(p, MfPoint(6000, 0.0, 0.05, p.CAMMAX + 0.1), {}).fy,
                   CalcMagicFormula(p, MfPoint(6000, 0.0, 0.05, p.CAMMAX), {}).fy);
  EXPECT_DOUBLE_EQ(CalcMagicFormula(p, MfPoint(6000, p.KPUMAX + 0.5, 0.0), {}).fx,
                   CalcMagicFormula(p, MfPoint(6000, p.KPUMAX, 0.0), {}).fx);
  // Pressure: 0 means INFLPRES; below PRESMIN is clamped.
  EXPECT_DOUBLE_EQ(CalcMagicFormula(p, MfPoint(6000, 0.05, 0.05, 0.0, 16.6, 0.0), {}).fx,
                   CalcMagicFormula(p, MfPoint(6000, 0.05, 0.05, 0.0, 16.6, p.INFLPRES), {}).fx);
  EXPECT_DOUBLE_EQ(CalcMagicFormula(p, MfPoint(6000, 0.05, 0.05, 0.0, 16.6, 1.0), {}).fx,
                   CalcMagicFormula(p, MfPoint(6000, 0.05, 0.05, 0.0, 16.6, p.PRESMIN), {}).fx);
}

TEST(MagicFormulaTest, ZeroLoadAndStandstillAreFinite) {
  const auto p = MfLoadTestTir("mfeval/MagicFormula61_Parameters.tir");
  for (const auto& op :
       {MfPoint(0.0, 0.1, 0.1), MfPoint(-100.0, 0.1, 0.1), MfPoint(4000, 0.1, 0.1, 0, 0),
        MfPoint(4000, 0.1, 0.1, 0, 0.3), MfPoint(4000, 0.1, 0.1, 0, -10.0)}) {
    const auto f = CalcMagicFormula(p, op, {});
    for (const double x : {f.fx, f.fy, f.mx, f.my, f.mz}) EXPECT_TRUE(std::isfinite(x));
  }
  const auto unloaded = CalcMagicFormula(p, MfPoint(0.0, 0.1, 0.1), {});
  EXPECT_EQ(unloaded.fx, 0.0);
  EXPECT_EQ(unloaded.fy, 0.0);
  EXPECT_EQ(CalcMagicFormula(p, MfPoint(4000, 0.1, 0.1, 0, 0), {}).my, 0.0);
}

TEST(MagicFormulaTest, ReversingFlipsTheLongitudinalForce) {
  const auto p = MfLoadTestTir("mfeval/MagicFormula61_Parameters.tir");
  const auto forward = CalcMagicFormula(p, MfPoint(5000, 0.05, 0.0, 0.0, 10.0), {});
  const auto backward = CalcMagicFormula(p, MfPoint(5000, 0.05, 0.0, 0.0, -10.0), {});
  EXPECT_DOUBLE_EQ(backward.fx, -forward.fx);
  EXPECT_GT(backward.my, 0.0);
  EXPECT_LT(forward.my, 0.0);
}

// ---------------------------------------------------------------------------------------------
// Scalar types and derivatives.

template <class T>
class MagicFormulaScalarTest : public ::testing::Test {};
TYPED_TEST_SUITE(MagicFormulaScalarTest, test::AllScalarTypes);

TYPED_TEST(MagicFormulaScalarTest, SameValuesAsDouble) {
  using T = TypeParam;
  for (const char* file :
       {"mfeval/MagicFormula61_Parameters.tir", "mfeval/MagicFormula52_Parameters.tir"}) {
    const auto p = MfLoadTestTir(file);
    const auto op = MfPoint(5000, -0.04, DegToRad(4.0), DegToRad(-2.0), 20.0);
    const auto expected = CalcMagicFormula(p, op, {});
    TyreOperatingPoint<T> op_t;
    op_t.fz = T(op.fz);
    op_t.slip_ratio = T(op.slip_ratio);
    op_t.slip_angle = T(op.slip_angle);
    op_t.camber = T(op.camber);
    op_t.speed = T(op.speed);
    for (const auto options :
         {MagicFormulaOptions::FromUseMode(111), MagicFormulaOptions::FromUseMode(221)}) {
      const auto f = CalcMagicFormula(p.Cast<T>(), op_t, options);
      const auto g = CalcMagicFormula(p, op, options);
      EXPECT_NEAR(ValueOf(f.fx), g.fx, 1e-9 * std::abs(g.fx)) << file;
      EXPECT_NEAR(ValueOf(f.fy), g.fy, 1e-9 * std::abs(g.fy)) << file;
      EXPECT_NEAR(ValueOf(f.mx), g.mx, 1e-9 * std::abs(g.mx) + 1e-12) << file;
      EXPECT_NEAR(ValueOf(f.my), g.my, 1e-9 * std::abs(g.my) + 1e-12) << file;
      EXPECT_NEAR(ValueOf(f.mz), g.mz, 1e-9 * std::abs(g.mz) + 1e-12) << file;
    }
    EXPECT_NE(expected.fx, 0.0);
  }
}

std::array<double, 5> MfOutputs(const TyreForces<double>& f) {
  return {f.fx, f.fy, f.mx, f.my, f.mz};
}

// Jet derivatives with respect to kappa and alpha against central differences, for both
// versions, both slip forms, at points away from the switching surfaces.
TEST(MagicFormulaDerivativeTest, SlipDerivativesMatchCentralDifferences) {
  for (const char* file :
       {"mfeval/MagicFormula61_Parameters.tir", "mfeval/MagicFormula52_Parameters.tir",
        "mfeval/PacejkaBook_Defaults.tir"}) {
    const auto p = MfLoadTestTir(file);
    const auto p_jet = p.Cast<Jet2>();
    for (const int mode : {111, 121, 211}) {
      const auto options = MagicFormulaOptions::FromUseMode(mode);
      for (const auto& op : {MfPoint(0.8 * p.FNOMIN, 0.03, DegToRad(2.0), DegToRad(1.0), 25.0),
                             MfPoint(1.2 * p.FNOMIN, -0.12, DegToRad(-7.0), DegToRad(-2.0), 12.0),
                             MfPoint(p.FNOMIN, 0.2, DegToRad(0.5), 0.0, 30.0)}) {
        TyreOperatingPoint<Jet2> op_jet;
        op_jet.fz = Jet2(op.fz);
        op_jet.slip_ratio = Jet2(op.slip_ratio, 0);
        op_jet.slip_angle = Jet2(op.slip_angle, 1);
        op_jet.camber = Jet2(op.camber);
        op_jet.speed = Jet2(op.speed);
        const auto f = CalcMagicFormula(p_jet, op_jet, options);
        const std::array<Jet2, 5> jets = {f.fx, f.fy, f.mx, f.my, f.mz};
        const auto eval = [&](const TyreOperatingPoint<double>& x) {
          return MfOutputs(CalcMagicFormula(p, x, options));
        };
        const auto d_kappa = test::CentralDifference(
            op, [](auto& x) -> double& { return x.slip_ratio; }, eval);
        const auto d_alpha = test::CentralDifference(
            op, [](auto& x) -> double& { return x.slip_angle; }, eval);
        const std::string where = std::string(file) + " mode " + std::to_string(mode);
        for (size_t k = 0; k < 5; ++k) {
          const double scale = std::max(1.0, std::abs(jets[k].a));
          test::ExpectNearDerivative(jets[k].v[0], d_kappa[k], scale,
                                     where + " d/dkappa output " + std::to_string(k));
          test::ExpectNearDerivative(jets[k].v[1], d_alpha[k], scale,
                                     where + " d/dalpha output " + std::to_string(k));
        }
      }
    }
  }
}

// Derivatives with respect to coefficients, as a fit needs them.
TEST(MagicFormulaDerivativeTest, CoefficientDerivativesMatchCentralDifferences) {
  const auto p = MfLoadTestTir("mfeval/MagicFormula61_Parameters.tir");
  auto p_jet = p.Cast<Jet2>();
  p_jet.PDY1.v[0] = 1.0;
  p_jet.QDZ1.v[1] = 1.0;
  const auto op = MfPoint(7000, -0.05, DegToRad(3.0), DegToRad(1.0), 20.0);
  TyreOperatingPoint<Jet2> op_jet;
  op_jet.fz = Jet2(op.fz);
  op_jet.slip_ratio = Jet2(op.slip_ratio);
  op_jet.slip_angle = Jet2(op.slip_angle);
  op_jet.camber = Jet2(op.camber);
  op_jet.speed = Jet2(op.speed);
  const auto f = CalcMagicFormula(p_jet, op_jet, {});
  const auto eval = [&](const MagicFormulaParams<double>& x) {
    return MfOutputs(CalcMagicFormula(x, op, {}));
  };
  const auto d_pdy1 = test::CentralDifference(
      p, [](auto& x) -> double& { return x.PDY1; }, eval);
  const auto d_qdz1 = test::CentralDifference(
      p, [](auto& x) -> double& { return x.QDZ1; }, eval);
  const std::array<Jet2, 5> jets = {f.fx, f.fy, f.mx, f.my, f.mz};
  for (size_t k = 0; k < 5; ++k) {
    const double scale = std::max(1.0, std::abs(jets[k].a));
    test::ExpectNearDerivative(jets[k].v[0], d_pdy1[k], scale, "d/dPDY1 " + std::to_string(k));
    test::ExpectNearDerivative(jets[k].v[1], d_qdz1[k], scale, "d/dQDZ1 " + std::to_string(k));
  }
  EXPECT_NE(jets[1].v[0], 0.0);  // Fy depends on PDY1
  EXPECT_NE(jets[4].v[1], 0.0);  // Mz depends on QDZ1
}

}  // namespace
}  // namespace hotlap::tyre
