#pragma once
/// @file
/// One bounded nonlinear least-squares problem solved from several starts, keeping the lowest
/// cost: the solve both tyre rig fits (mf_fit.h, unitire_fit.h) run. Not API.
///
/// How to use: give the start `x0` (inside `bounds`; StartInsideBounds helps), a function that
/// adds the residual blocks on the parameter block it is handed (AddDynamicAutoDiffResidual for
/// one functor per sample), and the starts: for each of `options.start_values`, the solve begins
/// at `x0` with every entry named in `options.start_indices` set to that value. The fits use this
/// for their curvature factors, whose cost has local minima far from the data's estimate.
///
/// Each start builds its own ceres::Problem (Levenberg-Marquardt, dense QR, one thread, silent);
/// the first start is kept, then any later one with a strictly lower final cost.

#include <functional>
#include <span>
#include <string>
#include <vector>

#include <ceres/dynamic_autodiff_cost_function.h>
#include <ceres/problem.h>

namespace hotlap::ident::internal {

/// Lower and upper bound of one free parameter.
struct ParameterBounds {
  double lower = 0.0;
  double upper = 0.0;
};

/// Options of SolveMultiStart: the starts and Ceres' stopping rules.
struct MultiStartOptions {
  /// One solve per value, in this order; the entries of `start_indices` take the value.
  std::vector<double> start_values;
  /// Indices into x of the parameters the starts set (may be empty: each start is then x0).
  std::vector<int> start_indices;
  int max_iterations = 200;            ///< Ceres' max_num_iterations per start
  double function_tolerance = 1e-12;   ///< Ceres' relative cost change to stop at
  double gradient_tolerance = 1e-14;   ///< Ceres' projected-gradient norm to stop at
  double parameter_tolerance = 1e-12;  ///< Ceres' relative step to stop at
};

/// The kept start's solution and how the solves went.
struct MultiStartResult {
  std::vector<double> x;     ///< solution of the kept start
  double final_cost = 0.0;   ///< Ceres' cost of the kept start, 1/2 sum of squared residuals
  bool converged = false;    ///< the kept start ended in ceres::CONVERGENCE
  int iterations = 0;        ///< Ceres iterations summed over every start
  std::string brief_report;  ///< Ceres' brief report of the kept start
};

/// Adds the problem's residual blocks, each on the one parameter block `x`.
using AddResiduals = std::function<void(ceres::Problem& problem, double* x)>;

/// Solves from every start (see the file comment) and returns the lowest-cost one. `bounds` has
/// one entry per value of `x0`; `options.start_values` must not be empty.
MultiStartResult SolveMultiStart(std::span<const double> x0,
                                 std::span<const ParameterBounds> bounds,
                                 const AddResiduals& add_residuals,
                                 const MultiStartOptions& options);

/// `value` clamped into `bounds`, a millionth of the range away from either end, so a first step
/// can go either way.
double StartInsideBounds(double value, const ParameterBounds& bounds);

/// Adds one residual block of `residuals` values computed by `functor` (owned by the problem)
/// from the `parameters` values at `x`, differentiated by dynamic automatic differentiation.
template <class Functor>
void AddDynamicAutoDiffResidual(ceres::Problem& problem, Functor* functor, int parameters,
                                int residuals, double* x) {
  auto* cost = new ceres::DynamicAutoDiffCostFunction<Functor, 14>(functor);
  cost->AddParameterBlock(parameters);
  cost->SetNumResiduals(residuals);
  problem.AddResidualBlock(cost, nullptr, x);
}

}  // namespace hotlap::ident::internal
