#include "hotlap/ocp/f1_lap_output.h"

#include <algorithm>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "hotlap/common/csv.h"
#include "hotlap/common/json_output.h"

namespace hotlap::ocp {

namespace {

// The top and the lowest speed of the lap, m/s.
std::pair<double, double> SpeedRange(const F1LapSolution& s) {
  double top = 0.0, slow = 1e9;
  for (double u : s.u) {
    top = std::max(top, u);
    slow = std::min(slow, u);
  }
  return {top, slow};
}

}  // namespace

void WriteF1LapCsv(const std::filesystem::path& path, const F1LapSolution& s,
                   const track::Track& track, const vehicle::F1CarParams& car) {
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

std::string F1LapText(const F1LapSolution& s) {
  const SolveResult& r = s.solve;
  const auto [top, slow] = SpeedRange(s);
  return fmt::format("{} after {} iterations in {:.2f} s: lap {:.3f} s (guess {:.3f} s)\n",
                     r.message, r.iterations, r.solve_seconds, s.lap_time, s.guess_lap_time) +
         fmt::format("  top speed {:.2f} m/s, slowest {:.2f} m/s; {} variables, {} constraints\n",
                     top, slow, s.variables, s.constraints);
}

nlohmann::json F1LapJson(const F1LapSolution& s, const std::string& track_name,
                         const std::string& car_name, int mesh_points) {
  const SolveResult& r = s.solve;
  const auto [top, slow] = SpeedRange(s);
  nlohmann::json j = {{"command", "optimise"},
                      {"model", "limebeer-2014-f1"},
                      {"track", track_name},
                      {"car", car_name},
                      {"mesh_points", mesh_points},
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
  if (track_name == "catalunya-fl") {
    // The peer's figure for this case, and our difference from it.
    j["peer_lap_time_s"] = kF1PeerLapTime;
    j["lap_time_difference_percent"] =
        RoundSignificant(100.0 * (s.lap_time - kF1PeerLapTime) / kF1PeerLapTime, 4);
  }
  return j;
}

}  // namespace hotlap::ocp
