#pragma once
/// @file
/// The value types the Magic Formula's equations (magic_formula_model.h) are written over: a
/// Scalar (double, ceres::Jet, SecondOrder) or simd::Lanes<W>, and the branch-free operations that
/// let one text serve both (comparisons giving a bool or a LaneMask, Where, Any, All, Sign, ...).
/// Included by magic_formula_model.h only; internal, not an API.

#include <cmath>
#include <type_traits>

#include "hotlap/common/scalar.h"
#include "hotlap/tyre/magic_formula_simd.h"

namespace hotlap::tyre::internal::model {

#if defined(HOTLAP_MF_SIMD)
// Inline everything into the per-instruction-set entry points (magic_formula.cc), so that the
// lanes' code is compiled for their instruction set.
#define HOTLAP_MF_MODEL_INLINE HOTLAP_MF_INLINE
#else
#define HOTLAP_MF_MODEL_INLINE inline
#endif

// ---------------------------------------------------------------------------------------------
// Value types: scalars and lanes.

template <class T>
struct ValueTraits {
  static constexpr bool kLanes = false;
  using Param = T;        // the parameters' scalar
  using Mask = bool;      // what a comparison gives
  using Factor = double;  // what Sign gives
};
#if defined(HOTLAP_MF_SIMD)
template <int W>
struct ValueTraits<simd::Lanes<W>> {
  static constexpr bool kLanes = true;
  using Param = double;
  using Mask = simd::LaneMask<W>;
  using Factor = simd::Lanes<W>;
};
#endif

template <class T>
concept Value = Scalar<T> || ValueTraits<T>::kLanes;
template <class T>
using ParamOf = typename ValueTraits<T>::Param;
template <class T>
using MaskOf = typename ValueTraits<T>::Mask;
template <class T>
using Params = MagicFormulaParams<ParamOf<T>>;

// Comparisons of scalars' values (lanes have their own, magic_formula_simd.h).
template <Scalar A, Scalar B>
HOTLAP_MF_MODEL_INLINE bool Lt(const A& a, const B& b) {
  return ValueOf(a) < ValueOf(b);
}
template <Scalar A, Scalar B>
HOTLAP_MF_MODEL_INLINE bool Le(const A& a, const B& b) {
  return ValueOf(a) <= ValueOf(b);
}
template <Scalar A, Scalar B>
HOTLAP_MF_MODEL_INLINE bool Gt(const A& a, const B& b) {
  return ValueOf(a) > ValueOf(b);
}
template <Scalar A, Scalar B>
HOTLAP_MF_MODEL_INLINE bool Ge(const A& a, const B& b) {
  return ValueOf(a) >= ValueOf(b);
}
template <Scalar A, Scalar B>
HOTLAP_MF_MODEL_INLINE bool Eq(const A& a, const B& b) {
  return ValueOf(a) == ValueOf(b);
}
HOTLAP_MF_MODEL_INLINE bool Any(bool m) { return m; }
HOTLAP_MF_MODEL_INLINE bool All(bool m) { return m; }
template <Scalar T>
HOTLAP_MF_MODEL_INLINE T Where(bool m, const T& a, const T& b) {
  return m ? a : b;
}

// The small number that keeps denominators away from zero (4.E6a).
inline constexpr double kEpsilon = 1e-6;

// MATLAB's sign(): -1, 0 or 1 (0 for NaN). Without branches: the signs of slips change from one
// call to the next, and a mispredicted branch costs more than the arithmetic.
template <Scalar T>
HOTLAP_MF_MODEL_INLINE double Sign(const T& x) {
  const double v = ValueOf(x);
  return static_cast<double>(v > 0.0) - static_cast<double>(v < 0.0);
}

// sign() with sign(0) = 1, as mfeval uses it to keep denominators non-zero.
template <Scalar T>
HOTLAP_MF_MODEL_INLINE double SignOr1(const T& x) {
  return 1.0 - 2.0 * static_cast<double>(ValueOf(x) < 0.0);
}

#if defined(HOTLAP_MF_SIMD)
template <int W>
HOTLAP_MF_MODEL_INLINE simd::Lanes<W> Sign(const simd::Lanes<W>& x) {
  const simd::Lanes<W> one(1.0), zero(0.0);
  return Where(Gt(x, 0.0), one, zero) - Where(Lt(x, 0.0), one, zero);
}

template <int W>
HOTLAP_MF_MODEL_INLINE simd::Lanes<W> SignOr1(const simd::Lanes<W>& x) {
  return Where(Lt(x, 0.0), simd::Lanes<W>(-1.0), simd::Lanes<W>(1.0));
}
#endif

// min(x, 1): the limit mfeval puts on the curvature factors (useMode 1xx); a NaN stays NaN.
template <Value T>
HOTLAP_MF_MODEL_INLINE T CapAtOne(const T& x) {
  return Where(Gt(x, 1.0), T(1.0), x);
}

template <Value T>
HOTLAP_MF_MODEL_INLINE T Clamp(const T& x, const ParamOf<T>& lo, const ParamOf<T>& hi) {
  return Where(Lt(x, lo), T(lo), Where(Gt(x, hi), T(hi), x));
}

// cos(atan(x)) = 1/sqrt(1 + x^2), cheaper and the same value.
template <Value T>
HOTLAP_MF_MODEL_INLINE T CosAtan(const T& x) {
  using std::sqrt;
  return 1.0 / sqrt(1.0 + x * x);
}

}  // namespace hotlap::tyre::internal::model
