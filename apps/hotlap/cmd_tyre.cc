// `hotlap tyre`: evaluate tyre force models at a point or over a sweep (tyre/tyre_grid.h); `tyre
// fit` is in cmd_tyre_fit.cc.

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
#include "hotlap/common/data_path.h"
#include "hotlap/common/error.h"
#include "hotlap/common/json_output.h"
#include "hotlap/common/output_folder.h"
#include "hotlap/common/units.h"
#include "hotlap/tyre/tir_file.h"
#include "hotlap/tyre/tyre_eval_json.h"
#include "hotlap/tyre/tyre_force_model.h"
#include "hotlap/tyre/tyre_force_params_io.h"
#include "hotlap/tyre/tyre_grid.h"
#include "hotlap/tyre/tyre_params_io.h"

namespace hotlap::app {

void PrintTirWarnings(const std::string& path) {
  for (const std::string& w : tyre::ReadTirFile(path).warnings) {
    std::fprintf(stderr, "hotlap: warning: %s\n", w.c_str());
  }
}

namespace {

// ---------------------------------------------------------------------------------------------
// tyre eval (tyre/tyre_grid.h)

struct EvalArgs {
  std::string model;
  std::string params;
  // Command-line values in the inputs' units, ordered as tyre::OperatingPointInputs().
  std::vector<double> values = tyre::DefaultOperatingPointValues();
  std::vector<std::string> sweeps;
  std::string out;
  std::string json;
  std::string compound;
  double wear_mm = 0.0;
};

// The grid's axes from the --sweep texts, the library's messages named as the options.
std::vector<tyre::GridAxis> ParseSweeps(const std::vector<std::string>& texts) {
  std::vector<tyre::GridAxis> axes;
  for (const std::string& s : texts) {
    try {
      axes.push_back(tyre::ParseGridAxis(s));
    } catch (const InputError& e) {
      throw InputError(std::string("--") + e.what());
    }
    for (size_t j = 0; j + 1 < axes.size(); ++j) {
      if (axes[j].input == axes.back().input) {
        throw InputError(fmt::format("--sweep '{}' repeats an input", s));
      }
    }
  }
  return axes;
}

int RunEval(const EvalArgs& a) {
  if (!a.sweeps.empty() && a.out.empty()) throw InputError("--sweep needs --out CSV");
  if (a.sweeps.empty() && !a.out.empty()) throw InputError("--out is only used with --sweep");
  if (a.sweeps.size() > 3) throw InputError("at most three --sweep inputs (a 3-D grid)");
  if (!a.out.empty()) CheckOutputFolder(a.out, "--out");
  if (!a.json.empty()) CheckOutputFolder(a.json, "--json");
  if (!(a.values[0] > 0.0))
    throw InputError(fmt::format("--fz-N must be > 0, got {:g}", a.values[0]));

  const tyre::TyreForceModel<double> model =
      tyre::LoadTyreForceModel(ResolveTyreFile(a.params), a.model);
  if (model.kind() == "mf") PrintTirWarnings(model.path.string());
  std::optional<tyre::TyreCompound> compound;
  if (!a.compound.empty()) compound = tyre::LoadTyreCompound(a.compound);
  const tyre::TyreCompound* grip_of = compound ? &*compound : nullptr;
  const auto& inputs = tyre::OperatingPointInputs();
  const double grip =
      compound ? compound->GripFactor(tyre::OperatingPointFrom(a.values).tread_temp, a.wear_mm)
               : 1.0;

  nlohmann::json summary = tyre::TyreEvalJson(model.kind(), a.params, grip, a.values);

  if (a.sweeps.empty()) {
    const tyre::TyreForces<double> f = tyre::EvaluateTyrePoint(model, grip_of, a.wear_mm, a.values);
    fmt::print("hotlap tyre eval: {} model '{}' ({})\n", model.kind(), model.name, a.params);
    for (size_t i = 0; i < inputs.size(); ++i) {
      fmt::print("  {:<16} {:g}\n", inputs[i].column, a.values[i]);
    }
    if (compound) fmt::print("  grip factor g(T) h(wear) = {:.4f}\n", grip);
    fmt::print(
        "  Fx {:10.2f} N    Fy {:10.2f} N    Mz {:9.2f} N m    Mx {:9.2f} N m    My {:9.2f} "
        "N m\n",
        f.fx, f.fy, f.mz, f.mx, f.my);
    summary.update(tyre::TyreForcesJson(f));
  } else {
    const tyre::TyreGrid g =
        tyre::EvaluateTyreGrid(model, grip_of, a.wear_mm, a.values, ParseSweeps(a.sweeps));
    WriteCsv(a.out,
             {{"source", fmt::format("hotlap {} tyre eval", HOTLAP_VERSION)},
              {"model", std::string(model.kind())},
              {"params", a.params}},
             g.names, g.columns);
    fmt::print(
        "hotlap tyre eval: {} model '{}': {} points, peak |Fx| {:.1f} N, |Fy| {:.1f} N, "
        "|Mz| {:.1f} N m\nwrote {}\n",
        model.kind(), model.name, g.points, g.peak_abs_fx, g.peak_abs_fy, g.peak_abs_mz, a.out);
    tyre::AddTyreGridJson(summary, g, a.out);
  }
  if (!a.json.empty()) WriteJsonFileAndSay(a.json, summary);
  return 0;
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
  e->add_option("--params", eval->params,
                "The model's parameter file, or a built-in tyre (e.g. gen7/left, brush_example)")
      ->required();
  for (size_t i = 0; i < tyre::OperatingPointInputs().size(); ++i) {
    e->add_option(std::string("--") + tyre::OperatingPointInputs()[i].name, eval->values[i])
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
      ->check(kNonNegative);
  e->add_option("--json", eval->json, "Write the summary as JSON (docs/json-output.md)");

  const CommandRunner run_fit = RegisterTyreFitSubcommand(tyre);
  return [e, eval, run_fit] {
    if (e->parsed()) return RunEval(*eval);
    return run_fit();
  };
}

}  // namespace hotlap::app
