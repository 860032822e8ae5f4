// `hotlap optimise` for the limebeer-2014-f1 car (docs/f1-peer.md).

#include "f1_optimal_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "hotlap/common/csv.h"
#include "hotlap/common/error.h"
#include "hotlap/common/json_output.h"
#include "hotlap/common/output_folder.h"
#include "hotlap/common/units.h"
#include "hotlap/ocp/f1_lap_problem.h"
#include "hotlap/ocp/solver_memory.h"
#include "hotlap/track/track_io.h"

namespace hotlap::app {

namespace {

namespace fs = std::filesystem;

// fastest-lap's lap time for this car on its 500-point Catalunya (shared/data/peer README).
constexpr double kPeerLapTime = 77.791;

void WriteChannels(const fs::path& path, const ocp::F1LapSolution& s, const track::Track& track,
                   const vehicle::F1CarParams& car) {
  std::vector<std::string> names = {"distance_m",        "time_s",         "speed_mps",
                                    "lateral_speed_mps", "yaw_rate_radps", "offset_m",
                                    "heading_error_rad", "steer_rad",      "throttle"};
  std::vector<std::vector<double>> values = {s.distance, s.time,  s.u,     s.v,       s.r,
                                             s.n,        s.alpha, s.steer, s.throttle};
  const char* corners[4] = {"fl", "fr", "rl", "rr"};
  for (int c = 0; c < 4; ++c) {
    const std::string k = corners[c];
    names.insert(names.end(), {"slip_ratio_" + k, "lateral_slip_" + k, "fz_" + k + "_N",
                               "fx_" + k + "_N", "fy_" + k + "_N"});
    values.insert(values.end(), {s.kappa[c], s.lambda[c], s.fz[c], s.fx[c], s.fy[c]});
  }
  WriteCsv(
      path,
      {{"source", fmt::format("hotlap {} optimal lap, model limebeer-2014-f1", HOTLAP_VERSION)},
       {"track", track.name()},
       {"car", car.path.string()},
       {"status", s.solve.message}},
      names, values);
}

}  // namespace

int RunF1Optimal(const OptimalArgs& a, const fs::path& car_file) {
  const auto started = std::chrono::steady_clock::now();
  const vehicle::F1CarParams car = vehicle::LoadF1Car(car_file);
  const track::Track track = track::LoadTrack(a.track);
  if (fs::exists(a.out) && !fs::is_directory(a.out)) {
    throw InputError(fmt::format("--out {}: exists and is not a folder", a.out));
  }
  if (!a.json.empty()) CheckOutputFolder(a.json, "--json");
  if (a.disc_limit_C || a.compare_disc_limit_C) {
    throw InputError("the limebeer-2014-f1 car has no brake temperatures: no disc limit");
  }
  double max_bank = 0.0, max_grade = 0.0;
  for (double d = 0.0; d < track.length_m(); d += 5.0) {
    max_bank = std::max(max_bank, std::abs(track.At(d).bank_rad));
    max_grade = std::max(max_grade, std::abs(track.At(d).grade_rad));
  }
  if (max_bank > 1e-3 || max_grade > 1e-3) {
    fmt::print(stderr,
               "warning: the limebeer-2014-f1 model is planar: this track's banking (up to {:.1f} "
               "deg) and grade (up to {:.1f} deg) are ignored\n",
               RadToDeg(max_bank), RadToDeg(max_grade));
  }
  ocp::F1LapOptions o;
  if (a.mesh_points > 0) o.mesh_points = a.mesh_points;
  ocp::KeepSolverMemory();
  ocp::IpoptOptions ipopt = ocp::F1IpoptOptions();
  ipopt.max_iterations = a.max_iterations;
  for (auto& kv : IpoptOptionPairs(a)) ipopt.extra.push_back(std::move(kv));
  ipopt.print_level = a.ipopt_output ? 5 : 0;
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
  const ocp::SolveResult& r = s.solve;
  double top = 0.0, slow = 1e9;
  for (double u : s.u) {
    top = std::max(top, u);
    slow = std::min(slow, u);
  }
  fmt::print("{} after {} iterations in {:.2f} s: lap {:.3f} s (guess {:.3f} s)\n", r.message,
             r.iterations, r.solve_seconds, s.lap_time, s.guess_lap_time);
  fmt::print("  top speed {:.2f} m/s, slowest {:.2f} m/s; {} variables, {} constraints\n", top,
             slow, s.variables, s.constraints);

  fs::create_directories(a.out);
  const fs::path csv = fs::path(a.out) / "optimal.csv";
  WriteChannels(csv, s, track, car);
  fmt::print("wrote {}\n", csv.string());
  if (!a.json.empty()) {
    nlohmann::json j = {{"command", "optimise"},
                        {"model", "limebeer-2014-f1"},
                        {"track", track.name()},
                        {"car", car.name},
                        {"mesh_points", o.mesh_points},
                        {"lap_time_s", RoundSignificant(s.lap_time)},
                        {"guess_lap_time_s", RoundSignificant(s.guess_lap_time)},
                        {"solve_time_s", RoundSignificant(r.solve_seconds)},
                        {"ipopt_iterations", r.iterations},
                        {"converged", r.ok()},
                        {"status", r.ok() ? "converged" : "failed"},
                        {"message", r.message},
                        {"top_speed_mps", RoundSignificant(top)},
                        {"min_speed_mps", RoundSignificant(slow)},
                        {"variables", s.variables},
                        {"constraints", s.constraints}};
    if (track.name() == "catalunya-fl") {
      // The peer's figure for this case, and our difference from it.
      j["peer_lap_time_s"] = kPeerLapTime;
      j["lap_time_difference_percent"] =
          RoundSignificant(100.0 * (s.lap_time - kPeerLapTime) / kPeerLapTime, 4);
    }
    WriteJsonFile(a.json, j);
    fmt::print("wrote {}\n", a.json);
  }
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  fmt::print("done in {:.1f} s\n", elapsed);
  return r.ok() ? 0 : 3;
}

}  // namespace hotlap::app
