#pragma once
/// @file
/// An element: a small function of a few variables of a nonlinear programme, differentiated
/// exactly, once and twice, by forward-mode automatic differentiation (ceres::Jet for first
/// derivatives, hotlap::SecondOrder for second).
///
/// Why elements: the optimal-control problems here are "lifted": every intermediate quantity
/// that many equations share (a tyre's forces, its slip angle, dt/ds, the total forces) is a
/// variable of the programme with an equation of its own, so that every equation is a function of
/// a handful of variables. A full node of the lap problem has about 60 variables; a dense nested
/// forward-mode Hessian of it would cost (60 + 1)^2 times the function per operation, while its
/// elements have 2 to 12 inputs each (docs/validation/optimal-control.md has the benchmark that chose this).
///
/// How to use: write a functor with a templated call operator on arrays,
///
///   struct Drag {
///     double cda;
///     template <class T> void operator()(const T* in, T* out) const {
///       out[0] = 0.5 * 1.2 * cda * in[0] * in[0];
///     }
///   };
///
/// and wrap it: `MakeElement<1, 1>(Drag{0.8})`. The functor must be a pure function of its
/// inputs, written with the scalar-templated models (use `using std::sin;` etc. so that Jets find
/// their overloads) and must branch only on ValueOf() of its inputs.

#include <array>
#include <memory>

#include <ceres/jet.h>

#include "hotlap/common/scalar.h"
#include "hotlap/common/second_order.h"

namespace hotlap::ocp {

/// The type-erased interface the programme holds.
class Element {
 public:
  virtual ~Element() = default;
  virtual int inputs() const = 0;
  virtual int outputs() const = 0;
  /// out[outputs()] = f(in).
  virtual void Values(const double* in, double* out) const = 0;
  /// out as Values, and jac[o * inputs() + i] = d out_o / d in_i.
  virtual void Jacobian(const double* in, double* out, double* jac) const = 0;
  /// hess[i * inputs() + j] = sum_o weight_o d^2 out_o / (d in_i d in_j), full and symmetric.
  virtual void Hessian(const double* in, const double* weights, double* hess) const = 0;
};

template <int kInputs, int kOutputs, class Functor>
class ElementOf final : public Element {
 public:
  explicit ElementOf(Functor f) : f_(std::move(f)) {}
  int inputs() const override { return kInputs; }
  int outputs() const override { return kOutputs; }

  void Values(const double* in, double* out) const override { f_(in, out); }

  void Jacobian(const double* in, double* out, double* jac) const override {
    using J = ceres::Jet<double, kInputs>;
    std::array<J, kInputs> x;
    for (int i = 0; i < kInputs; ++i) x[i] = J(in[i], i);
    std::array<J, kOutputs> y;
    f_(x.data(), y.data());
    for (int o = 0; o < kOutputs; ++o) {
      out[o] = y[o].a;
      for (int i = 0; i < kInputs; ++i) jac[o * kInputs + i] = y[o].v[i];
    }
  }

  void Hessian(const double* in, const double* weights, double* hess) const override {
    using S = SecondOrder<kInputs>;
    std::array<S, kInputs> x;
    for (int i = 0; i < kInputs; ++i) x[i] = S::Variable(in[i], i);
    std::array<S, kOutputs> y;
    f_(x.data(), y.data());
    for (int k = 0; k < kInputs * kInputs; ++k) hess[k] = 0.0;
    for (int o = 0; o < kOutputs; ++o) {
      const double w = weights[o];
      if (w == 0.0) continue;
      for (int i = 0; i < kInputs; ++i) {
        for (int j = 0; j <= i; ++j) {
          const double hij = w * y[o].h[i * (i + 1) / 2 + j];
          hess[i * kInputs + j] += hij;
          if (i != j) hess[j * kInputs + i] += hij;
        }
      }
    }
  }

 private:
  Functor f_;
};

/// Wraps `f` (see the file comment) as an element with kInputs inputs and kOutputs outputs.
template <int kInputs, int kOutputs, class Functor>
std::unique_ptr<Element> MakeElement(Functor f) {
  return std::make_unique<ElementOf<kInputs, kOutputs, Functor>>(std::move(f));
}

}  // namespace hotlap::ocp
