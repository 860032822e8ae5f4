#include "hotlap/ocp/element_nlp.h"

#include <algorithm>
#include <exception>
#include <stdexcept>
#include <system_error>
#include <thread>
#include <unordered_map>

#include <Eigen/Dense>

namespace hotlap::ocp {

namespace {

std::uint64_t Key(int a, int b) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
         static_cast<std::uint32_t>(b);
}

// Slot of (row, col) in a coordinate pattern, added if new.
int Slot(std::unordered_map<std::uint64_t, int>& index, Sparsity& pattern, int row, int col) {
  const auto [it, inserted] = index.emplace(Key(row, col), static_cast<int>(pattern.rows.size()));
  if (inserted) {
    pattern.rows.push_back(row);
    pattern.cols.push_back(col);
  }
  return it->second;
}

}  // namespace

int ElementNlp::AddVariable(double initial, double lower, double upper, double scale) {
  if (finalized_) throw std::logic_error("ElementNlp: AddVariable after Finalize");
  if (!(scale > 0.0)) throw std::invalid_argument("ElementNlp: variable scale must be > 0");
  x0_.push_back(initial);
  x_lower_.push_back(lower);
  x_upper_.push_back(upper);
  x_scale_.push_back(scale);
  return static_cast<int>(x0_.size()) - 1;
}

int ElementNlp::AddConstraint(double lower, double upper, double scale) {
  if (finalized_) throw std::logic_error("ElementNlp: AddConstraint after Finalize");
  if (!(scale > 0.0)) throw std::invalid_argument("ElementNlp: row scale must be > 0");
  g_lower_.push_back(lower);
  g_upper_.push_back(upper);
  g_scale_.push_back(scale);
  return static_cast<int>(g_lower_.size()) - 1;
}

void ElementNlp::AddLinear(int row, int var, double coefficient) {
  if (finalized_) throw std::logic_error("ElementNlp: AddLinear after Finalize");
  linear_.push_back({row, var, coefficient});
}

void ElementNlp::AddObjectiveLinear(int var, double coefficient) {
  objective_linear_.emplace_back(var, coefficient);
}

void ElementNlp::AddElement(std::shared_ptr<const Element> element, std::vector<int> inputs,
                            std::vector<std::vector<Target>> targets) {
  if (finalized_) throw std::logic_error("ElementNlp: AddElement after Finalize");
  if (static_cast<int>(inputs.size()) != element->inputs() ||
      static_cast<int>(targets.size()) != element->outputs()) {
    throw std::invalid_argument("ElementNlp: inputs or targets do not match the element");
  }
  max_inputs_ = std::max(max_inputs_, element->inputs());
  max_outputs_ = std::max(max_outputs_, element->outputs());
  instances_.push_back({std::move(element), std::move(inputs), std::move(targets), {}, {}});
}

void ElementNlp::Finalize() {
  std::unordered_map<std::uint64_t, int> jac_index, hess_index;
  linear_slots_.clear();
  for (const LinearTerm& t : linear_) {
    linear_slots_.push_back(Slot(jac_index, jac_pattern_, t.row, t.var));
  }
  for (Instance& inst : instances_) {
    const int n = static_cast<int>(inst.inputs.size());
    inst.jac_slots.clear();
    for (const auto& targets : inst.targets) {
      for (const Target& t : targets) {
        for (int i = 0; i < n; ++i) {
          inst.jac_slots.push_back(t.row == Target::kObjective
                                       ? -1
                                       : Slot(jac_index, jac_pattern_, t.row, inst.inputs[i]));
        }
      }
    }
    inst.hess_slots.assign(static_cast<size_t>(n * n), -1);
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        const int vi = inst.inputs[i], vj = inst.inputs[j];
        // d2L / dx_a dx_b (a > b) sums H_ij over inputs i reading a and j reading b; the diagonal
        // d2L / dx_a^2 sums every (i, j) reading a, in both orders.
        if (vi >= vj) {
          inst.hess_slots[i * n + j] = Slot(hess_index, hess_pattern_, vi, vj);
        }
      }
    }
  }
  finalized_ = true;
}

