#include "hotlap/ocp/adaptive_mesh.h"

#include <utility>

#include "hotlap/ocp/mesh_error.h"
#include "hotlap/ocp/mesh_refinement.h"
#include "hotlap/ocp/mesh_resample.h"

namespace hotlap::ocp {

MeshRound MeshRoundOf(const LapSolution& solution) {
  const MeshErrorEstimate e = EstimateMeshError(solution.rates);
  MeshRound r;
  r.nodes = solution.layout.nodes;
  r.iterations = solution.solve.iterations;
  r.solve_seconds = solution.solve.solve_seconds;
  r.lap_time_s = solution.lap_time;
  r.estimated_error_s = e.lap_time_error_s;
  r.abs_error_s = e.abs_error_s;
  r.converged = solution.solve.ok();
  return r;
}

AdaptiveMeshResult RefineLapMesh(const vehicle::Car& car, const track::Track& track,
                                 const LapProblemOptions& lap, const sim::QssLap& guess,
                                 const OptimalLapOptions& options, LapSolution start,
                                 LapProblemOptions start_problem) {
  AdaptiveMeshResult out;
  out.rounds.push_back(MeshRoundOf(start));
  out.solution = std::move(start);
  out.problem = std::move(start_problem);
  MeshRefinementOptions refine = options.refinement;
  refine.tolerance_s = options.tolerance_s;
  for (int round = 0; round < options.max_refinements; ++round) {
    const MeshErrorEstimate e = EstimateMeshError(out.solution.rates);
    if (e.interval_s.empty()) break;
    const MeshRefinement next = RefineMesh(
        LayoutNodeDistances(out.solution.layout, track.length_m()), e.interval_s, refine);
    if (next.split == 0) break;
    if (options.on_mesh) options.on_mesh(next);
    LapProblemOptions o = lap;
    o.mesh_m = next.mesh_m;
    o.collocation = Collocation::kTrapezoid;
    o.wear_in_programme = options.wear_in_programme;
    IpoptOptions ipopt = options.ipopt;
    // The point alone: with the multipliers too (an Ipopt warm start at a small barrier) the
    // first refined solve of Darlington's lap stalled at a constraint violation of 1e-2 for
    // 400-500 iterations on two meshes; from the point alone the same meshes converged in about
    // 160, then 75 and 35 (docs/validation/optimal-lap.md, "Mesh").
    StartFromSolutionOnMesh(out.solution.solve, out.solution.layout, track.length_m(), next.mesh_m,
                            options.refinement_multipliers, o.start_point, ipopt);
    // From a solution: SCOTCH's ordering, as coarse to fine (optimal_lap.cc).
    ipopt.extra.insert(ipopt.extra.begin(), {"mumps_pivot_order", "3"});
    LapSolution s = SolveMinimumTimeLap(car, track, o, guess, ipopt);
    out.rounds.push_back(MeshRoundOf(s));
    if (!s.solve.ok()) break;
    out.solution = std::move(s);
    out.problem = std::move(o);
  }
  return out;
}

}  // namespace hotlap::ocp
