#include "hotlap/common/rk4.h"

#include <cmath>
#include <functional>

#include <gtest/gtest.h>

namespace hotlap {
namespace {

// Integrates dx/dt = f(t, x) from (0, x0) to t_end in n equal steps.
double Integrate(const std::function<double(double, double)>& f, double x0, double t_end, int n) {
  const double h = t_end / n;
  double x = x0;
  for (int i = 0; i < n; ++i) x = Rk4Step(f, i * h, x, h);
  return x;
}

// Global error ~ C h^4, so halving h divides it by 2^4 = 16; the band [14, 18] allows for the
// next-order term (checked from 20 to 160 steps: with 10 steps dx/dt = -2 t x is still
// pre-asymptotic, ratio 18.07; the smallest error, ~1e-10, is far above the rounding floor).
void ExpectFourthOrder(const std::function<double(double, double)>& f, double x0, double t_end,
                       double exact) {
  double previous = std::abs(Integrate(f, x0, t_end, 20) - exact);
  for (int n = 40; n <= 160; n *= 2) {
    const double error = std::abs(Integrate(f, x0, t_end, n) - exact);
    ASSERT_GT(error, 1e-14) << "error at the rounding floor, ratio meaningless";
    const double ratio = previous / error;
    EXPECT_GT(ratio, 14.0) << "n = " << n;
    EXPECT_LT(ratio, 18.0) << "n = " << n;
    previous = error;
  }
}

TEST(Rk4Test, FourthOrderOnExponentialDecay) {
  // dx/dt = -x, x(0) = 1: x(1) = e^-1.
  ExpectFourthOrder([](double, double x) { return -x; }, 1.0, 1.0, std::exp(-1.0));
}

TEST(Rk4Test, FourthOrderOnTimeDependentOde) {
  // dx/dt = cos(t) x, x(0) = 1: x(t) = exp(sin t); integrated to t = 2.
  ExpectFourthOrder([](double t, double x) { return std::cos(t) * x; }, 1.0, 2.0,
                    std::exp(std::sin(2.0)));
  // dx/dt = -2 t x, x(0) = 1: x(t) = exp(-t^2); integrated to t = 1.5.
  ExpectFourthOrder([](double t, double x) { return -2.0 * t * x; }, 1.0, 1.5,
                    std::exp(-1.5 * 1.5));
}

// One step of dx/dt = -x is the degree-4 Taylor polynomial of e^-h, exactly.
TEST(Rk4Test, SingleStepIsTheTaylorPolynomial) {
  const double h = 0.3;
  const double step = Rk4Step([](double, double x) { return -x; }, 0.0, 2.0, h);
  const double taylor = 2.0 * (1 - h + h * h / 2 - h * h * h / 6 + h * h * h * h / 24);
  EXPECT_NEAR(step, taylor, 1e-15);
}

// With f depending on t only, RK4 is Simpson's rule: exact for cubics in t (to rounding).
TEST(Rk4Test, ExactForCubicQuadrature) {
  const auto f = [](double t, double) { return 4 * t * t * t - 3 * t * t + 2; };
  const double x = Integrate(f, 1.0, 2.0, 3);  // x(2) = 1 + [t^4 - t^3 + 2t]_0^2 = 13
  EXPECT_NEAR(x, 13.0, 1e-12);
  // A quartic is not: Simpson's error is -(h^4/180) (b-a) f''''... with f = 5 t^4, nonzero.
  const double y = Integrate([](double t, double) { return 5 * t * t * t * t; }, 0.0, 2.0, 3);
  EXPECT_GT(std::abs(y - 32.0), 1e-3);
}

// The step works with the model's state structs (anything with + and double *).
struct Vec2 {
  double a, b;
  friend Vec2 operator+(const Vec2& x, const Vec2& y) { return {x.a + y.a, x.b + y.b}; }
  friend Vec2 operator*(double k, const Vec2& x) { return {k * x.a, k * x.b}; }
};

TEST(Rk4Test, HarmonicOscillatorWithStructState) {
  // x'' = -x as (x, v): after one period 2 pi the state returns to (1, 0); error ~ 2pi h^4/120.
  const int n = 200;
  const double h = 2 * 3.14159265358979323846 / n;
  Vec2 s{1.0, 0.0};
  for (int i = 0; i < n; ++i) {
    s = Rk4Step([](double, const Vec2& x) { return Vec2{x.b, -x.a}; }, i * h, s, h);
  }
  EXPECT_NEAR(s.a, 1.0, 1e-7);
  EXPECT_NEAR(s.b, 0.0, 1e-7);
}

}  // namespace
}  // namespace hotlap
