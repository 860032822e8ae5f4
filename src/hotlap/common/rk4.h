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

namespace hotlap {

/// The same step when the right-hand side depends on time only through an input known at the
/// step's start, middle and end: `f(x, input)`. Lets a caller compute each input once (the two
/// middle stages share one, and a step's end is the next step's start).
template <class State, class Input, class F>
State Rk4StepWithInputs(F&& f, const State& x, double h, const Input& at_start,
                        const Input& at_middle, const Input& at_end) {
  const State k1 = f(x, at_start);
  const State k2 = f(x + (0.5 * h) * k1, at_middle);
  const State k3 = f(x + (0.5 * h) * k2, at_middle);
  const State k4 = f(x + h * k3, at_end);
  return x + (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
}

}  // namespace hotlap
