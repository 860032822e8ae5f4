#pragma once
/// @file
/// A sparse nonlinear programme assembled from variables, linear terms and elements (element.h):
///
///   minimise    sum of objective terms
///   subject to  lower_r <= g_r(x) <= upper_r,   lower_i <= x_i <= upper_i,
///
/// where each g_r and the objective are sums of constant-coefficient linear terms in the
/// variables and of coefficient-weighted outputs of elements. The programme knows its Jacobian
/// and Lagrangian-Hessian sparsity exactly from which variables each element reads, and
/// evaluates both exactly (elements are differentiated by forward-mode AD).
///
/// Scaling: every variable has a scale s_i and every row a scale t_r; the solver sees
/// y_i = x_i / s_i and g_r / t_r, and the objective divided by its scale, so that a well-chosen
/// scale makes every quantity of order one (spec section 10: temperatures in hundreds of kelvin,
/// forces in kN, ...). Builders work in physical units throughout.
///
/// How to use: AddVariable for each unknown, AddConstraint for each row, then AddLinear,
/// AddObjectiveLinear and AddElement to fill them; Finalize(); then hand it to SolveWithIpopt
/// (ipopt_solve.h).

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "hotlap/ocp/element.h"

namespace hotlap::ocp {

/// Where one element output goes: a constraint row, or the objective (row == kObjective), times a
/// constant coefficient.
struct Target {
  static constexpr int kObjective = -1;
  int row = kObjective;
  double coefficient = 1.0;
};

/// Lower-triangular (row >= col) or general coordinate sparsity.
struct Sparsity {
  std::vector<int> rows;
  std::vector<int> cols;
};

class ElementNlp {
 public:
  /// A new variable; returns its index. `scale` > 0; bounds may be +-infinity.
  int AddVariable(double initial, double lower, double upper, double scale);
  /// A new constraint row lower <= g <= upper; returns its index. `scale` > 0.
  int AddConstraint(double lower, double upper, double scale);
  /// g_row += coefficient * x_var.
  void AddLinear(int row, int var, double coefficient);
  /// objective += coefficient * x_var.
  void AddObjectiveLinear(int var, double coefficient);
  /// Adds the element reading variables `inputs` (in the element's input order; a variable may
  /// appear more than once); output o is added to every target in targets[o].
  void AddElement(std::shared_ptr<const Element> element, std::vector<int> inputs,
                  std::vector<std::vector<Target>> targets);
  /// The objective is divided by this (> 0) before the solver sees it.
  void SetObjectiveScale(double scale) { objective_scale_ = scale; }
  double objective_scale() const { return objective_scale_; }
  /// ScaledHessian gives each element's weighted Hessian with its negative eigenvalues set to
  /// zero (in the scaled variables) instead of the exact one: a positive semi-definite
  /// Lagrangian Hessian, so that the solver's inertia correction has less to do, at the price of
  /// Newton's convergence rate where the exact Hessian is indefinite (docs/optimal-control.md).
  void SetConvexElementHessians(bool convex) { convex_element_hessians_ = convex; }
  /// Threads that evaluate the elements for the constraints, Jacobian and Hessian (>= 1; 1: this
  /// thread alone). The elements are split into that many fixed parts (every n-th element), each
  /// summed into its own buffer and the buffers added in order, so a given thread count gives the
  /// same values bit for bit on every run (another count may differ in the last bits).
  void SetThreads(int threads) { threads_ = threads < 1 ? 1 : threads; }
  int threads() const { return threads_; }
  /// Builds the sparsity patterns; call once after adding everything.
  void Finalize();

  int variables() const { return static_cast<int>(x0_.size()); }
  int constraints() const { return static_cast<int>(g_lower_.size()); }

  // Physical-unit data.
  double initial(int i) const { return x0_[i]; }
  void set_initial(int i, double value) { x0_[i] = value; }
  double lower(int i) const { return x_lower_[i]; }
  double upper(int i) const { return x_upper_[i]; }
  void set_bounds(int i, double lower, double upper) {
    x_lower_[i] = lower;
    x_upper_[i] = upper;
  }
  double scale(int i) const { return x_scale_[i]; }
  double row_lower(int r) const { return g_lower_[r]; }
  double row_upper(int r) const { return g_upper_[r]; }
  double row_scale(int r) const { return g_scale_[r]; }

  /// Objective and constraint values at physical-unit x (unscaled).
  double Objective(const std::vector<double>& x) const;
  std::vector<double> Constraints(const std::vector<double>& x) const;

  // The scaled programme the solver sees (y = x / scale).
  void ScaledBounds(double* y_lower, double* y_upper, double* g_lower, double* g_upper) const;
  void ScaledStart(double* y) const;
  double ScaledObjective(const double* y) const;
  void ScaledObjectiveGradient(const double* y, double* grad) const;
  void ScaledConstraints(const double* y, double* g) const;
  const Sparsity& JacobianPattern() const { return jac_pattern_; }
  void ScaledJacobian(const double* y, double* values) const;
  /// Lower triangle (row >= col).
  const Sparsity& HessianPattern() const { return hess_pattern_; }
  /// Hessian of sigma * objective + sum lambda_r g_r, all scaled.
  void ScaledHessian(const double* y, double sigma, const double* lambda, double* values) const;
  /// Physical x from scaled y.
  std::vector<double> Unscale(const double* y) const;

 private:
  struct Instance {
    std::shared_ptr<const Element> element;
    std::vector<int> inputs;
    std::vector<std::vector<Target>> targets;
    // Filled by Finalize: for each output o, target t, input i, the Jacobian value slot (or -1
    // for the objective), flattened in that order; and for each input pair (i, j) with
    // var_i >= var_j the Hessian slot.
    std::vector<int> jac_slots;
    std::vector<int> hess_slots;  // inputs * inputs, -1 where var_i < var_j
  };
  // One thread's work space for an element's inputs, outputs, Jacobian and Hessian.
  struct Scratch {
    std::vector<double> in, out, jac, hess;
  };
  // Runs accumulate(instance, into, scratch) over every instance, adding into `out` (`size`
  // values), the instances split over threads_ threads as SetThreads says.
  template <class Accumulate>
  void AccumulateInstances(double* out, size_t size, const Accumulate& accumulate) const;
  // The element's n x n weighted Hessian `hess` (unscaled) with its negative curvature removed.
  void ClipNegativeCurvature(const Instance& inst, int n, double* hess) const;
  struct LinearTerm {
    int row;
    int var;
    double coefficient;
  };

  std::vector<double> x0_, x_lower_, x_upper_, x_scale_;
  std::vector<double> g_lower_, g_upper_, g_scale_;
  std::vector<LinearTerm> linear_;
  std::vector<int> linear_slots_;
  std::vector<std::pair<int, double>> objective_linear_;
  std::vector<Instance> instances_;
  double objective_scale_ = 1.0;
  bool convex_element_hessians_ = false;
  int threads_ = 1;
  Sparsity jac_pattern_, hess_pattern_;
  bool finalized_ = false;
  int max_inputs_ = 0, max_outputs_ = 0;
};

}  // namespace hotlap::ocp