template <class Accumulate>
void ElementNlp::AccumulateInstances(double* out, size_t size, const Accumulate& accumulate) const {
  const size_t count = instances_.size();
  const size_t parts = std::min<size_t>(static_cast<size_t>(threads_), std::max<size_t>(count, 1));
  const auto run = [&](size_t part, double* into) {
    Scratch scratch{std::vector<double>(max_inputs_), std::vector<double>(max_outputs_),
                    std::vector<double>(static_cast<size_t>(max_inputs_ * max_outputs_)),
                    std::vector<double>(static_cast<size_t>(max_inputs_ * max_inputs_))};
    // Every parts-th instance: each part gets its share of every kind of element (they are
    // added kind by kind, and the tyre and thermal ones cost most).
    for (size_t i = part; i < count; i += parts) accumulate(instances_[i], into, scratch);
  };
  if (parts <= 1) {
    run(0, out);
    return;
  }
  // Part 0 on this thread into `out`, the others into buffers of their own, added in order.
  std::vector<std::vector<double>> buffers(parts - 1, std::vector<double>(size, 0.0));
  std::vector<std::exception_ptr> errors(parts);
  const auto run_part = [&](size_t p) {
    try {
      run(p, p == 0 ? out : buffers[p - 1].data());
    } catch (...) {
      errors[p] = std::current_exception();
    }
  };
  std::vector<std::thread> workers;
  workers.reserve(parts - 1);  // no reallocation while threads are being added
  size_t started = 1;
  try {
    for (; started < parts; ++started) workers.emplace_back(run_part, started);
  } catch (const std::system_error&) {
    // No more threads to be had (a process or system limit): this thread does the rest, into
    // the same buffers, so the values are the same.
  }
  run_part(0);
  for (size_t p = started; p < parts; ++p) run_part(p);
  for (std::thread& w : workers) w.join();
  for (const std::exception_ptr& e : errors) {
    if (e) std::rethrow_exception(e);
  }
  for (const std::vector<double>& b : buffers) {
    for (size_t k = 0; k < size; ++k) out[k] += b[k];
  }
}

double ElementNlp::Objective(const std::vector<double>& x) const {
  double f = 0.0;
  for (const auto& [var, c] : objective_linear_) f += c * x[var];
  std::vector<double> in(max_inputs_), out(max_outputs_);
  for (const Instance& inst : instances_) {
    bool touches = false;
    for (const auto& targets : inst.targets) {
      for (const Target& t : targets) touches = touches || t.row == Target::kObjective;
    }
    if (!touches) continue;
    for (size_t i = 0; i < inst.inputs.size(); ++i) in[i] = x[inst.inputs[i]];
    inst.element->Values(in.data(), out.data());
    for (size_t o = 0; o < inst.targets.size(); ++o) {
      for (const Target& t : inst.targets[o]) {
        if (t.row == Target::kObjective) f += t.coefficient * out[o];
      }
    }
  }
  return f;
}

std::vector<double> ElementNlp::Constraints(const std::vector<double>& x) const {
  std::vector<double> g(g_lower_.size(), 0.0);
  for (const LinearTerm& t : linear_) g[t.row] += t.coefficient * x[t.var];
  AccumulateInstances(g.data(), g.size(), [&](const Instance& inst, double* into, Scratch& s) {
    for (size_t i = 0; i < inst.inputs.size(); ++i) s.in[i] = x[inst.inputs[i]];
    inst.element->Values(s.in.data(), s.out.data());
    for (size_t o = 0; o < inst.targets.size(); ++o) {
      for (const Target& t : inst.targets[o]) {
        if (t.row != Target::kObjective) into[t.row] += t.coefficient * s.out[o];
      }
    }
  });
  return g;
}

void ElementNlp::ScaledBounds(double* y_lower, double* y_upper, double* g_lower,
                              double* g_upper) const {
  for (size_t i = 0; i < x0_.size(); ++i) {
    y_lower[i] = x_lower_[i] / x_scale_[i];
    y_upper[i] = x_upper_[i] / x_scale_[i];
  }
  for (size_t r = 0; r < g_lower_.size(); ++r) {
    g_lower[r] = g_lower_[r] / g_scale_[r];
    g_upper[r] = g_upper_[r] / g_scale_[r];
  }
}

void ElementNlp::ScaledStart(double* y) const {
  for (size_t i = 0; i < x0_.size(); ++i) y[i] = x0_[i] / x_scale_[i];
}

std::vector<double> ElementNlp::Unscale(const double* y) const {
  std::vector<double> x(x0_.size());
  for (size_t i = 0; i < x.size(); ++i) x[i] = y[i] * x_scale_[i];
  return x;
}

double ElementNlp::ScaledObjective(const double* y) const {
  return Objective(Unscale(y)) / objective_scale_;
}

void ElementNlp::ScaledObjectiveGradient(const double* y, double* grad) const {
  const std::vector<double> x = Unscale(y);
  std::fill(grad, grad + x.size(), 0.0);
  for (const auto& [var, c] : objective_linear_) grad[var] += c;
  std::vector<double> in(max_inputs_), out(max_outputs_),
      jac(static_cast<size_t>(max_inputs_ * max_outputs_));
  for (const Instance& inst : instances_) {
    bool touches = false;
    for (const auto& targets : inst.targets) {
      for (const Target& t : targets) touches = touches || t.row == Target::kObjective;
    }
    if (!touches) continue;
    const int n = static_cast<int>(inst.inputs.size());
    for (int i = 0; i < n; ++i) in[i] = x[inst.inputs[i]];
    inst.element->Jacobian(in.data(), out.data(), jac.data());
    for (size_t o = 0; o < inst.targets.size(); ++o) {
      for (const Target& t : inst.targets[o]) {
        if (t.row != Target::kObjective) continue;
        for (int i = 0; i < n; ++i) grad[inst.inputs[i]] += t.coefficient * jac[o * n + i];
      }
    }
  }
  for (size_t i = 0; i < x.size(); ++i) grad[i] *= x_scale_[i] / objective_scale_;
}

