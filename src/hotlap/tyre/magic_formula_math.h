#pragma once
/// @file
/// Arctangents, sines and cosines of several arguments at once, for the Magic Formula, with the
/// instruction set chosen at run time: glibc's libmvec on four AVX2 lanes where the CPU has
/// AVX2, else on the two SSE2 lanes of the x86-64 baseline (magic_formula_simd.h); libm one by
/// one on other targets. A ceres::Jet or a SecondOrder gets its value from the same lanes and its
/// derivatives by the chain rule.
///
/// Why: one combined-slip evaluation takes some 25 arctangents and 14 sines and cosines, and one
/// by one through libm they cost three quarters of its time. Most of them do not depend on one
/// another, so CalcMagicFormula evaluates them in a few batches (magic_formula.cc). The double
/// model calls libmvec inline, one copy of the model per instruction set; the functions here are
/// the same calls out of line, for the model on Jets and SecondOrders (LanesMath) and for tests.
///
/// Accuracy: libmvec's, a few ulp (magic_formula_math_test.cc measures the distance to libm); the
/// same bits as the inline calls on the same instruction set, not across instruction sets.
///
/// Internal to the tyre models; not an API.

#include <array>
#include <cstddef>
#include <type_traits>

#include "hotlap/common/scalar.h"

namespace hotlap::tyre::internal {

/// x[i] = atan(x[i]) for i < n.
void AtanLanes(double* x, int n);

/// x[i] = cos(x[i]) where bit i of `cos_mask` is set, else sin(x[i]), for i < n <= 32.
void SinOrCosLanes(double* x, unsigned cos_mask, int n);

/// s[i] = sin(x[i]) and c[i] = cos(x[i]) for i < n; `s` or `c` may be `x`.
void SinAndCosLanes(const double* x, double* s, double* c, int n);

/// The instruction sets the lanes can use.
enum class MathIsa {
  kGeneric,  ///< the baseline: libmvec's two SSE2 lanes on x86-64, libm elsewhere
  kAvx2,     ///< libmvec's four AVX2 lanes
};

/// Whether this machine can run `isa`.
bool MathIsaSupported(MathIsa isa);

/// The instruction set in use (here, in CalcMagicFormula<double> and CalcMagicFormulaBatch): the
/// widest supported one unless SetMathIsa chose another.
MathIsa ActiveMathIsa();

/// Makes the lanes and the double model use `isa` (for tests and benchmarks; not thread-safe).
/// Returns false and changes nothing if this machine cannot run it.
bool SetMathIsa(MathIsa isa);

/// "generic" or "avx2".
const char* MathIsaName(MathIsa isa);

/// f(x) for a Jet or SecondOrder `x`, given the value f(x.a) and the derivatives f'(x.a) and
/// f''(x.a) (the Jet uses only f').
template <Scalar T>
T ChainRule(const T& x, double f, double f1, double f2) {
  if constexpr (IsJet<T>::value) {
    T out;
    out.a = f;
    out.v = f1 * x.v;
    return out;
  } else {
    return T::Chain(x, f, f1, f2);
  }
}

/// Batched functions of any scalar but double, with the interface of simd::SimdMath (the double
/// model's, magic_formula_simd.h): arctangents, sines and cosines take their values from the
/// lanes above and their derivatives from the chain rule; the single functions are the scalar
/// type's own (ceres', SecondOrder's).
struct LanesMath {
  /// atan of every element; the derivative is da / (1 + a^2).
  template <Scalar T, std::size_t N>
  static std::array<T, N> Atan(const std::array<T, N>& x) {
    static_assert(!std::is_same_v<T, double>);
    std::array<double, N> values;
    for (std::size_t i = 0; i < N; ++i) values[i] = x[i].a;
    AtanLanes(values.data(), static_cast<int>(N));
    std::array<T, N> out;
    for (std::size_t i = 0; i < N; ++i) {
      const double a = x[i].a;
      const double d = 1.0 / (1.0 + a * a);
      out[i] = ChainRule(x[i], values[i], d, -2.0 * a * d * d);
    }
    return out;
  }

  /// cos of the elements whose bit is set in `cos_mask`, sin of the others.
  template <Scalar T, std::size_t N>
  static std::array<T, N> SinOrCos(const std::array<T, N>& x, unsigned cos_mask) {
    static_assert(!std::is_same_v<T, double> && N <= 32);
    std::array<double, N> values, s, c;
    for (std::size_t i = 0; i < N; ++i) values[i] = x[i].a;
    SinAndCosLanes(values.data(), s.data(), c.data(), static_cast<int>(N));
    std::array<T, N> out;
    for (std::size_t i = 0; i < N; ++i) {
      out[i] = (cos_mask >> i) & 1u ? ChainRule(x[i], c[i], -s[i], -c[i])
                                    : ChainRule(x[i], s[i], c[i], -s[i]);
    }
    return out;
  }

  template <Scalar T>
  static T Sin(const T& x) {
    using std::sin;
    return sin(x);
  }
  template <Scalar T>
  static T Cos(const T& x) {
    using std::cos;
    return cos(x);
  }
  template <Scalar T>
  static T Tan(const T& x) {
    using std::tan;
    return tan(x);
  }
  template <Scalar T>
  static T Exp(const T& x) {
    using std::exp;
    return exp(x);
  }
  template <Scalar T>
  static T Log(const T& x) {
    using std::log;
    return log(x);
  }
};

}  // namespace hotlap::tyre::internal
