// End-to-end tests of `hotlap tyre eval` and `hotlap tyre fit --model unitire`: documented JSON
// keys and CSV columns, the UniTire paper's fit-and-predict protocol on synthesized rig data, and
// bad input giving a clear message, a non-zero exit and no output.

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "apps/run_hotlap.h"
#include "hotlap/common/csv.h"
#include "hotlap/common/units.h"
#include "hotlap/ident/mf_fit.h"
#include "hotlap/ident/rig_data.h"
#include "hotlap/ident/unitire_fit.h"
#include "hotlap/tyre/tir_file.h"
#include "hotlap/tyre/tyre_force_model.h"
#include "hotlap/tyre/tyre_force_params_io.h"
#include "test_util.h"

namespace hotlap {
namespace {

namespace fs = std::filesystem;

const fs::path kTir = test::SourcePath("tests/data/tir/mfeval/MagicFormula61_Parameters.tir");
const fs::path kUniTire = test::SourcePath("data/tyres/unitire_example.yaml");

using test::RunResult;

class TyreCommandTest : public test::CommandTest {};

// The point evaluation prints and writes exactly the model's forces at the given inputs (in the
// command line's units: degrees, degC).
TEST_F(TyreCommandTest, EvalWritesTheModelsForcesAsJson) {
  const fs::path json = dir() / "eval.json";
  const RunResult r = Run("tyre eval --model mf --params " + kTir.string() +
                          " --fz-N 6752 --slip-angle-deg 5 --speed-mps 16 --json " + json.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = Json(json);
  tyre::TyreOperatingPoint<double> op;
  op.fz = 6752;
  op.slip_angle = 5.0 * 3.14159265358979323846 / 180.0;
  op.speed = 16;
  op.tread_temp = CelsiusToKelvin(25.0);
  const tyre::TyreForces<double> f = tyre::CalcTyreForces(tyre::LoadTyreForceModel(kTir), op);
  for (const auto& [key, value] : std::vector<std::pair<std::string, double>>{
           {"fx_N", f.fx}, {"fy_N", f.fy}, {"mz_Nm", f.mz}, {"mx_Nm", f.mx}, {"my_Nm", f.my}}) {
    ASSERT_TRUE(j.contains(key)) << key;
    EXPECT_NEAR(j[key].get<double>(), value, 1e-6 * std::abs(value) + 1e-9) << key;
  }
  // The oracle's spot value (mfeval, useMode 111): Fy = -6526.979 N here.
  EXPECT_NEAR(j["fy_N"].get<double>(), -6526.979, 0.01);
  EXPECT_TRUE(test::Contains(r.out, "Fy"));
}

// A 2-D sweep: one CSV row per grid point, the last sweep varying fastest, inputs in the
// documented columns; the JSON summary's peak agrees with the CSV.
TEST_F(TyreCommandTest, SweepWritesTheGrid) {
  const fs::path csv = dir() / "sweep.csv", json = dir() / "sweep.json";
  const RunResult r = Run("tyre eval --model unitire --params " + kUniTire.string() +
                          " --sweep fz-N=2000:6000:2000 --sweep slip-angle-deg=-10:10:0.5 --out " +
                          csv.string() + " --json " + json.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const CsvTable t = ReadCsv(csv);
  ASSERT_EQ(t.RowCount(), 3u * 41u);
  const int fz = t.ColumnIndex("fz_N"), alpha = t.ColumnIndex("slip_angle_deg"),
            fy = t.ColumnIndex("fy_N");
  ASSERT_GE(fz, 0);
  ASSERT_GE(alpha, 0);
  ASSERT_GE(fy, 0);
  EXPECT_EQ(t.values[fz][0], 2000.0);
  EXPECT_EQ(t.values[alpha][0], -10.0);
  EXPECT_EQ(t.values[alpha][1], -9.5);
  EXPECT_EQ(t.values[fz][41], 4000.0);
  double peak = 0;
  for (double v : t.values[fy]) peak = std::max(peak, std::abs(v));
  EXPECT_NEAR(Json(json)["peak_abs_fy_N"].get<double>(), peak, 1e-6 * peak);
  EXPECT_EQ(Json(json)["points"].get<int>(), 123);
}

// The UniTire paper's protocol on rig data synthesized from the shipped model with 1% noise:
// fit on 0, 10, 32, 43 degC, predict 18 and 53 degC within 2% of the peak force.
TEST_F(TyreCommandTest, FitPredictsHeldOutTemperatures) {
  const tyre::UniTireParams<double> truth = tyre::LoadUniTireParams(kUniTire).params;
  std::vector<double> temps, loads = {2000, 4000, 6000}, alphas;
  for (double c : {0.0, 10.0, 18.0, 32.0, 43.0, 53.0}) temps.push_back(CelsiusToKelvin(c));
  for (double a = -8.0; a <= 8.0; a += 1.0) alphas.push_back(a * 3.14159265358979323846 / 180);
  const auto samples = ident::SynthesizeRigData(truth, temps, loads, alphas, 0.01, 7);
  const fs::path rig = dir() / "rig.csv";
  ident::WriteRigCsv(rig, {{"source", "synthesized"}}, samples);

  const fs::path out = dir() / "fitted.yaml", json = dir() / "fit.json";
  const RunResult r = Run("tyre fit --model unitire --data " + rig.string() +
                          " --fit-temps-C 0,10,32,43 --predict-temps-C 18,53 --out " +
                          out.string() + " --json " + json.string());
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const nlohmann::json j = Json(json);
  ASSERT_EQ(j["predict"].size(), 2u);
  for (const auto& p : j["predict"]) {
    for (const char* key : {"temp_C", "fy_rms_N", "fy_rms_rel_peak", "mz_rms_Nm"}) {
      ASSERT_TRUE(p.contains(key)) << key;
    }
    EXPECT_LT(p["fy_rms_rel_peak"].get<double>(), 0.02) << p.dump();
  }
  EXPECT_NEAR(j["predict"][0]["temp_C"].get<double>(), 18.0, 0.5);
  EXPECT_NEAR(j["predict"][1]["temp_C"].get<double>(), 53.0, 0.5);
  // The written file loads as a UniTire model, and says which values were fitted and which held.
  EXPECT_EQ(tyre::LoadTyreForceModel(out).kind(), "unitire");
  const std::string text = test::ReadTextFile(out);
  EXPECT_TRUE(test::Contains(text, "nominal_load_N: 4000  # held (not fitted)"));
  EXPECT_TRUE(test::Contains(text, "  # fitted to rig.csv\ncornering_stiffness_load_quad"));
}

// Magic Formula fit from rig data of a known .tir with 1% noise: writes a .tir that loads and
// reproduces the curves, and the JSON carries the coefficients and per-load metrics.
TEST_F(TyreCommandTest, FitMagicFormulaWritesATirFile) {
  const tyre::MagicFormulaParams<double> truth = tyre::LoadMagicFormula(kTir);
  std::vector<double> loads = {0.5 * truth.FNOMIN, truth.FNOMIN, 1.5 * truth.FNOMIN}, alphas,
                      kappas, cambers = {0.0};
  for (double a = -15.0; a <= 15.0; a += 1.0) alphas.push_back(a * 3.14159265358979323846 / 180);
  for (double k = -0.3; k <= 0.3001; k += 0.03) kappas.push_back(k);
  const auto samples = ident::SynthesizeMagicFormulaRigData(truth, loads, cambers, alphas, kappas,
                                                            10.0, CelsiusToKelvin(50), 0.01, 5);
  const fs::path rig = dir() / "rig.csv";
  ident::WriteRigCsv(rig, {{"source", "synthesized"}}, samples);
  const fs::path out = dir() / "fitted.tir", json = dir() / "fit.json";
  const RunResult r = Run("tyre fit --model mf --data " + rig.string() + " --out " + out.string() +
                          " --json " + json.string());
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const nlohmann::json j = Json(json);
  EXPECT_TRUE(j["converged"].get<bool>());
  ASSERT_TRUE(j["coefficients"].contains("PDY1"));
  ASSERT_TRUE(j["coefficients"].contains("PKX1"));
  ASSERT_EQ(j["metrics"].size(), 6u);
  for (const auto& m : j["metrics"]) EXPECT_LT(m["rms_rel_peak"].get<double>(), 0.015) << m;
  ASSERT_TRUE(j.contains("plausibility"));
  EXPECT_TRUE(j["plausibility"]["passed"].get<bool>()) << j["plausibility"];
  EXPECT_EQ(j["plausibility"]["lateral_sign"].get<double>(), -1.0);
  EXPECT_TRUE(j["plausibility"]["failures"].empty());
  EXPECT_TRUE(test::Contains(r.out, "plausibility over Fz"));
  const tyre::TyreForceModel<double> fitted = tyre::LoadTyreForceModel(out, "mf");
  tyre::TyreOperatingPoint<double> op;
  op.fz = truth.FNOMIN;
  op.slip_angle = 0.1;
  op.speed = 10.0;
  const double fy_truth = tyre::CalcMagicFormula(truth, op, {}).fy;
  EXPECT_NEAR(tyre::CalcTyreForces(fitted, op).fy, fy_truth, 0.02 * std::abs(fy_truth));
}

// A base whose stiffness load law passes pi inside 0.1-2 x FNOMIN, with data at one load (so
// PKY2 and PKY4 stay the base's, and the fit cannot mend it): the fit fails the plausibility
// check, exits 3 with the reason, and still writes its .tir and JSON.
TEST_F(TyreCommandTest, FitThatFailsThePlausibilityCheckExits3WithItsFiles) {
  tyre::MagicFormulaParams<double> base = tyre::LoadMagicFormula(kTir);
  const std::vector<double> loads = {base.FNOMIN}, cambers = {0.0};
  std::vector<double> alphas;
  for (double a = -10.0; a <= 10.0; a += 1.0) alphas.push_back(a * 3.14159265358979323846 / 180);
  const auto samples = ident::SynthesizeMagicFormulaRigData(base, loads, cambers, alphas, {}, 10.0,
                                                            CelsiusToKelvin(50), 0.01, 3);
  const fs::path rig = dir() / "rig.csv", base_tir = dir() / "base.tir";
  ident::WriteRigCsv(rig, {{"source", "synthesized"}}, samples);
  base.PKY4 = 5.0;
  base.PKY2 = 0.5;
  tyre::WriteTirFile(base_tir, base);
  const fs::path out = dir() / "fitted.tir", json = dir() / "fit.json";
  const RunResult r =
      Run("tyre fit --model mf --data " + rig.string() + " --base " + base_tir.string() +
          " --out " + out.string() + " --json " + json.string());
  EXPECT_EQ(r.exit_code, 3) << r.out << r.err;
  // The lightest load fails first: there the fitted stiffness already has the wrong sign.
  EXPECT_TRUE(test::Contains(r.err,
                             "hotlap: the fitted tyre is not physically plausible: Fy "
                             "stiffness "));
  ASSERT_TRUE(fs::exists(out));
  const nlohmann::json j = Json(json);
  EXPECT_FALSE(j["plausibility"]["passed"].get<bool>());
  ASSERT_EQ(j["plausibility"]["failures"].size(), 1u);
  EXPECT_TRUE(test::Contains(j["plausibility"]["failures"][0].get<std::string>(),
                             "is not negative as the data's"));
}

// tyre eval reads a .tir with empty values and unknown keys, warning on stderr.
TEST_F(TyreCommandTest, EvalWarnsAboutEmptyValuesAndUnknownKeys) {
  std::string text = test::ReadTextFile(kTir);
  text = test::ReplaceOnce(text, "0.255          $Nominal", "               $Nominal");
  text = test::ReplaceOnce(text, "[MODEL]", "[MODEL]\nMY_TOOL_KEY = 3");
  const fs::path tir = test::WriteTextFile(dir() / "odd.tir", text);
  const RunResult r = Run("tyre eval --model mf --params " + tir.string() + " --fz-N 4000");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(test::Contains(r.err, "hotlap: warning: " + tir.string() +
                                        ": keys without a value, taken as absent (defaults "
                                        "used): WIDTH\n"));
  EXPECT_TRUE(test::Contains(
      r.err, "hotlap: warning: " + tir.string() + ": unknown keys, not used: MY_TOOL_KEY\n"));
}

TEST_F(TyreCommandTest, BadInputFailsCleanlyWithoutOutput) {
  const fs::path json = dir() / "bad.json", csv = dir() / "bad.csv";
  struct Case {
    std::string args;
    std::string message;
  };
  const std::vector<Case> cases = {
      {"tyre eval --model unitire --params " + kTir.string(), "holds a 'mf' tyre model"},
      {"tyre eval --model mf --params " + kTir.string() + " --fz-N -5", "--fz-N must be > 0"},
      {"tyre eval --model mf --params " + kTir.string() + " --sweep slip=0:1:0.1 --out " +
           csv.string(),
       "unknown input 'slip'"},
      {"tyre eval --model mf --params " + kTir.string() + " --sweep slip-ratio=0:1:0.1",
       "--sweep needs --out"},
      {"tyre eval --model mf --params " + (dir() / "missing.tir").string(), "not found"},
      {"tyre fit --model unitire --data " + (dir() / "missing.csv").string() +
           " --fit-temps-C 0 --out " + (dir() / "f.yaml").string(),
       "missing.csv"},
      {"tyre fit --model mf --data " + (dir() / "missing.csv").string() + " --out " +
           (dir() / "f.tir").string(),
       "missing.csv"},
      {"tyre fit --model mf --data x.csv --fit-temps-C 20 --out " + (dir() / "f.tir").string(),
       "no temperature"},
  };
  for (const Case& c : cases) {
    const RunResult r = Run(c.args + " --json " + json.string());
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.err;
    EXPECT_TRUE(test::Contains(r.err, c.message)) << c.args;
    EXPECT_FALSE(fs::exists(json)) << c.args;
    EXPECT_FALSE(fs::exists(csv)) << c.args;
  }
}

}  // namespace
}  // namespace hotlap
