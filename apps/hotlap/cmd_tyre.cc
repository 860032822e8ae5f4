// `hotlap tyre`: evaluate tyre force models at a point or over a sweep, and fit them to rig data.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.h"
#include "hotlap/common/csv.h"
#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/ident/mf_fit.h"
#include "hotlap/ident/rig_data.h"
#include "hotlap/ident/unitire_fit.h"
#include "hotlap/tyre/tir_file.h"
#include "hotlap/tyre/tyre_force_model.h"
#include "hotlap/tyre/tyre_force_params_io.h"
#include "hotlap/tyre/tyre_params_io.h"
#include "output.h"

namespace hotlap::app {

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

// ---------------------------------------------------------------------------------------------
// tyre eval

// An input of the operating point as the command line names it, with its conversion to SI.
struct EvalVariable {
  const char* name;    // option and CSV column stem, e.g. "slip-angle-deg"
  const char* column;  // CSV column, e.g. "slip_angle_deg"
  double tyre::TyreOperatingPoint<double>::*field;
  double scale;  // SI = value * scale + shift
  double shift;
};

const std::vector<EvalVariable>& EvalVariables() {
  using Op = tyre::TyreOperatingPoint<double>;
  static const std::vector<EvalVariable> v = {
      {"fz-N", "fz_N", &Op::fz, 1.0, 0.0},
      {"slip-angle-deg", "slip_angle_deg", &Op::slip_angle, kDeg, 0.0},
      {"slip-ratio", "slip_ratio", &Op::slip_ratio, 1.0, 0.0},
      {"camber-deg", "camber_deg", &Op::camber, kDeg, 0.0},
      {"speed-mps", "speed_mps", &Op::speed, 1.0, 0.0},
      {"pressure-kPa", "pressure_kPa", &Op::pressure, 1e3, 0.0},
      {"tread-temp-C", "tread_temp_C", &Op::tread_temp, 1.0, kZeroCelsius},
  };
  return v;
}

struct EvalArgs {
  std::string model;
  std::string params;
  // Command-line values in the option's units (see EvalVariables); order as EvalVariables.
  std::vector<double> values = {4000.0, 0.0, 0.0, 0.0, 20.0, 0.0, 25.0};
  std::vector<std::string> sweeps;
  std::string out;
  std::string json;
  std::string compound;
  double wear_mm = 0.0;
};

// "NAME=FROM:TO:STEP" -> the variable's index and its values.
struct Sweep {
  size_t variable = 0;
  std::vector<double> values;
};

Sweep ParseSweep(const std::string& text) {
  const auto fail = [&](const std::string& why) -> Sweep {
    std::vector<std::string> names;
    for (const EvalVariable& v : EvalVariables()) names.push_back(v.name);
    throw InputError(fmt::format("--sweep '{}': {}; write NAME=FROM:TO:STEP with NAME one of {}",
                                 text, why, fmt::join(names, ", ")));
  };
  const size_t eq = text.find('=');
  if (eq == std::string::npos) return fail("no '='");
  const std::string name = text.substr(0, eq);
  const auto& vars = EvalVariables();
  const auto it =
      std::find_if(vars.begin(), vars.end(), [&](const EvalVariable& v) { return name == v.name; });
  if (it == vars.end()) return fail("unknown input '" + name + "'");
  double from = 0, to = 0, step = 0;
  char tail = 0;
  if (std::sscanf(text.c_str() + eq + 1, "%lf:%lf:%lf%c", &from, &to, &step, &tail) != 3) {
    return fail("the range is not FROM:TO:STEP");
  }
  if (!(std::isfinite(from) && std::isfinite(to) && step > 0.0)) {
    return fail("FROM and TO must be finite and STEP > 0");
  }
  const double count = std::floor((to - from) / step + 1e-9) + 1.0;
  if (!(count >= 1.0)) return fail("TO is below FROM");
  if (count > 1e6) return fail("more than a million points");
  Sweep s;
  s.variable = static_cast<size_t>(it - vars.begin());
  for (int i = 0; i < static_cast<int>(count); ++i) s.values.push_back(from + i * step);
  return s;
}

tyre::TyreOperatingPoint<double> PointFrom(const std::vector<double>& values) {
  tyre::TyreOperatingPoint<double> op;
  const auto& vars = EvalVariables();
  for (size_t i = 0; i < vars.size(); ++i) {
    op.*vars[i].field = values[i] * vars[i].scale + vars[i].shift;
  }
  return op;
}

nlohmann::json ForcesJson(const tyre::TyreForces<double>& f) {
  return {{"fx_N", RoundSignificant(f.fx)},
          {"fy_N", RoundSignificant(f.fy)},
          {"mz_Nm", RoundSignificant(f.mz)},
          {"mx_Nm", RoundSignificant(f.mx)},
          {"my_Nm", RoundSignificant(f.my)}};
}

bool IsFinite(const tyre::TyreForces<double>& f) {
  for (double x : {f.fx, f.fy, f.mz, f.mx, f.my}) {
    if (!std::isfinite(x)) return false;
  }
  return true;
}

void CheckFinite(const tyre::TyreForces<double>& f, const std::vector<double>& values) {
  if (!IsFinite(f)) {
    throw NumericalError(fmt::format("the tyre model gave a non-finite force at inputs {}",
                                     fmt::join(values, ", ")));
  }
}

int RunEval(const EvalArgs& a) {
  if (!a.sweeps.empty() && a.out.empty()) throw InputError("--sweep needs --out CSV");
  if (a.sweeps.empty() && !a.out.empty()) throw InputError("--out is only used with --sweep");
  if (a.sweeps.size() > 3) throw InputError("at most three --sweep inputs (a 3-D grid)");
  if (!a.out.empty()) CheckOutputFolder(a.out, "--out");
  if (!a.json.empty()) CheckOutputFolder(a.json, "--json");
  if (!(a.values[0] > 0.0))
    throw InputError(fmt::format("--fz-N must be > 0, got {:g}", a.values[0]));

  const tyre::TyreForceModel<double> model = tyre::LoadTyreForceModel(a.params, a.model);
  std::optional<tyre::TyreCompound> compound;
  if (!a.compound.empty()) compound = tyre::LoadTyreCompound(a.compound);
  const auto evaluate = [&](const std::vector<double>& values) {
    const tyre::TyreOperatingPoint<double> op = PointFrom(values);
    const tyre::TyreForces<double> f =
        compound ? tyre::CalcTyreForcesWithGrip(model, *compound, op, a.wear_mm)
                 : tyre::CalcTyreForces(model, op);
    CheckFinite(f, values);
    return f;
  };
  const double grip =
      compound ? compound->GripFactor(PointFrom(a.values).tread_temp, a.wear_mm) : 1.0;

  nlohmann::json summary = {{"command", "tyre eval"},
                            {"model", model.kind()},
                            {"params", a.params},
                            {"grip_factor", RoundSignificant(grip)}};
  nlohmann::json inputs;
  for (size_t i = 0; i < EvalVariables().size(); ++i) {
    inputs[EvalVariables()[i].column] = a.values[i];
  }
  summary["inputs"] = inputs;

  if (a.sweeps.empty()) {
    const tyre::TyreForces<double> f = evaluate(a.values);
    fmt::print("hotlap tyre eval: {} model '{}' ({})\n", model.kind(), model.name, a.params);
    for (size_t i = 0; i < EvalVariables().size(); ++i) {
      fmt::print("  {:<16} {:g}\n", EvalVariables()[i].column, a.values[i]);
    }
    if (compound) fmt::print("  grip factor g(T) h(wear) = {:.4f}\n", grip);
    fmt::print(
        "  Fx {:10.2f} N    Fy {:10.2f} N    Mz {:9.2f} N m    Mx {:9.2f} N m    My {:9.2f} "
        "N m\n",
        f.fx, f.fy, f.mz, f.mx, f.my);
    summary.update(ForcesJson(f));
  } else {
    std::vector<Sweep> sweeps;
    for (const std::string& s : a.sweeps) {
      sweeps.push_back(ParseSweep(s));
      for (size_t j = 0; j + 1 < sweeps.size(); ++j) {
        if (sweeps[j].variable == sweeps.back().variable) {
          throw InputError(fmt::format("--sweep '{}' repeats an input", s));
        }
      }
    }
    size_t total = 1;
    for (const Sweep& s : sweeps) total *= s.values.size();
    if (total > 2'000'000)
      throw InputError(fmt::format("the sweep has {} points (max 2e6)", total));
    std::vector<std::string> names;
    for (const EvalVariable& v : EvalVariables()) names.push_back(v.column);
    for (const char* n : {"fx_N", "fy_N", "mz_Nm", "mx_Nm", "my_Nm"}) names.push_back(n);
    std::vector<std::vector<double>> columns(names.size());
    double peak_fx = 0, peak_fy = 0, peak_mz = 0;
    std::vector<double> values = a.values;
    const size_t k = values.size();
    // The grid goes through the batch API in blocks (a Magic Formula evaluates several points
    // per call, with the same results as one by one).
    constexpr size_t kBlock = 1024;
    std::vector<tyre::TyreOperatingPoint<double>> ops;
    std::vector<tyre::TyreForces<double>> forces;
    bool load_error = false;
    for (size_t first = 0; first < total && !load_error; first += kBlock) {
      ops.clear();
      for (size_t n = first; n < std::min(total, first + kBlock); ++n) {
        // The last sweep varies fastest.
        size_t rest = n;
        for (size_t j = sweeps.size(); j-- > 0;) {
          values[sweeps[j].variable] = sweeps[j].values[rest % sweeps[j].values.size()];
          rest /= sweeps[j].values.size();
        }
        // (Reported after the points before it, as when evaluating one by one.)
        if (!(values[0] > 0.0)) {
          load_error = true;
          break;
        }
        for (size_t i = 0; i < k; ++i) columns[i].push_back(values[i]);
        ops.push_back(PointFrom(values));
      }
      forces.resize(ops.size());
      tyre::CalcTyreForcesBatch(model, ops, forces);
      for (size_t j = 0; j < ops.size(); ++j) {
        tyre::TyreForces<double> f = forces[j];
        if (compound) {
          f = tyre::ApplyGripFactor(f, compound->GripFactor(ops[j].tread_temp, a.wear_mm));
        }
        if (!IsFinite(f)) {
          std::vector<double> point(k);
          for (size_t i = 0; i < k; ++i) point[i] = columns[i][first + j];
          CheckFinite(f, point);
        }
        columns[k].push_back(f.fx);
        columns[k + 1].push_back(f.fy);
        columns[k + 2].push_back(f.mz);
        columns[k + 3].push_back(f.mx);
        columns[k + 4].push_back(f.my);
        peak_fx = std::max(peak_fx, std::abs(f.fx));
        peak_fy = std::max(peak_fy, std::abs(f.fy));
        peak_mz = std::max(peak_mz, std::abs(f.mz));
      }
    }
    if (load_error) throw InputError("the sweep reaches a load <= 0 N");
    WriteCsv(a.out,
             {{"source", fmt::format("hotlap {} tyre eval", HOTLAP_VERSION)},
              {"model", std::string(model.kind())},
              {"params", a.params}},
             names, columns);
    fmt::print(
        "hotlap tyre eval: {} model '{}': {} points, peak |Fx| {:.1f} N, |Fy| {:.1f} N, "
        "|Mz| {:.1f} N m\nwrote {}\n",
        model.kind(), model.name, total, peak_fx, peak_fy, peak_mz, a.out);
    summary["out"] = a.out;
    summary["points"] = total;
    summary["peak_abs_fx_N"] = RoundSignificant(peak_fx);
    summary["peak_abs_fy_N"] = RoundSignificant(peak_fy);
    summary["peak_abs_mz_Nm"] = RoundSignificant(peak_mz);
  }
  if (!a.json.empty()) {
    WriteJsonFile(a.json, summary);
    fmt::print("wrote {}\n", a.json);
  }
  return 0;
}

// ---------------------------------------------------------------------------------------------
// tyre fit

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

nlohmann::json MetricsJson(const ident::UniTireTempMetrics& m) {
  // Round to 1e-9 degC first so that 0 degC is written as 0, not -1.7e-13.
  const double temp_C = std::round(KelvinToCelsius(m.temp) * 1e9) / 1e9;
  nlohmann::json j = {{"temp_C", RoundSignificant(temp_C + 0.0, 6)},
                      {"samples", m.samples},
                      {"fy_rms_N", RoundSignificant(m.fy_rms_N)},
                      {"fy_peak_N", RoundSignificant(m.fy_peak_N)},
                      {"fy_rms_rel_peak", RoundSignificant(m.fy_rms_rel_peak)},
                      {"mz_rms_Nm", RoundSignificant(m.mz_rms_Nm)}};
  if (m.fx_rms_N) j["fx_rms_N"] = RoundSignificant(*m.fx_rms_N);
  return j;
}

int RunFitUniTire(const FitArgs& a) {
  const std::vector<ident::RigSample> samples = ident::ReadRigCsv(a.data);
  ident::UniTireFitOptions options;
  options.temp_tolerance = a.temp_tolerance_K;
  for (double t : a.fit_temps_C) options.fit_temps.push_back(CelsiusToKelvin(t));
  // Every requested temperature must be in the data.
  const auto present = [&](double temp_K) {
    return std::any_of(samples.begin(), samples.end(), [&](const ident::RigSample& s) {
      return std::abs(s.tread_temp - temp_K) <= a.temp_tolerance_K;
    });
  };
  for (const auto* list : {&a.fit_temps_C, &a.predict_temps_C}) {
    for (double t : *list) {
      if (!present(CelsiusToKelvin(t))) {
        throw InputError(fmt::format("{}: no rig sample within {:g} K of {:g} degC", a.data,
                                     a.temp_tolerance_K, t));
      }
    }
  }
  for (double p : a.predict_temps_C) {
    for (double f : a.fit_temps_C) {
      if (std::abs(p - f) <= a.temp_tolerance_K) {
        throw InputError(fmt::format("{:g} degC is both a fit and a predict temperature", p));
      }
    }
  }

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

  nlohmann::json fitted = nlohmann::json::array();
  nlohmann::json predicted = nlohmann::json::array();
  fmt::print("{:>8} {:>8} {:>8} {:>11} {:>11} {:>11} {:>11}\n", "temp C", "role", "samples",
             "Fy rms N", "Fy peak N", "rms/peak", "Mz rms N m");
  for (const ident::UniTireTempMetrics& m : fit.metrics) {
    const double temp_C = std::round(KelvinToCelsius(m.temp) * 1e9) / 1e9 + 0.0;
    const bool is_predict =
        std::any_of(a.predict_temps_C.begin(), a.predict_temps_C.end(),
                    [&](double t) { return std::abs(t - temp_C) <= a.temp_tolerance_K; });
    const char* role = m.fitted ? "fit" : (is_predict ? "predict" : "other");
    fmt::print("{:>8.1f} {:>8} {:>8} {:>11.2f} {:>11.1f} {:>10.2f}% {:>11.3f}\n", temp_C, role,
               m.samples, m.fy_rms_N, m.fy_peak_N, 100.0 * m.fy_rms_rel_peak, m.mz_rms_Nm);
    if (m.fitted) fitted.push_back(MetricsJson(m));
    if (is_predict) predicted.push_back(MetricsJson(m));
  }
  fmt::print("wrote {}\n", a.out);
  if (!a.json.empty()) {
    nlohmann::json params;
    for (size_t i = 0; i < fit.fitted_fields.size(); ++i) params.push_back(fit.fitted_fields[i]);
    WriteJsonFile(a.json, {{"command", "tyre fit"},
                           {"model", "unitire"},
                           {"data", a.data},
                           {"out", a.out},
                           {"converged", fit.converged},
                           {"iterations", fit.iterations},
                           {"fitted_parameters", params},
                           {"fit", fitted},
                           {"predict", predicted}});
    fmt::print("wrote {}\n", a.json);
  }
  return fit.converged ? 0 : 3;
}

int RunFitMagicFormula(const FitArgs& a) {
  if (!a.fit_temps_C.empty() || !a.predict_temps_C.empty()) {
    throw InputError(
        "--fit-temps-C and --predict-temps-C are for --model unitire; the Magic Formula has no "
        "temperature");
  }
  const std::vector<ident::RigSample> samples = ident::ReadRigCsv(a.data);
  ident::MagicFormulaFitOptions options;
  if (!a.base.empty()) options.base = tyre::LoadMagicFormula(a.base);
  fmt::print("hotlap tyre fit: Magic Formula pure-slip coefficients to {} ({} samples){}\n", a.data,
             samples.size(), a.base.empty() ? "" : ", starting from " + a.base);
  std::fflush(stdout);
  const ident::MagicFormulaFitResult fit = ident::FitMagicFormula(samples, options);
  for (const std::string& w : fit.warnings) fmt::print("warning: {}\n", w);
  fmt::print(
      "{} after {} iterations; {} free coefficients ({} side-slip, {} longitudinal samples)\n",
      fit.converged ? "converged" : "NOT converged", fit.iterations, fit.fitted_coefficients.size(),
      fit.lateral_samples, fit.longitudinal_samples);

  const auto& table = tyre::MagicFormulaParamTable();
  const auto value_of = [&](const tyre::MagicFormulaParams<double>& p, const std::string& name) {
    for (const tyre::MagicFormulaParamInfo& info : table) {
      if (info.name == name) return p.*info.field;
    }
    return std::nan("");
  };
  nlohmann::json coefficients = nlohmann::json::object();
  fmt::print("{:>8} {:>14} {:>14}\n", "coef", "start", "fitted");
  for (const std::string& name : fit.fitted_coefficients) {
    const double start = value_of(fit.initial_guess, name);
    const double value = value_of(fit.params, name);
    fmt::print("{:>8} {:>14.6g} {:>14.6g}\n", name, start, value);
    coefficients[name] = RoundSignificant(value);
  }
  nlohmann::json metrics = nlohmann::json::array();
  fmt::print("{:>8} {:>10} {:>8} {:>10} {:>10} {:>9}\n", "channel", "Fz N", "samples", "rms N",
             "peak N", "rms/peak");
  for (const ident::MagicFormulaFitMetrics& m : fit.metrics) {
    fmt::print("{:>8} {:>10.0f} {:>8} {:>10.2f} {:>10.1f} {:>8.2f}%\n", m.channel, m.fz_N,
               m.samples, m.rms_N, m.peak_N, 100.0 * m.rms_rel_peak);
    metrics.push_back({{"channel", m.channel},
                       {"fz_N", RoundSignificant(m.fz_N)},
                       {"samples", m.samples},
                       {"rms_N", RoundSignificant(m.rms_N)},
                       {"peak_N", RoundSignificant(m.peak_N)},
                       {"rms_rel_peak", RoundSignificant(m.rms_rel_peak)}});
  }
  tyre::WriteTirFile(
      a.out, fit.params,
      fmt::format("pure-slip coefficients fitted by hotlap {} tyre fit to {}\nfree: {}",
                  HOTLAP_VERSION, std::filesystem::path(a.data).filename().string(),
                  fmt::join(fit.fitted_coefficients, " ")));
  fmt::print("wrote {}\n", a.out);
  if (!a.json.empty()) {
    WriteJsonFile(a.json, {{"command", "tyre fit"},
                           {"model", "mf"},
                           {"data", a.data},
                           {"out", a.out},
                           {"converged", fit.converged},
                           {"iterations", fit.iterations},
                           {"coefficients", coefficients},
                           {"metrics", metrics},
                           {"warnings", fit.warnings}});
    fmt::print("wrote {}\n", a.json);
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

CommandRunner RegisterTyreCommand(CLI::App& app) {
  CLI::App* tyre = app.add_subcommand("tyre", "Tyre force models: evaluate, sweep and fit");
  tyre->require_subcommand(1);

  auto eval = std::make_shared<EvalArgs>();
  CLI::App* e = tyre->add_subcommand(
      "eval", "Forces and moments of a tyre model at one point, or over a sweep (CSV)");
  e->add_option("--model", eval->model, "mf (a .tir file), brush or unitire (YAML)")
      ->required()
      ->check(CLI::IsMember({"mf", "brush", "unitire"}));
  e->add_option("--params", eval->params, "The model's parameter file")->required();
  for (size_t i = 0; i < EvalVariables().size(); ++i) {
    e->add_option(std::string("--") + EvalVariables()[i].name, eval->values[i])
        ->capture_default_str();
  }
  e->add_option("--sweep", eval->sweeps,
                "NAME=FROM:TO:STEP, up to three (a grid; the last varies fastest), e.g. "
                "slip-angle-deg=-15:15:0.5");
  e->add_option("--out", eval->out, "Sweep output CSV");
  e->add_option("--compound", eval->compound,
                "Compound YAML: scale Fx, Fy, Mz by its g(T_tread) h(wear)");
  e->add_option("--wear-mm", eval->wear_mm, "Tread depth lost, for --compound")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  e->add_option("--json", eval->json, "Write the summary as JSON (docs/json-output.md)");

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
      ->check(CLI::PositiveNumber);
  f->add_option("--out", fit->out, "Fitted parameter file (.yaml for unitire, .tir for mf)")
      ->required();
  f->add_option("--base", fit->base,
                "mf: .tir to start from and to keep the coefficients the fit does not free "
                "(default: generic coefficients sized to the data)");
  f->add_option("--json", fit->json, "Write the summary as JSON (docs/json-output.md)");

  return [e, f, eval, fit] {
    if (e->parsed()) return RunEval(*eval);
    return RunFit(*fit);
  };
}

}  // namespace hotlap::app
