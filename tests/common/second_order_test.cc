#include "hotlap/common/second_order.h"

#include <cmath>
#include <functional>

#include <gtest/gtest.h>

namespace hotlap {
namespace {

using S = SecondOrder<2>;

// Value, gradient and Hessian of f(x, y) by SecondOrder against central differences of double f.
void CheckAgainstDifferences(const std::function<S(const S&, const S&)>& fs,
                             const std::function<double(double, double)>& fd, double x0, double y0,
                             const char* what) {
  const S r = fs(S::Variable(x0, 0), S::Variable(y0, 1));
  EXPECT_NEAR(r.a, fd(x0, y0), 1e-14 * (1 + std::abs(r.a))) << what;
  const double h = 1e-5;
  const double dx = (fd(x0 + h, y0) - fd(x0 - h, y0)) / (2 * h);
  const double dy = (fd(x0, y0 + h) - fd(x0, y0 - h)) / (2 * h);
  EXPECT_NEAR(r.v[0], dx, 1e-7 * (1 + std::abs(dx))) << what;
  EXPECT_NEAR(r.v[1], dy, 1e-7 * (1 + std::abs(dy))) << what;
  const double hh = 1e-4;
  const double dxx = (fd(x0 + hh, y0) - 2 * fd(x0, y0) + fd(x0 - hh, y0)) / (hh * hh);
  const double dyy = (fd(x0, y0 + hh) - 2 * fd(x0, y0) + fd(x0, y0 - hh)) / (hh * hh);
  const double dxy =
      (fd(x0 + hh, y0 + hh) - fd(x0 + hh, y0 - hh) - fd(x0 - hh, y0 + hh) + fd(x0 - hh, y0 - hh)) /
      (4 * hh * hh);
  EXPECT_NEAR(r.Hessian(0, 0), dxx, 1e-4 * (1 + std::abs(dxx))) << what;
  EXPECT_NEAR(r.Hessian(1, 1), dyy, 1e-4 * (1 + std::abs(dyy))) << what;
  EXPECT_NEAR(r.Hessian(1, 0), dxy, 1e-4 * (1 + std::abs(dxy))) << what;
  EXPECT_EQ(r.Hessian(0, 1), r.Hessian(1, 0)) << what;
}

TEST(SecondOrderTest, EveryFunctionMatchesDifferences) {
  const double x = 0.7, y = -1.3;
  CheckAgainstDifferences([](const S& a, const S& b) { return a * b + 2.0 * a - b / 3.0 + 1.0; },
                          [](double a, double b) { return a * b + 2.0 * a - b / 3.0 + 1.0; }, x, y,
                          "arithmetic");
  CheckAgainstDifferences([](const S& a, const S& b) { return a / b - 1.5 / (a + b * b); },
                          [](double a, double b) { return a / b - 1.5 / (a + b * b); }, x, y,
                          "division");
  CheckAgainstDifferences(
      [](const S& a, const S& b) { return sqrt(a * a + b * b) + exp(a * b) + log(a + 2.0); },
      [](double a, double b) {
        return std::sqrt(a * a + b * b) + std::exp(a * b) + std::log(a + 2.0);
      },
      x, y, "sqrt exp log");
  CheckAgainstDifferences(
      [](const S& a, const S& b) { return sin(a * b) + cos(a - b) + tan(a / 2.0) + atan(a * b); },
      [](double a, double b) {
        return std::sin(a * b) + std::cos(a - b) + std::tan(a / 2.0) + std::atan(a * b);
      },
      x, y, "trig");
  CheckAgainstDifferences(
      [](const S& a, const S& b) { return cosh(a) * tanh(b) + sinh(a * b) + expm1(a); },
      [](double a, double b) {
        return std::cosh(a) * std::tanh(b) + std::sinh(a * b) + std::expm1(a);
      },
      x, y, "hyperbolic");
  CheckAgainstDifferences(
      [](const S& a, const S& b) { return pow(a, 0.805) * pow(a + 2.0, b) + atan2(b, a); },
      [](double a, double b) {
        return std::pow(a, 0.805) * std::pow(a + 2.0, b) + std::atan2(b, a);
      },
      x, y, "pow atan2");
  CheckAgainstDifferences([](const S& a, const S& b) { return abs(b) * a; },
                          [](double a, double b) { return std::abs(b) * a; }, x, y, "abs");
}

TEST(SecondOrderTest, CompoundAssignmentAndNegation) {
  S a = S::Variable(2.0, 0);
  const S b = S::Variable(3.0, 1);
  a *= b;
  a -= 1.0;
  a /= 2.0;
  const S c = -a;
  EXPECT_DOUBLE_EQ(c.a, -2.5);
  EXPECT_DOUBLE_EQ(c.v[0], -1.5);
  EXPECT_DOUBLE_EQ(c.v[1], -1.0);
  EXPECT_DOUBLE_EQ(c.Hessian(1, 0), -0.5);
  EXPECT_DOUBLE_EQ(c.Hessian(0, 0), 0.0);
}

}  // namespace
}  // namespace hotlap
