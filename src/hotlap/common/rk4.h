#pragma once
/// @file
/// The classical fourth-order Runge-Kutta step, for any state type with `a + b` and `double * a`
/// (the model state structs provide both). Fourth order in the step for smooth right-hand sides;
/// tests/common/rk4_test.cc shows the order.

namespace hotlap {

/// One step of size h from (t, x): `f(t, x)` returns dx/dt.
template <class State, class F>
State Rk4Step(F&& f, double t, const State& x, double h) {
  const State k1 = f(t, x);
  const State k2 = f(t + 0.5 * h, x + (0.5 * h) * k1);
  const State k3 = f(t + 0.5 * h, x + (0.5 * h) * k2);
  const State k4 = f(t + h, x + h * k3);
  return x + (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
}

}  // namespace hotlap
