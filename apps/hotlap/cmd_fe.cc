// `hotlap fe inflate|footprint|roll|abs`: the finite-element tyre's steps (docs/fe-tyre.md).
// Each step runs the ones before it (footprint inflates first, and so on). Outputs: a history CSV
// per step, the footprint pressure map (CSV and SVG), deformed shapes as .vtu, a JSON summary.
// The abs step (sim::FeAbsStop) can write checkpoints (--checkpoint-every-s) and continue from
// one (--restart), or run as an ensemble (--ensemble N --perturb KIND). This file parses, calls
// the library (runs::RunFe) and writes the JSON.

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "commands.h"
#include "hotlap/common/json_output.h"
#include "hotlap/common/output_folder.h"
#include "hotlap/fe/element_kernel.h"
#include "hotlap/runs/fe_run.h"

namespace hotlap::app {

namespace {

struct FeArgs {
  std::string step;
  std::string config;
  std::string out;
  std::string json;
  double duration_s = 0.0;           // 0: the file's
  int threads = 0;                   // 0: OpenMP's default (all cores)
  std::string kernel;                // empty: HOTLAP_FE_KERNEL, else auto
  double checkpoint_every_s = 0.0;   // 0: no checkpoints
  std::string restart;               // checkpoint to continue from
  double step_scale = 1.0;           // the time step is this times the stable one's (0, 1]
  int ensemble = 0;                  // abs: members of an ensemble (0: one stop)
  std::string perturb = "spin";      // the ensemble's perturbation
  int first_member = 0;              // the ensemble's first member (a shard)
  std::vector<std::string> abs_set;  // abs: KEY=VALUE overrides of the ABS file's numbers
};

// --kernel, else the environment variable HOTLAP_FE_KERNEL, else auto.
fe::ElementKernel ChooseKernel(const std::string& option) {
  if (!option.empty()) return fe::ParseElementKernel(option, "--kernel");
  const char* env = std::getenv("HOTLAP_FE_KERNEL");
  if (env == nullptr || *env == '\0') return fe::BestElementKernel();
  return fe::ParseElementKernel(env, "fe: HOTLAP_FE_KERNEL");
}

int RunFeCommand(const FeArgs& a) {
  if (!a.json.empty()) CheckOutputFolder(a.json, "--json");
  runs::FeRunOptions o;
  o.step = a.step;
  o.config = a.config;
  o.out = a.out;
  o.duration_s = a.duration_s;
  o.threads = a.threads;
  o.kernel = ChooseKernel(a.kernel);
  o.checkpoint_every_s = a.checkpoint_every_s;
  o.restart = a.restart;
  o.step_scale = a.step_scale;
  o.ensemble = a.ensemble;
  o.perturbation = sim::ParseFePerturbation(a.perturb, "--perturb");
  o.abs_set = a.abs_set;
  o.first_member = a.first_member;
  o.note = [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); };
  o.say = [](const std::string& line) {
    std::printf("%s\n", line.c_str());
    std::fflush(stdout);
  };
  const runs::FeRunResult r = runs::RunFe(o);
  if (!a.json.empty()) WriteJsonFile(a.json, r.summary);
  return 0;
}

}  // namespace

CommandRunner RegisterFeCommand(CLI::App& app) {
  auto args = std::make_shared<FeArgs>();
  CLI::App* sub = app.add_subcommand(
      "fe", "Finite-element tyre: inflate, footprint, free rolling, ABS stop (docs/fe-tyre.md)");
  sub->add_option("step", args->step, "inflate | footprint | roll | abs (runs the ones before)")
      ->required()
      ->check(CLI::IsMember({"inflate", "footprint", "roll", "abs"}));
  sub->add_option("--config", args->config, "FE tyre configuration (data/fe/*.yaml)")->required();
  sub->add_option("--out", args->out,
                  "Output folder: histories, footprint map, .vtu shapes, abs_report.html (abs)")
      ->required();
  sub->add_option("--json", args->json, "Write the summary as JSON (docs/fe-tyre.md)");
  sub->add_option("--duration-s", args->duration_s,
                  "Simulated time of the last step (roll or abs), s (default: the file's)")
      ->check(kPositive);
  sub->add_option("--threads", args->threads,
                  "Threads of the solver's element loop (default: all cores, OpenMP's default)")
      ->check(kPositive);
  sub->add_option("--kernel", args->kernel,
                  "Element loop: auto | portable | avx2 (default: HOTLAP_FE_KERNEL, else auto)")
      ->check(CLI::IsMember({"auto", "portable", "avx2"}));
  sub->add_option("--checkpoint-every-s", args->checkpoint_every_s,
                  "abs: write <out>/abs_checkpoint.bin every S of simulated time and at the end")
      ->check(kPositive);
  sub->add_option("--step-scale", args->step_scale,
                  "Time step as a fraction of the stable one's, in (0, 1] (a time-step study; "
                  "the road's penalty stiffness stays that of the full step; default 1)")
      ->check(CLI::Range(0.0, 1.0))
      ->check(kPositive);
  sub->add_option("--restart", args->restart,
                  "abs: continue from a checkpoint file (same configuration files and mesh)");
  sub->add_option("--ensemble", args->ensemble,
                  "abs: run N stops that differ by a tiny perturbation and report each figure's "
                  "mean, standard error and spread (--threads: stops at once)")
      ->check(kPositive);
  sub->add_option("--perturb", args->perturb,
                  "abs --ensemble: spin (the initial spin by up to 1e-9 relative) | sum-order (the "
                  "rim's sums over its nodes) | round-off (every node's velocity by one rounding)")
      ->check(CLI::IsMember({"spin", "sum-order", "round-off"}));
  sub->add_option("--first-member", args->first_member,
                  "abs --ensemble: start at member K of the sequence (a shard of a larger "
                  "ensemble; sum-order or round-off)")
      ->check(CLI::NonNegativeNumber);
  sub->add_option("--abs-set", args->abs_set,
                  "abs: override a number of the ABS file the FE file names, KEY=VALUE in the "
                  "key's own unit, repeatable (e.g. controller.reapply_fraction=0.85)");
  return [args] { return RunFeCommand(*args); };
}

}  // namespace hotlap::app
