// `hotlap optimise`: the minimum-lap-time optimal control with tyre and brake thermal states and,
// optionally, a front-disc temperature limit (docs/optimal-control.md).

#include <memory>

#include "commands.h"
#include "optimal_runs.h"

namespace hotlap::app {

CommandRunner RegisterOptimiseCommand(CLI::App& app) {
  auto args = std::make_shared<OptimalArgs>();
  CLI::App* sub = app.add_subcommand(
      "optimise", "Minimum-lap-time optimal control with tyre and brake temperatures as states");
  AddOptimalOptions(sub, *args);
  sub->add_option("--disc-limit-C", args->run.disc_limit_C,
                  "Front disc temperatures at most this, degC (none by default)");
  args->f1_only.push_back(
      sub->add_option("--mesh-points", args->mesh_points,
                      "limebeer-2014-f1 cars only: mesh nodes (default 500; docs/f1-peer.md)")
          ->check(CLI::Range(20, 100000)));
  return [args] { return RunOptimal(*args); };
}

}  // namespace hotlap::app
