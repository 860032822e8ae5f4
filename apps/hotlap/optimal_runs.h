#pragma once
// The optimal lap as `hotlap optimise` and `hotlap lap --method ocp` run it: options, one solve or
// the paper's comparison without and with a front-disc limit, outputs and summaries.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

namespace hotlap::app {

struct OptimalArgs {
  std::string track = "darlington";
  std::string car = "gen7";
  std::string out;
  std::string json;
  double step_m = 3.0;
  double steer_smoothing = -1.0;       ///< the steer's smoothness weight (< 0: the library's)
  double pedal_smoothing = -1.0;       ///< the pedal's
  double coarse_step_m = 15.0;         ///< solve first on this mesh and start from it (0: off)
  std::string hessian = "exact";       ///< exact, or convex-elements
  std::optional<double> disc_limit_C;  ///< one solve with this front-disc limit
  std::optional<double> compare_disc_limit_C;  ///< two solves: without, and with this limit
  std::string thermal_start = "racing";
  double ambient_C = 25.0;
  double track_C = 40.0;
  int max_iterations = 1000;
  bool mesh_check = false;
  bool ipopt_output = false;
  bool single_process = false;
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

/// The --ipopt-option values as (name, value) pairs.
std::vector<std::pair<std::string, std::string>> IpoptOptionPairs(const OptimalArgs& args);

/// Runs the solve(s), prints the summary, writes the outputs. Returns the exit code: 0, or 3 when
/// a solve did not converge (its last point is still written).
int RunOptimal(const OptimalArgs& args);

}  // namespace hotlap::app
