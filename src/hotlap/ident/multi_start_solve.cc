#include "hotlap/ident/multi_start_solve.h"

#include <algorithm>
#include <stdexcept>

#include <ceres/solver.h>

namespace hotlap::ident::internal {

MultiStartResult SolveMultiStart(std::span<const double> x0,
                                 std::span<const ParameterBounds> bounds,
                                 const AddResiduals& add_residuals,
                                 const MultiStartOptions& options) {
  if (bounds.size() != x0.size() || options.start_values.empty()) {
    throw std::logic_error("SolveMultiStart: one bound per parameter and at least one start");
  }
  const int n = static_cast<int>(x0.size());
  MultiStartResult result;
  bool have_best = false;
  for (double start : options.start_values) {
    std::vector<double> x(x0.begin(), x0.end());
    for (int i : options.start_indices) x[i] = start;
    ceres::Problem problem;
    add_residuals(problem, x.data());
    for (int i = 0; i < n; ++i) {
      problem.SetParameterLowerBound(x.data(), i, bounds[i].lower);
      problem.SetParameterUpperBound(x.data(), i, bounds[i].upper);
    }
    ceres::Solver::Options solver;
    solver.linear_solver_type = ceres::DENSE_QR;
    solver.max_num_iterations = options.max_iterations;
    solver.function_tolerance = options.function_tolerance;
    solver.gradient_tolerance = options.gradient_tolerance;
    solver.parameter_tolerance = options.parameter_tolerance;
    solver.logging_type = ceres::SILENT;
    solver.num_threads = 1;
    ceres::Solver::Summary summary;
    ceres::Solve(solver, &problem, &summary);
    result.iterations += static_cast<int>(summary.iterations.size());
    if (!have_best || summary.final_cost < result.final_cost) {
      have_best = true;
      result.x = x;
      result.final_cost = summary.final_cost;
      result.converged = summary.termination_type == ceres::CONVERGENCE;
      result.brief_report = summary.BriefReport();
    }
  }
  return result;
}

double StartInsideBounds(double value, const ParameterBounds& bounds) {
  const double margin = 1e-6 * (bounds.upper - bounds.lower);
  return std::clamp(value, bounds.lower + margin, bounds.upper - margin);
}

}  // namespace hotlap::ident::internal
