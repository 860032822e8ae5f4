#pragma once
/// @file
/// The next mesh of the adaptive refinement (ocp/adaptive_mesh.h) from a solved lap's error
/// estimate (ocp/mesh_error.h): intervals whose estimated lap-time error is above their share of
/// the tolerance are split, pairs of neighbours far below it merged.
///
/// Each interval's share of the tolerance is its share of the lap's length, tol h_k / L, so the
/// sum of |e_k| stays within the tolerance when every interval is within its share. The
/// trapezoid's error from an interval falls as h^3, so an interval m times over its share is
/// split into ceil(sqrt(m)) equal parts (each part then within its own smaller share), at most
/// `max_split` and none under `min_step_m`. Two neighbours neither of which is split are merged
/// when the error their union is estimated to have ((h_a + h_b)^3 times the mean of e/h^3 of the
/// two) is below `merge_fraction` of the union's share and the union is at most `max_step_m`.
/// Then the mesh is graded: an interval more than `max_ratio` times as long as a neighbour is
/// split into enough parts (the first solves of Darlington's lap on meshes that jumped from
/// 3.7 m to 15 m did not converge in 400-500 iterations).

#include <vector>

namespace hotlap::ocp {

struct MeshRefinementOptions {
  double tolerance_s = 1e-3;  ///< the sum of |e_k| asked for, s
  double min_step_m = 0.75;   ///< no interval is split below this, m
  double max_step_m = 15.0;  ///< no merge makes an interval longer than this, m (the coarse mesh's)
  int max_split = 4;         ///< an interval into at most this many in one round
  double merge_fraction = 0.1;  ///< merge where the union's estimate is below this of its share
  /// Grading: an interval at most this many times as long as either neighbour (more parts where
  /// a split neighbour asks it, no merge that breaks it; <= 1: none).
  double max_ratio = 2.0;
};

/// What RefineMesh did.
struct MeshRefinement {
  std::vector<double> mesh_m;  ///< the new nodes, m (0 to the lap's length)
  int split = 0;               ///< intervals split
  int merged = 0;              ///< pairs merged
  int graded = 0;              ///< intervals split further (or at all) for the grading
  /// Intervals over their share that could not be split further (at min_step_m already).
  int over_at_min_step = 0;
};

/// The next mesh from the nodes `mesh_m` and each interval's estimated lap-time error
/// `interval_error_s` (MeshErrorEstimate::interval_s; one an interval).
MeshRefinement RefineMesh(const std::vector<double>& mesh_m,
                          const std::vector<double>& interval_error_s,
                          const MeshRefinementOptions& options);

}  // namespace hotlap::ocp
