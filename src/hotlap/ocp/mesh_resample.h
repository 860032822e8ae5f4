#pragma once
/// @file
/// A solved lap taken onto another mesh of the same problem when either mesh is non-uniform
/// (LapProblemOptions::mesh_m): the start of each solve of the adaptive mesh's refinement
/// (ocp/adaptive_mesh.h) from the one before. The same rules as ResampleLapPoint and
/// ResampleLapMultipliers (lap_problem.h), in distance along the centre line instead of node
/// counts.

#include <vector>

#include "hotlap/ocp/ipopt_solve.h"
#include "hotlap/ocp/lap_problem.h"

namespace hotlap::ocp {

/// The node distances of `layout`: its mesh_m, else its nodes spread evenly over `length_m`.
std::vector<double> LayoutNodeDistances(const LapLayout& layout, double length_m);

/// A point of the lap problem on the nodes at `from_m` taken onto the nodes at `to_m` (both from
/// 0 to the same length): every node variable linearly interpolated in distance. InputError if x
/// is not whole nodes of `from_m`.
std::vector<double> ResampleLapPointOnMesh(const std::vector<double>& x,
                                           const std::vector<double>& from_m,
                                           const std::vector<double>& to_m);

/// The multipliers of `solve` (of `from`, its nodes at `from_m`) on the layout `to` (its nodes at
/// `to_m`), both trapezoids: a node equation's or a bound's multiplier as a density per metre of
/// its node's share of the lap (half of each interval beside it), a defect's (the costate) and a
/// rate limit's interpolated at the interval midpoints, the closure's copied. InputError if the
/// sizes do not match `from` or either is not a trapezoid.
LapMultipliers ResampleLapMultipliersOnMesh(const SolveResult& solve, const LapLayout& from,
                                            const std::vector<double>& from_m, const LapLayout& to,
                                            const std::vector<double>& to_m);

/// StartFromSolution onto the non-uniform trapezoid mesh `to_mesh_m` of a track `length_m` long:
/// the point as `start_point` and, if `with_multipliers` and `from` is a trapezoid, the
/// multipliers as `ipopt`'s warm start.
void StartFromSolutionOnMesh(const SolveResult& solve, const LapLayout& from, double length_m,
                             const std::vector<double>& to_mesh_m, bool with_multipliers,
                             std::vector<double>& start_point, IpoptOptions& ipopt);

}  // namespace hotlap::ocp
