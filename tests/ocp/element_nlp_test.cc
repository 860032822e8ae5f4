#include "hotlap/ocp/element_nlp.h"

#include <cmath>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Dense>

namespace hotlap::ocp {
namespace {

// f(a, b, c) = (a sin(b) + c^2 a, exp(a b) / (1 + c^2)).
struct Wiggle {
  template <class T>
  void operator()(const T* in, T* out) const {
    using std::exp;
    using std::sin;
    out[0] = in[0] * sin(in[1]) + in[2] * in[2] * in[0];
    out[1] = exp(in[0] * in[1]) / (1.0 + in[2] * in[2]);
  }
};

TEST(ElementTest, DerivativesMatchCentralDifferences) {
  const auto e = MakeElement<3, 2>(Wiggle{});
  const double x[3] = {0.7, -0.4, 1.3};
  double out[2], jac[6];
  e->Jacobian(x, out, jac);
  const double h = 1e-6;
  for (int i = 0; i < 3; ++i) {
    double xp[3] = {x[0], x[1], x[2]}, xm[3] = {x[0], x[1], x[2]};
    xp[i] += h;
    xm[i] -= h;
    double op[2], om[2];
    e->Values(xp, op);
    e->Values(xm, om);
    for (int o = 0; o < 2; ++o) EXPECT_NEAR(jac[o * 3 + i], (op[o] - om[o]) / (2 * h), 1e-8);
  }
  // Weighted Hessian against differences of the Jacobian.
  const double w[2] = {0.3, -1.7};
  double hess[9];
  e->Hessian(x, w, hess);
  for (int i = 0; i < 3; ++i) {
    double xp[3] = {x[0], x[1], x[2]}, xm[3] = {x[0], x[1], x[2]};
    xp[i] += h;
    xm[i] -= h;
    double jp[6], jm[6], o[2];
    e->Jacobian(xp, o, jp);
    e->Jacobian(xm, o, jm);
    for (int j = 0; j < 3; ++j) {
      const double fd = (w[0] * (jp[j] - jm[j]) + w[1] * (jp[3 + j] - jm[3 + j])) / (2 * h);
      EXPECT_NEAR(hess[i * 3 + j], fd, 1e-6) << i << "," << j;
      EXPECT_DOUBLE_EQ(hess[i * 3 + j], hess[j * 3 + i]);
    }
  }
}

// A programme whose element reads one variable twice and writes two rows and the objective, with
// scales: its scaled Jacobian and Hessian match finite differences of the scaled functions.
TEST(ElementNlpTest, ScaledDerivativesMatchFiniteDifferences) {
  ElementNlp nlp;
  const int a = nlp.AddVariable(0.7, -10, 10, 2.0);
  const int b = nlp.AddVariable(-0.4, -10, 10, 0.5);
  const int c = nlp.AddVariable(1.3, -10, 10, 3.0);
  const int r0 = nlp.AddConstraint(0, 0, 10.0);
  const int r1 = nlp.AddConstraint(-1, 1, 0.1);
  nlp.AddLinear(r0, c, 2.0);
  nlp.AddLinear(r1, a, -1.0);
  nlp.AddObjectiveLinear(b, 0.5);
  const std::shared_ptr<const Element> e = MakeElement<3, 2>(Wiggle{});
  nlp.AddElement(e, {a, b, a}, {{{r0, 1.5}, {Target::kObjective, 2.0}}, {{r1, -0.5}}});
  nlp.AddElement(e, {c, b, c}, {{{r1, 1.0}}, {{Target::kObjective, 1.0}}});
  nlp.SetObjectiveScale(4.0);
  nlp.Finalize();
  const int n = nlp.variables(), m = nlp.constraints();
  std::vector<double> y(n);
  nlp.ScaledStart(y.data());
  const double h = 1e-6;
  // Gradient.
  std::vector<double> grad(n);
  nlp.ScaledObjectiveGradient(y.data(), grad.data());
  // Jacobian (dense from the pattern).
  std::vector<double> jv(nlp.JacobianPattern().rows.size());
  nlp.ScaledJacobian(y.data(), jv.data());
  std::vector<double> jac(m * n, 0.0);
  for (size_t k = 0; k < jv.size(); ++k) {
    jac[nlp.JacobianPattern().rows[k] * n + nlp.JacobianPattern().cols[k]] += jv[k];
  }
  for (int i = 0; i < n; ++i) {
    std::vector<double> yp = y, ym = y;
    yp[i] += h;
    ym[i] -= h;
    EXPECT_NEAR(grad[i],
                (nlp.ScaledObjective(yp.data()) - nlp.ScaledObjective(ym.data())) / (2 * h), 1e-7);
    std::vector<double> gp(m), gm(m);
    nlp.ScaledConstraints(yp.data(), gp.data());
    nlp.ScaledConstraints(ym.data(), gm.data());
    for (int r = 0; r < m; ++r) EXPECT_NEAR(jac[r * n + i], (gp[r] - gm[r]) / (2 * h), 1e-7);
  }
  // Hessian of sigma f + lambda' g against differences of the gradient of that Lagrangian.
  const double sigma = 0.8;
  const std::vector<double> lambda = {1.3, -0.6};
  const auto lagrangian_gradient = [&](const std::vector<double>& yy) {
    std::vector<double> g(n), jvals(jv.size());
    nlp.ScaledObjectiveGradient(yy.data(), g.data());
    nlp.ScaledJacobian(yy.data(), jvals.data());
    for (int i = 0; i < n; ++i) g[i] *= sigma;
    for (size_t k = 0; k < jvals.size(); ++k) {
      g[nlp.JacobianPattern().cols[k]] += lambda[nlp.JacobianPattern().rows[k]] * jvals[k];
    }
    return g;
  };
  std::vector<double> hv(nlp.HessianPattern().rows.size());
  nlp.ScaledHessian(y.data(), sigma, lambda.data(), hv.data());
  std::vector<double> hess(n * n, 0.0);
  for (size_t k = 0; k < hv.size(); ++k) {
    const int r = nlp.HessianPattern().rows[k], col = nlp.HessianPattern().cols[k];
    EXPECT_GE(r, col);
    hess[r * n + col] += hv[k];
    if (r != col) hess[col * n + r] += hv[k];
  }
  for (int i = 0; i < n; ++i) {
    std::vector<double> yp = y, ym = y;
    yp[i] += h;
    ym[i] -= h;
    const auto gp = lagrangian_gradient(yp), gm = lagrangian_gradient(ym);
    for (int j = 0; j < n; ++j) {
      EXPECT_NEAR(hess[j * n + i], (gp[j] - gm[j]) / (2 * h), 1e-6) << i << "," << j;
    }
  }
}

// The scaled Lagrangian Hessian as a dense symmetric matrix.
Eigen::MatrixXd DenseScaledHessian(const ElementNlp& nlp, const std::vector<double>& y,
                                   double sigma, const std::vector<double>& lambda) {
  const int n = nlp.variables();
  std::vector<double> hv(nlp.HessianPattern().rows.size());
  nlp.ScaledHessian(y.data(), sigma, lambda.data(), hv.data());
  Eigen::MatrixXd h = Eigen::MatrixXd::Zero(n, n);
  for (size_t k = 0; k < hv.size(); ++k) {
    const int r = nlp.HessianPattern().rows[k], c = nlp.HessianPattern().cols[k];
    h(r, c) += hv[k];
    if (r != c) h(c, r) += hv[k];
  }
  return h;
}

// Convex element Hessians: an element with negative curvature (a saddle, x y) gives its Hessian
// with the negative eigenvalue clipped in the scaled variables; one that is already convex
// (x^2 + y^2 with positive weight) is left exactly as it is.
struct Saddle {
  template <class T>
  void operator()(const T* in, T* out) const {
    out[0] = in[0] * in[1];
  }
};
struct Bowl {
  template <class T>
  void operator()(const T* in, T* out) const {
    out[0] = in[0] * in[0] + in[1] * in[1];
  }
};

TEST(ElementNlpTest, ConvexElementHessiansClipNegativeCurvatureOnly) {
  for (const bool convex : {false, true}) {
    ElementNlp nlp;
    const int a = nlp.AddVariable(0.3, -10, 10, 2.0);
    const int b = nlp.AddVariable(-0.4, -10, 10, 0.5);
    const int c = nlp.AddVariable(1.1, -10, 10, 1.0);
    nlp.AddElement(MakeElement<2, 1>(Saddle{}), {a, b}, {{{Target::kObjective, 1.0}}});
    nlp.AddElement(MakeElement<2, 1>(Bowl{}), {b, c}, {{{Target::kObjective, 1.0}}});
    nlp.SetConvexElementHessians(convex);
    nlp.Finalize();
    std::vector<double> y(3);
    nlp.ScaledStart(y.data());
    const Eigen::MatrixXd h = DenseScaledHessian(nlp, y, 1.0, {});
    // Scaled: the saddle's block is [[0, s_a s_b], [s_a s_b, 0]] = [[0, 1], [1, 0]] with
    // eigenvalues -1 and 1; clipped it is 0.5 [[1, 1], [1, 1]]. The bowl's block is
    // diag(2 s_b^2, 2 s_c^2) = diag(0.5, 2) either way.
    Eigen::Matrix3d expected;
    if (convex) {
      expected << 0.5, 0.5, 0.0, 0.5, 0.5 + 0.5, 0.0, 0.0, 0.0, 2.0;
    } else {
      expected << 0.0, 1.0, 0.0, 1.0, 0.5, 0.0, 0.0, 0.0, 2.0;
    }
    EXPECT_LT((h - expected).cwiseAbs().maxCoeff(), 1e-12) << "convex " << convex << "\n" << h;
    const double smallest = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(h).eigenvalues()[0];
    if (convex) {
      EXPECT_GE(smallest, -1e-12);
    } else {
      EXPECT_LT(smallest, 0.0);
    }
  }
}

// A chain of elements sharing variables and rows, as a lap's nodes do.
ElementNlp ChainNlp(int links, int threads) {
  ElementNlp nlp;
  std::vector<int> v;
  for (int i = 0; i <= links; ++i) {
    v.push_back(nlp.AddVariable(0.3 + 0.01 * i, -10, 10, 1.0 + 0.1 * (i % 7)));
  }
  const std::shared_ptr<const Element> e = MakeElement<3, 2>(Wiggle{});
  for (int i = 0; i < links; ++i) {
    const int r0 = nlp.AddConstraint(0, 0, 1.0 + i % 3), r1 = nlp.AddConstraint(0, 0, 2.0);
    nlp.AddLinear(r0, v[i], 1.0);
    nlp.AddElement(e, {v[i], v[i + 1], v[(i * 7) % (links + 1)]},
                   {{{r0, 1.0}, {Target::kObjective, 0.1}}, {{r1, -1.0}, {r0, 0.5}}});
  }
  nlp.SetThreads(threads);
  nlp.Finalize();
  return nlp;
}

struct Derivatives {
  std::vector<double> g, jac, hess;
};

Derivatives Evaluate(const ElementNlp& nlp) {
  Derivatives d;
  std::vector<double> y(nlp.variables());
  nlp.ScaledStart(y.data());
  std::vector<double> lambda(nlp.constraints());
  for (size_t r = 0; r < lambda.size(); ++r) lambda[r] = std::sin(1.0 + r);
  d.g.resize(nlp.constraints());
  nlp.ScaledConstraints(y.data(), d.g.data());
  d.jac.resize(nlp.JacobianPattern().rows.size());
  nlp.ScaledJacobian(y.data(), d.jac.data());
  d.hess.resize(nlp.HessianPattern().rows.size());
  nlp.ScaledHessian(y.data(), 0.7, lambda.data(), d.hess.data());
  return d;
}

// The derivatives on several threads are those of one thread (to round-off: the sums run in
// another order), and the same bit for bit on every call with the same thread count.
TEST(ElementNlpTest, ThreadsGiveTheSameDerivatives) {
  const Derivatives one = Evaluate(ChainNlp(501, 1));
  for (int threads : {2, 3, 8}) {
    const ElementNlp nlp = ChainNlp(501, threads);
    ASSERT_EQ(nlp.threads(), threads);
    const Derivatives d = Evaluate(nlp), again = Evaluate(nlp);
    for (const auto& [a, b] :
         {std::pair{&one.g, &d.g}, std::pair{&one.jac, &d.jac}, std::pair{&one.hess, &d.hess}}) {
      ASSERT_EQ(a->size(), b->size());
      for (size_t k = 0; k < a->size(); ++k) {
        EXPECT_NEAR((*a)[k], (*b)[k], 1e-12 * (1.0 + std::abs((*a)[k]))) << threads << " " << k;
      }
    }
    EXPECT_EQ(d.g, again.g) << threads;
    EXPECT_EQ(d.jac, again.jac) << threads;
    EXPECT_EQ(d.hess, again.hess) << threads;
  }
  EXPECT_EQ(ChainNlp(3, 0).threads(), 1);  // at least one
}

}  // namespace
}  // namespace hotlap::ocp
