#pragma once
// The optimal lap as `hotlap optimise` and `hotlap lap --method ocp` run it: the command-line
// options, the checks before any work, and what is printed and written of the library's runs
// (ocp/optimal_run.h).

#include <filesystem>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "hotlap/ocp/optimal_run.h"

namespace hotlap::app {

struct OptimalArgs {
  std::string track = "darlington";
  std::string car = "gen7";
  std::vector<std::string> set;  ///< --set KEY=VALUE: car parameters overridden
  std::string out;
  std::string json;
  std::string command = "optimise";  ///< the JSON's "command": "optimise" or "lap --method ocp"
  /// The library's options, filled by CLI11 (the Hessian, the second process and the Ipopt
  /// options from the three below at run time).
  ocp::OptimalRunOptions run = [] {
    ocp::OptimalRunOptions o;
    o.threads = 0;  // --threads: one per core
    return o;
  }();
  std::string hessian = "exact";   ///< exact, or convex-elements
  std::string controls = "pedal";  ///< pedal, or independent (the old two controls)
  bool single_process = false;
  bool mesh_check = false;
  std::string warm_start;                  ///< a lap saved with --save-solution to start from
  std::string save_solution;               ///< where to save the solved lap
  std::vector<std::string> ipopt_options;  ///< NAME=VALUE, passed to Ipopt as they are
  int mesh_points = 0;  ///< limebeer-2014-f1 cars only: mesh nodes (0: 500; docs/f1-peer.md)
  /// Options given on the command line that only one of the two models uses (filled by CLI11
  /// at parse time): the stock car's mesh spacing, thermal start, temperatures and mesh check;
  /// the F1 car's mesh points. Giving one to the other model is an input error, not ignored.
  std::vector<const CLI::Option*> stock_car_only, f1_only;
};

/// Adds the options shared by both commands to `sub` (optimal_options.cc).
void AddOptimalOptions(CLI::App* sub, OptimalArgs& args);

/// args.run with the Hessian, the second process and the --ipopt-option pairs filled in.
ocp::OptimalRunOptions RunOptions(const OptimalArgs& args);

/// Runs the solve(s), prints the summary, writes the outputs. Returns the exit code: 0, or 3 when
/// a solve did not converge (its last point is still written).
int RunOptimal(const OptimalArgs& args);

/// The same for a car of model limebeer-2014-f1 in `car_file` (f1_optimal_run.cc, docs/f1-peer.md):
/// one minimum-time solve, <out>/optimal.csv and, with --json, the summary.
int RunF1Optimal(const OptimalArgs& args, const std::filesystem::path& car_file);

}  // namespace hotlap::app