void ElementNlp::ScaledConstraints(const double* y, double* g) const {
  const std::vector<double> values = Constraints(Unscale(y));
  for (size_t r = 0; r < values.size(); ++r) g[r] = values[r] / g_scale_[r];
}

void ElementNlp::ScaledJacobian(const double* y, double* values) const {
  const std::vector<double> x = Unscale(y);
  std::fill(values, values + jac_pattern_.rows.size(), 0.0);
  for (size_t k = 0; k < linear_.size(); ++k) values[linear_slots_[k]] += linear_[k].coefficient;
  AccumulateInstances(values, jac_pattern_.rows.size(),
                      [&](const Instance& inst, double* into, Scratch& s) {
                        const int n = static_cast<int>(inst.inputs.size());
                        for (int i = 0; i < n; ++i) s.in[i] = x[inst.inputs[i]];
                        inst.element->Jacobian(s.in.data(), s.out.data(), s.jac.data());
                        size_t k = 0;
                        for (size_t o = 0; o < inst.targets.size(); ++o) {
                          for (const Target& t : inst.targets[o]) {
                            for (int i = 0; i < n; ++i, ++k) {
                              if (inst.jac_slots[k] >= 0) {
                                into[inst.jac_slots[k]] += t.coefficient * s.jac[o * n + i];
                              }
                            }
                          }
                        }
                      });
  for (size_t k = 0; k < jac_pattern_.rows.size(); ++k) {
    values[k] *= x_scale_[jac_pattern_.cols[k]] / g_scale_[jac_pattern_.rows[k]];
  }
}

void ElementNlp::ClipNegativeCurvature(const Instance& inst, int n, double* hess) const {
  // In the scaled variables (D H D, D the inputs' scales), where the solver measures curvature.
  Eigen::Map<Eigen::MatrixXd> h(hess, n, n);
  Eigen::VectorXd d(n);
  for (int i = 0; i < n; ++i) d[i] = x_scale_[inst.inputs[i]];
  const Eigen::MatrixXd scaled = d.asDiagonal() * (0.5 * (h + h.transpose())) * d.asDiagonal();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(scaled);
  if (eig.info() != Eigen::Success || eig.eigenvalues().minCoeff() >= 0.0) return;
  const Eigen::VectorXd clipped = eig.eigenvalues().cwiseMax(0.0);
  const Eigen::MatrixXd convex =
      eig.eigenvectors() * clipped.asDiagonal() * eig.eigenvectors().transpose();
  h = d.cwiseInverse().asDiagonal() * convex * d.cwiseInverse().asDiagonal();
}

void ElementNlp::ScaledHessian(const double* y, double sigma, const double* lambda,
                               double* values) const {
  const std::vector<double> x = Unscale(y);
  std::fill(values, values + hess_pattern_.rows.size(), 0.0);
  AccumulateInstances(
      values, hess_pattern_.rows.size(), [&](const Instance& inst, double* into, Scratch& s) {
        const int n = static_cast<int>(inst.inputs.size());
        bool any = false;
        for (size_t o = 0; o < inst.targets.size(); ++o) {
          double w = 0.0;
          for (const Target& t : inst.targets[o]) {
            w += t.coefficient * (t.row == Target::kObjective ? sigma / objective_scale_
                                                              : lambda[t.row] / g_scale_[t.row]);
          }
          s.out[o] = w;  // the outputs' weights
          any = any || w != 0.0;
        }
        if (!any) return;
        for (int i = 0; i < n; ++i) s.in[i] = x[inst.inputs[i]];
        inst.element->Hessian(s.in.data(), s.out.data(), s.hess.data());
        if (convex_element_hessians_) ClipNegativeCurvature(inst, n, s.hess.data());
        for (int k = 0; k < n * n; ++k) {
          if (inst.hess_slots[k] >= 0) into[inst.hess_slots[k]] += s.hess[k];
        }
      });
  for (size_t k = 0; k < hess_pattern_.rows.size(); ++k) {
    values[k] *= x_scale_[hess_pattern_.rows[k]] * x_scale_[hess_pattern_.cols[k]];
  }
}

}  // namespace hotlap::ocp
