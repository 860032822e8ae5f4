#pragma once
/// @file
/// `hotlap fe inflate|footprint|roll|abs` as one library call (docs/fe-tyre.md): the step chain
/// (each step runs the ones before it), the outputs of each step (history CSVs, the footprint
/// map, deformed shapes as .vtu, abs_report.html), the lumped `hotlap abs` run of the same event
/// beside the FE one, the checkpoints and the restart of the abs step, the ensemble of abs stops
/// (fe_abs_ensemble.h), and the JSON summary. The command line parses its options, calls RunFe
/// and writes the summary.
///
///   runs::FeRunOptions o;  o.step = "abs";  o.config = "data/fe/paper_235_75r15.yaml";
///   o.out = "out/fe";  o.ensemble = 16;
///   const runs::FeRunResult r = runs::RunFe(o);   // r.summary: the --json document

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hotlap/abs/fe_perturbation.h"
#include "hotlap/fe/element_kernel.h"

namespace hotlap::runs {

struct FeRunOptions {
  std::string step = "abs";  ///< inflate | footprint | roll | abs
  std::filesystem::path config;
  std::filesystem::path out;  ///< checked first, created once the input is accepted
  double duration_s = 0.0;    ///< of the last step (roll or abs); 0: the file's
  int threads = 0;            ///< solver threads (0: OpenMP's default); ensemble: members at once
  fe::ElementKernel kernel = fe::BestElementKernel();
  double checkpoint_every_s = 0.0;  ///< abs: 0 for no checkpoints
  std::filesystem::path restart;    ///< abs: a checkpoint to continue from (empty: none)
  double step_scale = 1.0;          ///< the time step as a fraction of the stable one's, (0, 1]
  int ensemble = 0;                 ///< abs: members of an ensemble (0: one plain stop)
  sim::FePerturbation perturbation = sim::FePerturbation::kSpin;  ///< of the ensemble's members
  /// abs --ensemble: the first member's index in the perturbation's sequence (a shard of a larger
  /// ensemble, sim::FeAbsEnsembleOptions::first_member; sum-order and round-off only).
  int first_member = 0;
  /// abs: numbers of the FE file's ABS file (`abs.config_file`) replaced, "KEY=VALUE" each
  /// (sim::ParseAbsOverrides; e.g. "controller.reapply_fraction=0.85"): the FE stop's controller
  /// and the lumped run of the same ABS file take them, the lumped own tuning does not.
  std::vector<std::string> abs_set;
  /// Lines for the user as the run goes: `note` progress and warnings (the command's stderr),
  /// `say` each step's summary (its stdout). Either may be empty.
  std::function<void(const std::string&)> note, say;
};

struct FeRunResult {
  nlohmann::json summary;  ///< docs/fe-tyre.md, "JSON keys"
};

/// Runs the steps up to options.step. Throws InputError on bad input (before anything is
/// written), NumericalError if a step fails.
FeRunResult RunFe(const FeRunOptions& options);

}  // namespace hotlap::runs
