#include "hotlap/tyre/magic_formula.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "hotlap/common/error.h"
#include "hotlap/tyre/magic_formula_math.h"
#include "hotlap/tyre/magic_formula_model.h"
#include "hotlap/tyre/magic_formula_simd.h"

// GCC warns that a 4-lane vector returned from baseline code changes the ABI: the model's 4-lane
// functions are only ever inlined into AVX2 code (magic_formula_simd.h).
#pragma GCC diagnostic ignored "-Wpsabi"

// The equations are in magic_formula_model.h. Here: the entry points, one copy of the model per
// instruction set for doubles (with libmvec's calls inlined), chosen at run time.

namespace hotlap::tyre {

namespace {

using internal::model::Evaluate;
using internal::model::Outputs;
using internal::model::Point;

#if !defined(HOTLAP_MF_SIMD)
// libm, one function at a time: doubles on targets without libmvec.
struct LibmMath {
  template <std::size_t N>
  static std::array<double, N> Atan(const std::array<double, N>& x) {
    std::array<double, N> out;
    for (std::size_t i = 0; i < N; ++i) out[i] = std::atan(x[i]);
    return out;
  }
  template <std::size_t N>
  static std::array<double, N> SinOrCos(const std::array<double, N>& x, unsigned cos_mask) {
    std::array<double, N> out;
    for (std::size_t i = 0; i < N; ++i) {
      out[i] = (cos_mask >> i) & 1u ? std::cos(x[i]) : std::sin(x[i]);
    }
    return out;
  }
  static double Sin(double x) { return std::sin(x); }
  static double Cos(double x) { return std::cos(x); }
  static double Tan(double x) { return std::tan(x); }
  static double Exp(double x) { return std::exp(x); }
  static double Log(double x) { return std::log(x); }
};
#endif

template <Scalar T, class Math>
HOTLAP_MF_MODEL_INLINE TyreForces<T> EvaluatePoint(const MagicFormulaParams<T>& p,
                                                   const TyreOperatingPoint<T>& op,
                                                   const MagicFormulaOptions& options) {
  const Outputs<T> f = Evaluate<T, Math>(
      p, Point<T>{op.fz, op.slip_ratio, op.slip_angle, op.camber, op.speed, op.pressure}, options);
  return {f.fx, f.fy, f.mx, f.my, f.mz};
}

#if defined(HOTLAP_MF_SIMD)

// W operating points per evaluation, one per lane; the lanes past the end of `points` repeat its
// last point.
template <int W>
HOTLAP_MF_INLINE void EvaluateBatch(const MagicFormulaParams<double>& p,
                                    std::span<const TyreOperatingPoint<double>> points,
                                    const MagicFormulaOptions& options,
                                    std::span<TyreForces<double>> out) {
  using L = internal::simd::Lanes<W>;
  using D = typename L::D;
  const std::size_t n = points.size();
  for (std::size_t i = 0; i < n; i += W) {
    D fz{}, kappa{}, alpha{}, gamma{}, vx{}, pressure{};
    for (int k = 0; k < W; ++k) {
      const TyreOperatingPoint<double>& op = points[std::min(i + k, n - 1)];
      fz[k] = op.fz;
      kappa[k] = op.slip_ratio;
      alpha[k] = op.slip_angle;
      gamma[k] = op.camber;
      vx[k] = op.speed;
      pressure[k] = op.pressure;
    }
    const Point<L> in{L(fz), L(kappa), L(alpha), L(gamma), L(vx), L(pressure)};
    const Outputs<L> f = Evaluate<L, internal::simd::LaneMath<W>>(p, in, options);
    const std::size_t m = std::min<std::size_t>(W, n - i);
    for (std::size_t k = 0; k < m; ++k) {
      out[i + k] = {f.fx.v[k], f.fy.v[k], f.mx.v[k], f.my.v[k], f.mz.v[k]};
    }
  }
}

// The baseline: two SSE2 lanes.
TyreForces<double> EvaluateSse2(const MagicFormulaParams<double>& p,
                                const TyreOperatingPoint<double>& op,
                                const MagicFormulaOptions& options) {
  return EvaluatePoint<double, internal::simd::SimdMath<2>>(p, op, options);
}

void EvaluateBatchSse2(const MagicFormulaParams<double>& p,
                       std::span<const TyreOperatingPoint<double>> points,
                       const MagicFormulaOptions& options, std::span<TyreForces<double>> out) {
  EvaluateBatch<2>(p, points, options, out);
}

// Four AVX2 lanes.
HOTLAP_MF_AVX2 TyreForces<double> EvaluateAvx2(const MagicFormulaParams<double>& p,
                                               const TyreOperatingPoint<double>& op,
                                               const MagicFormulaOptions& options) {
  return EvaluatePoint<double, internal::simd::SimdMath<4>>(p, op, options);
}

HOTLAP_MF_AVX2 void EvaluateBatchAvx2(const MagicFormulaParams<double>& p,
                                      std::span<const TyreOperatingPoint<double>> points,
                                      const MagicFormulaOptions& options,
                                      std::span<TyreForces<double>> out) {
  EvaluateBatch<4>(p, points, options, out);
}

#endif

}  // namespace

MagicFormulaOptions MagicFormulaOptions::FromUseMode(int use_mode) {
  MagicFormulaOptions o;
  switch (use_mode) {
    case 111:
      return o;
    case 121:
      o.slip_form = MagicFormulaSlipForm::kTangent;
      return o;
    case 211:
      o.limits = MagicFormulaLimits::kNone;
      return o;
    case 221:
      o.limits = MagicFormulaLimits::kNone;
      o.slip_form = MagicFormulaSlipForm::kTangent;
      return o;
    default:
      throw InputError("Magic Formula useMode " + std::to_string(use_mode) +
                       " is not supported; supported: 111, 121, 211, 221 (no turn slip)");
  }
}

template <Scalar T>
TyreForces<T> CalcMagicFormula(const MagicFormulaParams<T>& p, const TyreOperatingPoint<T>& op,
                               const MagicFormulaOptions& options) {
  if constexpr (std::is_same_v<T, double>) {
#if defined(HOTLAP_MF_SIMD)
    if (internal::ActiveMathIsa() == internal::MathIsa::kAvx2) {
      return EvaluateAvx2(p, op, options);
    }
    return EvaluateSse2(p, op, options);
#else
    return EvaluatePoint<double, LibmMath>(p, op, options);
#endif
  } else {
    return EvaluatePoint<T, internal::LanesMath>(p, op, options);
  }
}

void CalcMagicFormulaBatch(const MagicFormulaParams<double>& params,
                           std::span<const TyreOperatingPoint<double>> points,
                           const MagicFormulaOptions& options, std::span<TyreForces<double>> out) {
  if (out.size() != points.size()) {
    throw std::invalid_argument("CalcMagicFormulaBatch: " + std::to_string(points.size()) +
                                " points but room for " + std::to_string(out.size()) + " results");
  }
  if (points.empty()) return;
#if defined(HOTLAP_MF_SIMD)
  if (internal::ActiveMathIsa() == internal::MathIsa::kAvx2) {
    EvaluateBatchAvx2(params, points, options, out);
  } else {
    EvaluateBatchSse2(params, points, options, out);
  }
#else
  for (std::size_t i = 0; i < points.size(); ++i) {
    out[i] = EvaluatePoint<double, LibmMath>(params, points[i], options);
  }
#endif
}

MagicFormulaParams<double> LoadMagicFormula(const std::filesystem::path& path) {
  return ReadTirFile(path).params;
}

#define HOTLAP_INSTANTIATE(T)                 \
  template TyreForces<T> CalcMagicFormula<T>( \
      const MagicFormulaParams<T>&, const TyreOperatingPoint<T>&, const MagicFormulaOptions&);
HOTLAP_FOR_EACH_SCALAR(HOTLAP_INSTANTIATE)
// The optimal-control tyre element's scalar: tyre forces over (Fz, kappa, alpha).
HOTLAP_INSTANTIATE(::hotlap::SecondOrder<3>)
#undef HOTLAP_INSTANTIATE

}  // namespace hotlap::tyre
