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
    options.start_point = StartPointOnMesh(s, track, options.step_m);
    const LapMultipliers m = ResampleLapMultipliers(
        s.solve, s.layout, s.layout.WithNodes(LapNodeCount(track, options.step_m)));
    options.ipopt.warm_z_lower = m.z_lower;
    options.ipopt.warm_z_upper = m.z_upper;
    options.ipopt.warm_lambda = m.lambda;
  }
  return SolveLap(car, track, options, "half mesh", nullptr, progress, log);
}

}  // namespace hotlap::ocp
