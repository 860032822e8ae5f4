#pragma once
/// @file
/// The adaptive mesh's refinement loop (OptimalLapOptions::tolerance_s): from a solved lap, the
/// error estimate (ocp/mesh_error.h), the next mesh (ocp/mesh_refinement.h) and the solve on it
/// from the last one's point and multipliers (ocp/mesh_resample.h), until no interval is over
/// its share of the tolerance.

#include <vector>

#include "hotlap/ocp/lap_problem.h"
#include "hotlap/ocp/optimal_lap.h"

namespace hotlap::ocp {

struct AdaptiveMeshResult {
  /// The last converged solve (`start` if none after it converged).
  LapSolution solution;
  /// Its problem as posed (the mesh, the start point that froze the wear): `start_problem`, or
  /// the refined solve's. RunOptimalLap keeps it (OptimalLapRun::posed) for the sensitivities.
  LapProblemOptions problem;
  std::vector<MeshRound> rounds;  ///< `start` first, then each solve
};

/// Refines from `start` (a converged solve of `start_problem` on any mesh of `track`): at most
/// options.max_refinements solves of `lap` on the refined meshes (its mesh_m and start_point
/// replaced: the last solve's point, and its multipliers if options.refinement_multipliers; the
/// wear in the programme as options.wear_in_programme), each with options.ipopt
/// and MUMPS' SCOTCH ordering as every solve from a solution. Stops when no interval is over its
/// share of options.tolerance_s (RefineMesh splits none) or a solve fails (its round is recorded,
/// the solution kept is the one before).
AdaptiveMeshResult RefineLapMesh(const vehicle::Car& car, const track::Track& track,
                                 const LapProblemOptions& lap, const sim::QssLap& guess,
                                 const OptimalLapOptions& options, LapSolution start,
                                 LapProblemOptions start_problem);

/// A solve's round: its nodes, iterations, time, lap and estimate.
MeshRound MeshRoundOf(const LapSolution& solution);

}  // namespace hotlap::ocp
