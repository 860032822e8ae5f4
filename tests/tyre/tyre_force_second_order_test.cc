// The tyre force models on SecondOrder<3>, the optimal-control tyre element's scalar: the
// gradient and Hessian of Fx and Fy with respect to (Fz, kappa, alpha) against central
// differences of the double model.

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <variant>

#include <gtest/gtest.h>

#include "hotlap/common/second_order.h"
#include "hotlap/tyre/tyre_force_model.h"
#include "test_util.h"

namespace hotlap::tyre {
namespace {

using S3 = SecondOrder<3>;

// Where the derivatives are taken: load as a fraction of the model's nominal load, slips away
// from zero (where sign() switches), inside every file's limits.
struct Probe {
  double load;  // Fz / nominal
  double kappa;
  double alpha;  // rad
  double gamma;  // rad
  double speed;  // m/s
};
constexpr std::array<Probe, 4> kProbes = {{
    {0.8, 0.04, 0.03, 0.01, 20.0},
    {1.2, -0.06, -0.07, -0.02, 25.0},
    {0.6, 0.12, -0.12, 0.0, 15.0},
    {1.0, -0.02, 0.2, 0.03, 40.0},
}};

// The inputs as (Fz, kappa, alpha).
using Inputs = std::array<double, 3>;

TyreOperatingPoint<double> PointAt(const Probe& probe, const Inputs& x) {
  TyreOperatingPoint<double> op;
  op.fz = x[0];
  op.slip_ratio = x[1];
  op.slip_angle = x[2];
  op.camber = probe.gamma;
  op.speed = probe.speed;
  op.tread_temp = 350.0;  // the brush and UniTire models' temperature factors
  return op;
}

std::array<double, 2> FxFy(const TyreForceModel<double>& model, const Probe& probe,
                           const Inputs& x) {
  const TyreForces<double> f = CalcTyreForces(model, PointAt(probe, x));
  return {f.fx, f.fy};
}

// Checks the SecondOrder<3> gradient and Hessian of Fx and Fy at `probe` against central
// differences of the double model, Richardson-extrapolated from steps h and h/2 with
// h = (1e-3 Fz, 1e-4, 1e-4): the truncation error is O(h^4) (the slip curves bend on a scale of
// 0.01, so plain differences would be 1e-4 off), the rounding error O(1e-15 |F| / h^2). The
// tolerance is 1e-6 of the entry plus 1e-7 |F| / (s_i s_j), with scales s = (Fz, 1, 1).
enum class Order { kGradient, kGradientAndHessian };

void ExpectDerivativesMatch(const TyreForceModel<double>& model, double nominal_load,
                            const Probe& probe, Order order, const std::string& what) {
  const Inputs x0 = {probe.load * nominal_load, probe.kappa, probe.alpha};
  const Inputs h = {1e-3 * x0[0], 1e-4, 1e-4};
  const Inputs scale = {x0[0], 1.0, 1.0};

  const TyreForceModel<S3> model_s3 = model.Cast<S3>();
  TyreOperatingPoint<S3> op;
  const TyreOperatingPoint<double> op_d = PointAt(probe, x0);
  op.fz = S3::Variable(x0[0], 0);
  op.slip_ratio = S3::Variable(x0[1], 1);
  op.slip_angle = S3::Variable(x0[2], 2);
  op.camber = op_d.camber;
  op.speed = op_d.speed;
  op.tread_temp = op_d.tread_temp;
  const TyreForces<S3> f = CalcTyreForces(model_s3, op);
  const std::array<const S3*, 2> ad = {&f.fx, &f.fy};

  // F at x0 + di h_i e_i + dj h_j e_j.
  const auto at = [&](int i, double di, int j, double dj) {
    Inputs x = x0;
    x[i] += di * h[i];
    x[j] += dj * h[j];
    return FxFy(model, probe, x);
  };
  // Central differences with steps h / r, and their Richardson extrapolation.
  const auto gradient = [&](int o, int i, double r) {
    return (at(i, 1 / r, i, 0)[o] - at(i, -1 / r, i, 0)[o]) * r / (2.0 * h[i]);
  };
  const auto hessian = [&](int o, int i, int j, double r) {
    if (i == j) {
      return (at(i, 1 / r, i, 0)[o] - 2.0 * at(i, 0, i, 0)[o] + at(i, -1 / r, i, 0)[o]) * r * r /
             (h[i] * h[i]);
    }
    return (at(i, 1 / r, j, 1 / r)[o] - at(i, 1 / r, j, -1 / r)[o] - at(i, -1 / r, j, 1 / r)[o] +
            at(i, -1 / r, j, -1 / r)[o]) *
           r * r / (4.0 * h[i] * h[j]);
  };
  const auto extrapolate = [](double coarse, double fine) { return (4.0 * fine - coarse) / 3.0; };

  const std::array<double, 2> f0 = FxFy(model, probe, x0);
  for (int o = 0; o < 2; ++o) {
    const std::string name = what + (o == 0 ? " Fx" : " Fy");
    const double size = std::max(std::abs(f0[o]), 1.0);
    EXPECT_NEAR(ad[o]->a, f0[o], 1e-12 * size) << name;
    for (int i = 0; i < 3; ++i) {
      const double fd = extrapolate(gradient(o, i, 1.0), gradient(o, i, 2.0));
      EXPECT_NEAR(ad[o]->v[i], fd, 1e-6 * std::abs(fd) + 1e-7 * size / scale[i])
          << name << " d/dx" << i;
      for (int j = 0; j <= i && order == Order::kGradientAndHessian; ++j) {
        const double fd2 = extrapolate(hessian(o, i, j, 1.0), hessian(o, i, j, 2.0));
        EXPECT_NEAR(ad[o]->Hessian(i, j), fd2,
                    1e-6 * std::abs(fd2) + 1e-7 * size / (scale[i] * scale[j]))
            << name << " d2/dx" << i << "dx" << j;
      }
    }
  }
}

TEST(TyreForceSecondOrderTest, MagicFormulaDerivativesMatchCentralDifferences) {
  for (const char* path : {"tests/data/tir/mfeval/MagicFormula52_Parameters.tir",
                           "tests/data/tir/mfeval/MagicFormula61_Parameters.tir",
                           "tests/data/tir/mfeval/MagicFormula62_Parameters.tir",
                           "tests/data/tir/mfeval/PacejkaBook_Defaults.tir",
                           "data/cars/gen7/tyres/left.tir", "data/cars/gen7/tyres/right.tir"}) {
    const TyreForceModel<double> model = LoadTyreForceModel(test::SourcePath(path));
    ASSERT_EQ(model.kind(), "mf");
    const MagicFormulaParams<double>& p = std::get<MagicFormulaModel<double>>(model.params).params;
    for (size_t k = 0; k < kProbes.size(); ++k) {
      // Inside the limits, so that no input is clamped.
      ASSERT_LT(kProbes[k].load * p.FNOMIN * 1.01, p.FZMAX) << path;
      ExpectDerivativesMatch(model, p.FNOMIN, kProbes[k], Order::kGradientAndHessian,
                             std::string(path) + " probe " + std::to_string(k));
    }
  }
}

// UniTire and the brush model: gradient and Hessian. The brush model solves its torsional fixed
// point in double and then takes two chord steps in T (brush_model.cc): one step alone gives
// exact first derivatives but a Hessian off by up to several times the entry here.
TEST(TyreForceSecondOrderTest, BrushAndUniTireDerivativesMatchCentralDifferences) {
  for (const auto& [path, order] :
       {std::pair{"data/tyres/unitire_example.yaml", Order::kGradientAndHessian},
        std::pair{"data/tyres/brush_example.yaml", Order::kGradientAndHessian}}) {
    const TyreForceModel<double> model = LoadTyreForceModel(test::SourcePath(path));
    EXPECT_EQ(model.Cast<S3>().kind(), model.kind());
    for (size_t k = 0; k < kProbes.size(); ++k) {
      ExpectDerivativesMatch(model, 4000.0, kProbes[k], order,
                             std::string(path) + " probe " + std::to_string(k));
    }
  }
}

}  // namespace
}  // namespace hotlap::tyre
