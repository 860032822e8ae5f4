// The transcription and the solver on problems with known optima: the minimum time of a double
// integrator (bang-bang, T = 2), minimum control energy (u = 6 - 12 t, J = 12) with the
// trapezoidal rule's second-order convergence, and an infeasible problem reported as such.

#include "hotlap/ocp/ipopt_solve.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"

namespace hotlap::ocp {
namespace {

// SCOTCH_PTHREAD_NUMBER as the test process found it, before any solve ("" if unset).
const std::string kScotchThreadsAtStart = [] {
  const char* value = std::getenv("SCOTCH_PTHREAD_NUMBER");
  return std::string(value ? value : "");
}();

// h/2 (a + b) with h = T / N: the trapezoid of a rate over one interval of a free final time.
struct FreeTimeTrapezoid {
  double intervals;
  template <class T>
  void operator()(const T* in, T* out) const {
    out[0] = 0.5 * in[0] / intervals * (in[1] + in[2]);
  }
};

// Minimum time to move a double integrator x'' = u, |u| <= u_max, from rest at 0 to rest at 1:
// accelerate for half the time and brake for the other half, T = 2 / sqrt(u_max).
struct DoubleIntegrator {
  ElementNlp nlp;
  int t = 0;           // the final time's variable
  std::vector<int> u;  // the control's, per node
};

DoubleIntegrator MakeDoubleIntegrator(int n, double u_max) {
  DoubleIntegrator d;
  ElementNlp& nlp = d.nlp;
  const int t = d.t = nlp.AddVariable(3.0, 0.1, 10.0, 1.0);
  std::vector<int> x(n + 1), v(n + 1), &u = d.u;
  u.resize(n + 1);
  for (int k = 0; k <= n; ++k) {
    const double s = static_cast<double>(k) / n;
    const bool end = k == 0 || k == n;
    x[k] = nlp.AddVariable(s, end ? s : -1e19, end ? s : 1e19, 1.0);
    v[k] = nlp.AddVariable(0.5, end ? 0.0 : -1e19, end ? 0.0 : 1e19, 1.0);
    u[k] = nlp.AddVariable(0.0, -u_max, u_max, 1.0);
  }
  const std::shared_ptr<const Element> trap = MakeElement<3, 1>(FreeTimeTrapezoid{double(n)});
  for (int k = 0; k < n; ++k) {
    const int rx = nlp.AddConstraint(0, 0, 1.0), rv = nlp.AddConstraint(0, 0, 1.0);
    nlp.AddLinear(rx, x[k + 1], 1.0);
    nlp.AddLinear(rx, x[k], -1.0);
    nlp.AddElement(trap, {t, v[k], v[k + 1]}, {{{rx, -1.0}}});
    nlp.AddLinear(rv, v[k + 1], 1.0);
    nlp.AddLinear(rv, v[k], -1.0);
    nlp.AddElement(trap, {t, u[k], u[k + 1]}, {{{rv, -1.0}}});
  }
  nlp.AddObjectiveLinear(t, 1.0);
  nlp.Finalize();
  return d;
}

// |u| <= 1: T = 2.
TEST(IpoptSolveTest, DoubleIntegratorMinimumTimeIsBangBang) {
  const int n = 40;
  const DoubleIntegrator d = MakeDoubleIntegrator(n, 1.0);
  const SolveResult r = SolveWithIpopt(d.nlp, {});
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_NEAR(r.x[d.t], 2.0, 2.0 / n);
  // Full throttle in the first half, full brake in the second (away from the switch).
  for (int k = 2; k < n / 2 - 2; ++k) EXPECT_NEAR(r.x[d.u[k]], 1.0, 1e-4) << k;
  for (int k = n / 2 + 3; k <= n - 2; ++k) EXPECT_NEAR(r.x[d.u[k]], -1.0, 1e-4) << k;
}

// A warm start from a neighbouring problem's point and multipliers (as the limited lap starts
// from the free one) reaches the same optimum as a cold start, in fewer iterations; multipliers
// of the wrong size are ignored (a cold start).
TEST(IpoptSolveTest, WarmStartFromANeighbourConvergesFaster) {
  const int n = 40;
  const DoubleIntegrator d1 = MakeDoubleIntegrator(n, 1.0);
  const ElementNlp& first = d1.nlp;
  const int t = d1.t;
  const SolveResult a = SolveWithIpopt(first, {});
  ASSERT_TRUE(a.ok()) << a.message;
  ASSERT_EQ(a.z_lower.size(), static_cast<size_t>(first.variables()));
  ASSERT_EQ(a.lambda.size(), static_cast<size_t>(first.constraints()));

  DoubleIntegrator d2 = MakeDoubleIntegrator(n, 0.8);
  ElementNlp& tighter = d2.nlp;
  const SolveResult cold = SolveWithIpopt(tighter, {});
  for (int i = 0; i < tighter.variables(); ++i) {
    tighter.set_initial(i, std::clamp(a.x[i], tighter.lower(i), tighter.upper(i)));
  }
  IpoptOptions warm;
  warm.warm_z_lower = a.z_lower;
  warm.warm_z_upper = a.z_upper;
  warm.warm_lambda = a.lambda;
  const SolveResult w = SolveWithIpopt(tighter, warm);
  ASSERT_TRUE(cold.ok()) << cold.message;
  ASSERT_TRUE(w.ok()) << w.message;
  EXPECT_NEAR(w.x[t], 2.0 / std::sqrt(0.8), 2.0 / n);
  EXPECT_NEAR(w.x[t], cold.x[t], 1e-6);
  EXPECT_LT(w.iterations, cold.iterations);

  IpoptOptions wrong = warm;
  wrong.warm_lambda.pop_back();
  const SolveResult ignored = SolveWithIpopt(tighter, wrong);
  ASSERT_TRUE(ignored.ok()) << ignored.message;
  EXPECT_NEAR(ignored.x[t], cold.x[t], 1e-6);
  // The multipliers are what the warm start adds over the point alone (here 4 iterations against
  // 5 from the point alone and 8 cold).
  EXPECT_LT(w.iterations, ignored.iterations);

  // The point alone with a small first barrier (IpoptOptions::primal_start_mu, coarse to fine):
  // the same solution, in no more iterations than Ipopt's mu_init 0.1 from the same point (on the
  // lap it is far fewer: CoarseToFineTest).
  IpoptOptions primal;
  primal.primal_start_mu = 1e-4;
  const SolveResult p = SolveWithIpopt(tighter, primal);
  ASSERT_TRUE(p.ok()) << p.message;
  EXPECT_NEAR(p.x[t], cold.x[t], 1e-6);
  EXPECT_LE(p.iterations, ignored.iterations);
}

// Checkpoints are iterates a solve can resume from: the one taken at the last iteration is the
// result's point and multipliers (so the unscaling and reordering are Ipopt's own, here with the
// objective scaled by Ipopt and the fixed ends removed by it), and a warm start from one in the
// middle reaches the same optimum in no more iterations than the solve had left, plus a few.
TEST(IpoptSolveTest, CheckpointsAreIteratesToResumeFrom) {
  const int n = 40;
  const DoubleIntegrator d = MakeDoubleIntegrator(n, 1.0);
  std::vector<SolveResult> saved;
  IpoptOptions o;
  o.extra = {{"obj_scaling_factor", "7.5"}};
  o.checkpoint_every = 1;
  o.on_checkpoint = [&](const SolveResult& c) { saved.push_back(c); };
  const SolveResult r = SolveWithIpopt(d.nlp, o);
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_GE(saved.size(), 4u);
  const SolveResult& last = saved.back();
  EXPECT_EQ(last.iterations, r.iterations);
  EXPECT_EQ(last.status, SolveStatus::kStopped);
  EXPECT_GT(last.barrier_mu, 0.0);
  ASSERT_EQ(last.x.size(), r.x.size());
  ASSERT_EQ(last.lambda.size(), r.lambda.size());
  const auto near = [](double a, double b) {
    return std::abs(a - b) <= 1e-9 * (1.0 + std::abs(b));
  };
  for (size_t i = 0; i < r.x.size(); ++i) {
    // Ipopt ends by putting x back inside the original bounds, which it had relaxed by 1e-8
    // (bound_relax_factor), so a point on a bound moves by that much; the multipliers do not.
    EXPECT_NEAR(last.x[i], r.x[i], 2e-8 * (1.0 + std::abs(r.x[i]))) << "x " << i;
    if (d.nlp.lower(static_cast<int>(i)) < d.nlp.upper(static_cast<int>(i))) {  // not fixed
      EXPECT_TRUE(near(last.z_lower[i], r.z_lower[i])) << "z_L " << i;
      EXPECT_TRUE(near(last.z_upper[i], r.z_upper[i])) << "z_U " << i;
    }
  }
  double largest_lambda = 0.0;
  for (size_t i = 0; i < r.lambda.size(); ++i) {
    EXPECT_TRUE(near(last.lambda[i], r.lambda[i])) << "lambda " << i;
    largest_lambda = std::max(largest_lambda, std::abs(r.lambda[i]));
  }
  EXPECT_GT(largest_lambda, 1e-3);  // the comparison above compared something

  const SolveResult& mid = saved[saved.size() / 2];
  DoubleIntegrator again = MakeDoubleIntegrator(n, 1.0);
  for (int i = 0; i < again.nlp.variables(); ++i) again.nlp.set_initial(i, mid.x[i]);
  IpoptOptions resume;
  resume.extra = o.extra;
  resume.warm_z_lower = mid.z_lower;
  resume.warm_z_upper = mid.z_upper;
  resume.warm_lambda = mid.lambda;
  resume.warm_mu = mid.barrier_mu;
  const SolveResult w = SolveWithIpopt(again.nlp, resume);
  ASSERT_TRUE(w.ok()) << w.message;
  EXPECT_NEAR(w.x[d.t], r.x[d.t], 1e-6);
  EXPECT_LE(w.iterations, r.iterations - mid.iterations + 3)
      << "resumed at " << mid.iterations << " of " << r.iterations;
}

struct HalfSquareTrapezoid {
  double h;
  template <class T>
  void operator()(const T* in, T* out) const {
    out[0] = 0.5 * h * (in[0] * in[0] + in[1] * in[1]);
  }
};

struct FixedTrapezoid {
  double h;
  template <class T>
  void operator()(const T* in, T* out) const {
    out[0] = 0.5 * h * (in[0] + in[1]);
  }
};

// min int u^2 dt over [0, 1], x'' = u, rest to rest from 0 to 1: u = 6 - 12 t, J = 12. The
// trapezoidal transcription's error falls as h^2.
double MinimumEnergy(int n, double* u_mid_error) {
  ElementNlp nlp;
  const double h = 1.0 / n;
  std::vector<int> x(n + 1), v(n + 1), u(n + 1);
  for (int k = 0; k <= n; ++k) {
    const bool end = k == 0 || k == n;
    x[k] = nlp.AddVariable(0.0, end ? (k == 0 ? 0.0 : 1.0) : -1e19,
                           end ? (k == 0 ? 0.0 : 1.0) : 1e19, 1.0);
    v[k] = nlp.AddVariable(0.0, end ? 0.0 : -1e19, end ? 0.0 : 1e19, 1.0);
    u[k] = nlp.AddVariable(0.0, -1e19, 1e19, 10.0);
  }
  const std::shared_ptr<const Element> trap = MakeElement<2, 1>(FixedTrapezoid{h});
  const std::shared_ptr<const Element> cost = MakeElement<2, 1>(HalfSquareTrapezoid{h});
  for (int k = 0; k < n; ++k) {
    const int rx = nlp.AddConstraint(0, 0, 1.0), rv = nlp.AddConstraint(0, 0, 1.0);
    nlp.AddLinear(rx, x[k + 1], 1.0);
    nlp.AddLinear(rx, x[k], -1.0);
    nlp.AddElement(trap, {v[k], v[k + 1]}, {{{rx, -1.0}}});
    nlp.AddLinear(rv, v[k + 1], 1.0);
    nlp.AddLinear(rv, v[k], -1.0);
    nlp.AddElement(trap, {u[k], u[k + 1]}, {{{rv, -1.0}}});
    nlp.AddElement(cost, {u[k], u[k + 1]}, {{{Target::kObjective, 1.0}}});
  }
  nlp.Finalize();
  IpoptOptions options;
  options.tolerance = 1e-10;
  const SolveResult r = SolveWithIpopt(nlp, options);
  EXPECT_TRUE(r.ok()) << r.message;
  *u_mid_error = std::abs(r.x[u[n / 2]] - 0.0);
  return r.objective;
}

TEST(IpoptSolveTest, MinimumEnergyConvergesAtSecondOrder) {
  double e1 = 0, e2 = 0;
  const double j20 = MinimumEnergy(20, &e1);
  const double j40 = MinimumEnergy(40, &e2);
  EXPECT_NEAR(j20, 12.0, 0.15);
  EXPECT_NEAR(j40, 12.0, 0.04);
  const double ratio = std::abs(j20 - 12.0) / std::abs(j40 - 12.0);
  EXPECT_GT(ratio, 3.5);  // 4 for second order
  EXPECT_LT(ratio, 4.5);
  EXPECT_LT(e2, 1e-6);  // u(1/2) = 0 by symmetry
}

// x in [0, 1] with x >= 2 imposed as a row: reported as infeasible, not as a crash.
struct Identity {
  template <class T>
  void operator()(const T* in, T* out) const {
    out[0] = in[0] * in[0];
  }
};

TEST(IpoptSolveTest, InfeasibleProblemSaysSo) {
  ElementNlp nlp;
  const int x = nlp.AddVariable(0.5, 0.0, 1.0, 1.0);
  const int r = nlp.AddConstraint(2.0, 1e19, 1.0);
  nlp.AddElement(MakeElement<1, 1>(Identity{}), {x}, {{{r, 1.0}}});
  nlp.AddObjectiveLinear(x, 1.0);
  nlp.Finalize();
  const SolveResult res = SolveWithIpopt(nlp, {});
  EXPECT_FALSE(res.ok());
  EXPECT_EQ(res.status, SolveStatus::kInfeasible) << res.message;
  EXPECT_NE(res.message.find("cannot all be met"), std::string::npos);
  EXPECT_EQ(res.x.size(), 1u);
}

// (x - 0.3)^2 times a sign: a bowl (convex) or a cap (negative curvature).
struct Parabola {
  double sign;
  template <class T>
  void operator()(const T* in, T* out) const {
    out[0] = sign * (in[0] - 0.3) * (in[0] - 0.3);
  }
};

// Iterations with an inertia correction: none on a convex problem; on a cap over [0, 1] whose
// maximum is inside (its minimum at the far bound x = 1), Ipopt has to perturb the negative
// Hessian before its first steps.
TEST(IpoptSolveTest, CountsTheIterationsThatNeededAnInertiaCorrection) {
  for (const double sign : {1.0, -1.0}) {
    ElementNlp nlp;
    const int x = nlp.AddVariable(0.35, 0.0, 1.0, 1.0);
    nlp.AddElement(MakeElement<1, 1>(Parabola{sign}), {x}, {{{Target::kObjective, 1.0}}});
    nlp.Finalize();
    const SolveResult res = SolveWithIpopt(nlp, {});
    ASSERT_TRUE(res.ok()) << res.message;
    EXPECT_NEAR(res.x[0], sign > 0 ? 0.3 : 1.0, 1e-6);
    EXPECT_LE(res.regularized_iterations, res.iterations);
    if (sign > 0) {
      EXPECT_EQ(res.regularized_iterations, 0);
    } else {
      EXPECT_GT(res.regularized_iterations, 0);
    }
  }
}

// min x over 0 <= x <= 1 from 0.5: the smallest problem Ipopt can be handed options for.
void MakeLowerBoundProblem(ElementNlp& nlp) {
  const int x = nlp.AddVariable(0.5, 0.0, 1.0, 1.0);
  nlp.AddObjectiveLinear(x, 1.0);
  nlp.Finalize();
}

// Extra options reach Ipopt by their type; one it does not know, or a value it refuses, is bad
// input that names the option, not a solve quietly run without it.
TEST(IpoptSolveTest, ExtraOptionsAreCheckedByIpopt) {
  ElementNlp nlp;
  MakeLowerBoundProblem(nlp);
  IpoptOptions o;
  o.extra = {{"mumps_pivot_order", "5"}, {"mu_init", "1"}, {"mu_strategy", "monotone"}};
  EXPECT_TRUE(SolveWithIpopt(nlp, o).ok());
  for (const auto& bad :
       {std::pair<std::string, std::string>{"no_such_option", "1"}, {"mu_strategy", "sideways"}}) {
    o.extra = {bad};
    try {
      SolveWithIpopt(nlp, o);
      ADD_FAILURE() << bad.first << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(bad.first), std::string::npos) << e.what();
    }
  }
}

// SCOTCH (MUMPS' ordering 3) orders on one thread after a solve, so that solves ordered by it are
// the same bit for bit from run to run (its threaded ordering is not; ipopt_solve.cc); a value
// the user set is left alone.
TEST(IpoptSolveTest, ScotchOrdersOnOneThreadUnlessTheUserSaysOtherwise) {
  ElementNlp nlp;
  MakeLowerBoundProblem(nlp);
  IpoptOptions o;
  o.extra = {{"mumps_pivot_order", "3"}};
  EXPECT_TRUE(SolveWithIpopt(nlp, o).ok());
  const char* now = std::getenv("SCOTCH_PTHREAD_NUMBER");
  ASSERT_NE(now, nullptr);
  EXPECT_EQ(std::string(now), kScotchThreadsAtStart.empty() ? "1" : kScotchThreadsAtStart);
}

}  // namespace
}  // namespace hotlap::ocp
