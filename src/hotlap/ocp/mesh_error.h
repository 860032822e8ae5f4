#pragma once
/// @file
/// How far a solved lap's time is from the exact (continuous) problem's, interval by interval,
/// from the collocation's own defects between the nodes (docs/optimal-control-model.md, "Mesh
/// error").
///
/// The trapezoid imposes x_{k+1} - x_k = h_k / 2 (f_k + f_{k+1}) on every interval of length h_k.
/// The exact solution does not satisfy it: its defect is tau_k = integral of f over the interval
/// minus the trapezoid, about -h_k^3 / 12 f''. That integral is estimated by an embedded
/// higher-order rule, the cubic through the rates at four neighbouring nodes (the interval's two
/// and one either side, or the nearest four at the lap's ends) integrated exactly, so tau_k is
/// that rule minus the trapezoid, from the node rates the solve already has. The solved lap is
/// then the exact problem with every defect's right-hand side moved by -tau_k, and the lap time
/// moves with a right-hand side by minus the row's multiplier (the costate), so the lap time's
/// error from interval k is
///
///     e_k = sum over states j of lambda_kj tau_kj  -  tau_w,k
///
/// (the second term the trapezoid's own error in the lap time, the integral of w = dt/ds). Their
/// sum estimates T(mesh) - T(exact); |e_k| says where the mesh is too coarse
/// (ocp/mesh_refinement.h). A first-order (dual-weighted residual) estimate: it assumes the
/// rates are smooth over each four-node stencil, so where the pedal switches it marks the
/// intervals there rather than measuring them exactly.

#include <vector>

namespace hotlap::ocp {

/// A trapezoid solution's picture for the estimate: the nodes, every state's rate at each node,
/// each interval's costates, and dt/ds at each node.
struct CollocationRates {
  std::vector<double> node_m;  ///< the nodes' distances along the centre line, m
  int states = 0;              ///< states per node
  /// d(state)/ds at each node, node after node (`states` each; the state's unit per metre).
  std::vector<double> rates;
  /// Each interval's defect multipliers in physical units, interval after interval (`states`
  /// each): minus the change of the objective (s) per unit of the defect's right-hand side. 0 for
  /// a state without defects (integrated after the solve).
  std::vector<double> costates;
  std::vector<double> dt_ds;  ///< w = dt/ds at each node, s/m

  bool empty() const { return node_m.size() < 4; }
};

/// The estimate: each interval's share of the lap-time error and their sums.
struct MeshErrorEstimate {
  /// e_k, s: positive where the mesh makes the lap longer than the exact problem's.
  std::vector<double> interval_s;
  double lap_time_error_s = 0.0;  ///< sum of e_k: the estimate of T(mesh) - T(exact)
  double abs_error_s = 0.0;       ///< sum of |e_k|
};

/// The estimate of `rates` (empty if it has fewer than four nodes).
MeshErrorEstimate EstimateMeshError(const CollocationRates& rates);

/// The integral over [s[k], s[k + 1]] of the cubic through (s[i], f[i]), i = i0..i0 + 3 with
/// i0 the stencil of interval k (k - 1, clamped to the nodes), minus the trapezoid of f over the
/// interval: tau_k of the file comment. `f` at every node; at least four nodes.
double TrapezoidDefect(const std::vector<double>& s, const std::vector<double>& f, int k);

}  // namespace hotlap::ocp
