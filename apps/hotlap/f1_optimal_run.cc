// `hotlap optimise` for the limebeer-2014-f1 car (docs/f1-peer.md): the checks, the library's
// solve (ocp/f1_lap_problem.h), the summary and the outputs (ocp/f1_lap_output.h).

#include <chrono>
#include <cstdio>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/common/json_output.h"
#include "hotlap/common/output_folder.h"
#include "hotlap/ocp/f1_lap_output.h"
#include "hotlap/ocp/f1_lap_problem.h"
#include "hotlap/ocp/solver_memory.h"
#include "hotlap/runs/f1_run.h"
#include "hotlap/track/track_io.h"
#include "optimal_runs.h"

namespace hotlap::app {

namespace fs = std::filesystem;

int RunF1Optimal(const OptimalArgs& a, const fs::path& car_file) {
  const auto started = std::chrono::steady_clock::now();
  const ocp::OptimalRunOptions run = RunOptions(a);
  runs::CheckF1Run(a.car, !a.set.empty(), run);
  const vehicle::F1CarParams car = vehicle::LoadF1Car(car_file);
  const track::Track track = track::LoadTrack(a.track);
  CheckOutputDirectory(a.out, "--out");
  if (!a.json.empty()) CheckOutputFolder(a.json, "--json");
  fmt::print(stderr, "{}", runs::PlanarTrackWarning(track));
  ocp::F1LapOptions o;
  if (a.mesh_points > 0) o.mesh_points = a.mesh_points;
  ocp::KeepSolverMemory();
  ocp::IpoptOptions ipopt = runs::F1RunIpoptOptions(run);
  ipopt.on_iteration = [](int it, double obj, double pr, double du) {
    if (it % 10 == 0) {
      fmt::print("  iteration {:4d}: objective {:.4f}, infeasibility {:.1e}, optimality {:.1e}\n",
                 it, obj, pr, du);
      std::fflush(stdout);
    }
    return true;
  };
  fmt::print("hotlap optimal lap: car '{}' (limebeer-2014-f1) on {} ({:.1f} m), {} mesh points\n",
             car.name, track.name(), track.length_m(), o.mesh_points);
  std::fflush(stdout);
  const ocp::F1LapSolution s = ocp::SolveF1Lap(car, track, o, ipopt);
  fmt::print("{}", ocp::F1LapText(s));

  fs::create_directories(a.out);
  const fs::path csv = fs::path(a.out) / "optimal.csv";
  ocp::WriteF1LapCsv(csv, s, track, car);
  fmt::print("wrote {}\n", csv.string());
  if (!a.json.empty()) {
    WriteJsonFileAndSay(a.json, ocp::F1LapJson(s, track.name(), car.name, o.mesh_points));
  }
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  fmt::print("done in {:.1f} s\n", elapsed);
  return s.solve.ok() ? 0 : 3;
}

}  // namespace hotlap::app
