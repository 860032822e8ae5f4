#include "hotlap/runs/f1_run.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"

namespace hotlap::runs {

void CheckF1Run(const std::string& car, bool overrides, const ocp::OptimalRunOptions& run) {
  if (overrides) {
    throw InputError(
        fmt::format("--set does not apply to the car '{}' (the limebeer-2014-f1 model "
                    "has no dotted keys to override; docs/f1-peer.md)",
                    car));
  }
  if (run.disc_limit_C || run.compare_disc_limit_C) {
    throw InputError("the limebeer-2014-f1 car has no brake temperatures: no disc limit");
  }
}

std::string PlanarTrackWarning(const track::Track& track) {
  double max_bank = 0.0, max_grade = 0.0;
  for (double d = 0.0; d < track.length_m(); d += 5.0) {
    max_bank = std::max(max_bank, std::abs(track.At(d).bank_rad));
    max_grade = std::max(max_grade, std::abs(track.At(d).grade_rad));
  }
  if (!(max_bank > 1e-3 || max_grade > 1e-3)) return "";
  return fmt::format(
      "warning: the limebeer-2014-f1 model is planar: this track's banking (up to {:.1f} deg) and "
      "grade (up to {:.1f} deg) are ignored\n",
      RadToDeg(max_bank), RadToDeg(max_grade));
}

ocp::IpoptOptions F1RunIpoptOptions(const ocp::OptimalRunOptions& run) {
  ocp::IpoptOptions ipopt = ocp::F1IpoptOptions();
  ipopt.max_iterations = run.max_iterations;
  for (const auto& kv : run.ipopt_options) ipopt.extra.push_back(kv);
  ipopt.print_level = run.ipopt_output ? 5 : 0;
  return ipopt;
}

}  // namespace hotlap::runs
