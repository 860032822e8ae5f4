#include "hotlap/ocp/mesh_check.h"

namespace hotlap::ocp {

SolvedLap SolveOnHalfMesh(const vehicle::Car& car, const track::Track& track,
                          OptimalLapOptions options, const SolvedLap& solved,
                          const LapProgress& progress, const LapLog& log) {
  options.step_m *= 0.5;
  options.front_disc_limit = solved.front_disc_limit;
  options.start_point.clear();
  const LapSolution& s = solved.run.solution;
  if (s.solve.ok()) {
    // Point and multipliers: a warm start, as coarse to fine does.
    StartFromSolution(s.solve, s.layout, LapNodeCount(track, options.step_m, options.collocation),
                      options.collocation, true, options.start_point, options.ipopt);
  }
  return SolveLap(car, track, options, "half mesh", nullptr, progress, log);
}

}  // namespace hotlap::ocp
