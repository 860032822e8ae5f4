// `hotlap tyre fit`: a UniTire (with its temperature factors) or Magic Formula model fitted to
// rig data (ident/unitire_fit.h, ident/mf_fit.h), written as a parameter file.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.h"
#include "hotlap/common/error.h"
#include "hotlap/common/json_output.h"
#include "hotlap/common/output_folder.h"
#include "hotlap/common/units.h"
#include "hotlap/ident/mf_fit.h"
#include "hotlap/ident/rig_data.h"
#include "hotlap/ident/tyre_fit_json.h"
#include "hotlap/ident/unitire_fit.h"
#include "hotlap/tyre/magic_formula.h"
#include "hotlap/tyre/tir_file.h"
#include "hotlap/tyre/tyre_force_params_io.h"
#include "hotlap/tyre/tyre_params_io.h"

namespace hotlap::app {

namespace {

struct FitArgs {
  std::string model;
  std::string data;
  std::vector<double> fit_temps_C;
  std::vector<double> predict_temps_C;
  std::string out;
  std::string json;
  std::string base;
  double temp_tolerance_K = 1.5;
};

int RunFitUniTire(const FitArgs& a) {
  const std::vector<ident::RigSample> samples = ident::ReadRigCsv(a.data);
  ident::UniTireFitOptions options;
  options.temp_tolerance = a.temp_tolerance_K;
  for (double t : a.fit_temps_C) options.fit_temps.push_back(CelsiusToKelvin(t));
  std::vector<double> predict_temps;
  for (double t : a.predict_temps_C) predict_temps.push_back(CelsiusToKelvin(t));
  ident::RequireFitAndPredictTemps(samples, options, predict_temps, a.data);

  fmt::print("hotlap tyre fit: UniTire to {} ({} samples), fit on {} degC\n", a.data,
             samples.size(), fmt::join(a.fit_temps_C, ", "));
  std::fflush(stdout);
  const ident::UniTireFitResult fit = ident::FitUniTire(samples, options);
  fmt::print("{} after {} iterations; {} free parameters\n",
             fit.converged ? "converged" : "NOT converged", fit.iterations,
             fit.fitted_fields.size());

  tyre::UniTireParamsFile file{std::filesystem::path(a.out).stem().string(), fit.params};
  tyre::WriteUniTireParams(
      a.out, file,
      fmt::format(
          "UniTire parameters fitted by hotlap {} tyre fit to {}\nfit temperatures: {} degC",
          HOTLAP_VERSION, a.data, fmt::join(a.fit_temps_C, ", ")),
      "", [&](std::string_view name) {
        const std::string data = std::filesystem::path(a.data).filename().string();
        const bool fitted = std::find(fit.fitted_fields.begin(), fit.fitted_fields.end(), name) !=
                            fit.fitted_fields.end();
        return fitted ? fmt::format("fitted to {}", data)
                      : fmt::format("held (not fitted): initial guess from {}", data);
      });

  fmt::print("{:>8} {:>8} {:>8} {:>11} {:>11} {:>11} {:>11}\n", "temp C", "role", "samples",
             "Fy rms N", "Fy peak N", "rms/peak", "Mz rms N m");
  for (const ident::UniTireTempMetrics& m : fit.metrics) {
    const bool is_predict = ident::IsPredictTemp(m, a.predict_temps_C, a.temp_tolerance_K);
    const char* role = m.fitted ? "fit" : (is_predict ? "predict" : "other");
    fmt::print("{:>8.1f} {:>8} {:>8} {:>11.2f} {:>11.1f} {:>10.2f}% {:>11.3f}\n",
               ident::MetricsTempC(m), role, m.samples, m.fy_rms_N, m.fy_peak_N,
               100.0 * m.fy_rms_rel_peak, m.mz_rms_Nm);
  }
  fmt::print("wrote {}\n", a.out);
  if (!a.json.empty()) {
    WriteJsonFileAndSay(
        a.json, ident::UniTireFitJson(fit, a.data, a.out, a.predict_temps_C, a.temp_tolerance_K));
  }
  return fit.converged ? 0 : 3;
}

// Prints the plausibility check.
void PrintPlausibility(const ident::MagicFormulaPlausibility& c) {
  fmt::print("plausibility over Fz {:.0f}-{:.0f} N, |alpha| <= {:.3g} deg{}: {}\n", c.fz_min_N,
             c.fz_max_N, c.slip_angle_max_rad * 180.0 / kPi,
             c.slip_ratio_max > 0.0 ? fmt::format(", |kappa| <= {:.3g}", c.slip_ratio_max) : "",
             c.passed ? "passed" : "FAILED");
  for (const std::string& f : c.failures) fmt::print("  failed: {}\n", f);
  for (const std::string& b : c.at_bounds) fmt::print("  at a bound: {}\n", b);
  if (c.slip_angle_max_rad > 0.0 && c.passed) {
    fmt::print("  peak |Fy|/Fz {:.3f}-{:.3f}\n", c.peak_mu_y_min, c.peak_mu_y_max);
  }
}

int RunFitMagicFormula(const FitArgs& a) {
  if (!a.fit_temps_C.empty() || !a.predict_temps_C.empty()) {
    throw InputError(
        "--fit-temps-C and --predict-temps-C are for --model unitire; the Magic Formula has no "
        "temperature");
  }
  const std::vector<ident::RigSample> samples = ident::ReadRigCsv(a.data);
  ident::MagicFormulaFitOptions options;
  if (!a.base.empty()) {
    options.base = tyre::LoadMagicFormula(a.base);
    PrintTirWarnings(a.base);
  }
  fmt::print("hotlap tyre fit: Magic Formula pure-slip coefficients to {} ({} samples){}\n", a.data,
             samples.size(), a.base.empty() ? "" : ", starting from " + a.base);
  std::fflush(stdout);
  const ident::MagicFormulaFitResult fit = ident::FitMagicFormula(samples, options);
  for (const std::string& w : fit.warnings)
    std::fprintf(stderr, "hotlap: warning: %s\n", w.c_str());
  fmt::print(
      "{} after {} iterations; {} free coefficients ({} side-slip, {} longitudinal samples)\n",
      fit.converged ? "converged" : "NOT converged", fit.iterations, fit.fitted_coefficients.size(),
      fit.lateral_samples, fit.longitudinal_samples);

  const auto value_of = [](const tyre::MagicFormulaParams<double>& p, const std::string& name) {
    const tyre::MagicFormulaParamInfo* info = tyre::FindMagicFormulaParam(name);
    return info ? p.*info->field : std::nan("");
  };
  fmt::print("{:>8} {:>14} {:>14}\n", "coef", "start", "fitted");
  for (const std::string& name : fit.fitted_coefficients) {
    const double start = value_of(fit.initial_guess, name);
    const double value = value_of(fit.params, name);
    fmt::print("{:>8} {:>14.6g} {:>14.6g}\n", name, start, value);
  }
  fmt::print("{:>8} {:>10} {:>8} {:>10} {:>10} {:>9}\n", "channel", "Fz N", "samples", "rms N",
             "peak N", "rms/peak");
  for (const ident::MagicFormulaFitMetrics& m : fit.metrics) {
    fmt::print("{:>8} {:>10.0f} {:>8} {:>10.2f} {:>10.1f} {:>8.2f}%\n", m.channel, m.fz_N,
               m.samples, m.rms_N, m.peak_N, 100.0 * m.rms_rel_peak);
  }
  PrintPlausibility(fit.plausibility);
  tyre::WriteTirFile(
      a.out, fit.params,
      fmt::format("pure-slip coefficients fitted by hotlap {} tyre fit to {}\nfree: {}",
                  HOTLAP_VERSION, std::filesystem::path(a.data).filename().string(),
                  fmt::join(fit.fitted_coefficients, " ")));
  fmt::print("wrote {}\n", a.out);
  if (!a.json.empty()) WriteJsonFileAndSay(a.json, ident::MagicFormulaFitJson(fit, a.data, a.out));
  if (!fit.plausibility.passed) {
    std::fprintf(stderr, "hotlap: the fitted tyre is not physically plausible: %s\n",
                 fmt::format("{}", fmt::join(fit.plausibility.failures, "; ")).c_str());
    return 3;
  }
  return fit.converged ? 0 : 3;
}

int RunFit(const FitArgs& a) {
  CheckOutputFolder(a.out, "--out");
  if (!a.json.empty()) CheckOutputFolder(a.json, "--json");
  if (a.model == "unitire") {
    if (a.fit_temps_C.empty()) throw InputError("--fit-temps-C is required for --model unitire");
    if (!a.base.empty()) throw InputError("--base is only used with --model mf");
    return RunFitUniTire(a);
  }
  return RunFitMagicFormula(a);
}

}  // namespace

CommandRunner RegisterTyreFitSubcommand(CLI::App* tyre) {
  auto fit = std::make_shared<FitArgs>();
  CLI::App* f = tyre->add_subcommand("fit", "Fit a tyre model to rig data (CSV)");
  f->add_option("--model", fit->model, "unitire or mf")
      ->required()
      ->check(CLI::IsMember({"unitire", "mf"}));
  f->add_option("--data", fit->data, "Rig CSV (docs/tyre-forces.md)")->required();
  f->add_option("--fit-temps-C", fit->fit_temps_C, "Temperatures to fit on (unitire)")
      ->delimiter(',');
  f->add_option("--predict-temps-C", fit->predict_temps_C, "Held-out temperatures (unitire)")
      ->delimiter(',');
  f->add_option("--temp-tolerance-K", fit->temp_tolerance_K,
                "Samples this close to a temperature belong to it")
      ->capture_default_str()
      ->check(kPositive);
  f->add_option("--out", fit->out, "Fitted parameter file (.yaml for unitire, .tir for mf)")
      ->required();
  f->add_option("--base", fit->base,
                "mf: .tir to start from and to keep the coefficients the fit does not free "
                "(default: generic coefficients sized to the data)");
  f->add_option("--json", fit->json, "Write the summary as JSON (docs/json-output.md)");

  return [fit] { return RunFit(*fit); };
}

}  // namespace hotlap::app
