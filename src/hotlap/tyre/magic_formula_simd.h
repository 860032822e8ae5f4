#pragma once
/// @file
/// SIMD lanes for the Magic Formula, through glibc's vector maths library libmvec (part of
/// Debian's libc6, linked as `mvec`): arctangents, sines, cosines, tangents, exponentials and
/// logarithms of 2 (SSE2) or 4 (AVX2) doubles in one call; and Lanes<W>, W doubles with the
/// arithmetic, comparisons and selections the model needs, so that the model evaluates W operating
/// points at once (CalcMagicFormulaBatch).
///
/// libmvec's functions follow the x86-64 vector function ABI and are declared here by their
/// names: _ZGVbN2v_atan takes and returns an __m128d (SSE), _ZGVdN4v_atan an __m256d (AVX2); the
/// arctangents and tangents need glibc 2.35 or later (Debian 12 has 2.36). Each lane is computed
/// on its own (lanes with special arguments go to scalar code inside libmvec), so an argument gets
/// the same result in whichever lane and call it is, on one instruction set. libmvec is accurate
/// to a few ulp, not correctly rounded: its results may differ from libm's scalar functions, and
/// between instruction sets, in the last bits (magic_formula_math_test.cc measures how far).
///
/// Inline only, and only ever inlined into functions compiled for the matching instruction set
/// (HOTLAP_MF_AVX2 for W = 4; the baseline SSE2 for W = 2): such a caller gets 4-lane AVX2
/// arithmetic and passes its vectors to libmvec in registers. Nothing here may be called from
/// baseline code with W = 4.
///
/// Internal to the tyre models; not an API.

#include <array>
#include <cstddef>

// libmvec's x86-64 names; other targets (and builds with -DHOTLAP_MF_NO_SIMD, to check that path)
// evaluate the model with libm, one function at a time. So does Clang (the sanitizer and fuzzing
// builds, docs/reliability.md): it checks the AVX2 target of the generic lane templates where
// GCC checks only the inlined callers, and refuses this file.
#include <cstdlib>  // defines __GLIBC__ on glibc
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__GLIBC__) && \
    !defined(HOTLAP_MF_NO_SIMD)
#define HOTLAP_MF_SIMD 1
#endif

#if defined(HOTLAP_MF_SIMD)

#include <immintrin.h>

/// Code compiled for AVX2 (four lanes); AVX2 has no fused multiply-add, so the arithmetic rounds
/// as on the baseline.
#define HOTLAP_MF_AVX2 __attribute__((target("avx2")))
#define HOTLAP_MF_INLINE inline __attribute__((always_inline))

// GCC warns that passing an __m256d changes the ABI without AVX: these functions are only ever
// inlined into AVX2 code (see the file comment).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

extern "C" {
// SSE: two lanes (SSE2 is the x86-64 baseline; libmvec uses SSE4.1 where the CPU has it).
__m128d hotlap_mvec_atan_sse(__m128d) __asm__("_ZGVbN2v_atan");
__m128d hotlap_mvec_sin_sse(__m128d) __asm__("_ZGVbN2v_sin");
__m128d hotlap_mvec_cos_sse(__m128d) __asm__("_ZGVbN2v_cos");
__m128d hotlap_mvec_tan_sse(__m128d) __asm__("_ZGVbN2v_tan");
__m128d hotlap_mvec_exp_sse(__m128d) __asm__("_ZGVbN2v_exp");
__m128d hotlap_mvec_log_sse(__m128d) __asm__("_ZGVbN2v_log");
// AVX2: four lanes.
__m256d hotlap_mvec_atan_avx2(__m256d) __asm__("_ZGVdN4v_atan");
__m256d hotlap_mvec_sin_avx2(__m256d) __asm__("_ZGVdN4v_sin");
__m256d hotlap_mvec_cos_avx2(__m256d) __asm__("_ZGVdN4v_cos");
__m256d hotlap_mvec_tan_avx2(__m256d) __asm__("_ZGVdN4v_tan");
__m256d hotlap_mvec_exp_avx2(__m256d) __asm__("_ZGVdN4v_exp");
__m256d hotlap_mvec_log_avx2(__m256d) __asm__("_ZGVdN4v_log");
}

namespace hotlap::tyre::internal::simd {

/// W doubles in one register, and the integer lanes of the same shape that comparisons give.
template <int W>
struct Vec;
template <>
struct Vec<2> {
  using D = __m128d;
  using I = decltype(D{} < D{});
};
template <>
struct Vec<4> {
  using D = __m256d;
  using I = decltype(D{} < D{});
};

/// `x` in every lane (not D{} + x, which turns -0 into +0).
template <int W>
HOTLAP_MF_INLINE typename Vec<W>::D Broadcast(double x) {
  if constexpr (W == 2) {
    return typename Vec<W>::D{x, x};
  } else {
    return typename Vec<W>::D{x, x, x, x};
  }
}

/// libmvec by register width.
HOTLAP_MF_INLINE __m128d MvecAtan(const __m128d& x) { return hotlap_mvec_atan_sse(x); }
HOTLAP_MF_INLINE __m128d MvecSin(const __m128d& x) { return hotlap_mvec_sin_sse(x); }
HOTLAP_MF_INLINE __m128d MvecCos(const __m128d& x) { return hotlap_mvec_cos_sse(x); }
HOTLAP_MF_INLINE __m128d MvecTan(const __m128d& x) { return hotlap_mvec_tan_sse(x); }
HOTLAP_MF_INLINE __m128d MvecExp(const __m128d& x) { return hotlap_mvec_exp_sse(x); }
HOTLAP_MF_INLINE __m128d MvecLog(const __m128d& x) { return hotlap_mvec_log_sse(x); }
HOTLAP_MF_INLINE __m256d MvecAtan(const __m256d& x) { return hotlap_mvec_atan_avx2(x); }
HOTLAP_MF_INLINE __m256d MvecSin(const __m256d& x) { return hotlap_mvec_sin_avx2(x); }
HOTLAP_MF_INLINE __m256d MvecCos(const __m256d& x) { return hotlap_mvec_cos_avx2(x); }
HOTLAP_MF_INLINE __m256d MvecTan(const __m256d& x) { return hotlap_mvec_tan_avx2(x); }
HOTLAP_MF_INLINE __m256d MvecExp(const __m256d& x) { return hotlap_mvec_exp_avx2(x); }
HOTLAP_MF_INLINE __m256d MvecLog(const __m256d& x) { return hotlap_mvec_log_avx2(x); }

/// sqrt of every lane (correctly rounded, as std::sqrt). GCC's vector extensions have no square
/// root; the builtins expand to sqrtpd / vsqrtpd in the caller's instruction set.
HOTLAP_MF_INLINE __m128d VecSqrt(const __m128d& x) { return __builtin_ia32_sqrtpd(x); }
HOTLAP_MF_INLINE __m256d VecSqrt(const __m256d& x) { return __builtin_ia32_sqrtpd256(x); }

/// Lanes [i, i + W) of `x` as a vector; lanes past its end repeat x[i] (a harmless argument).
template <int W, std::size_t N>
HOTLAP_MF_INLINE typename Vec<W>::D LoadChunk(const std::array<double, N>& x, std::size_t i) {
  typename Vec<W>::D v = Broadcast<W>(x[i]);
  for (int k = 1; k < W; ++k) {
    if (i + k < N) v[k] = x[i + k];
  }
  return v;
}

template <int W, std::size_t N>
HOTLAP_MF_INLINE void StoreChunk(const typename Vec<W>::D& v, std::size_t i,
                                 std::array<double, N>& x) {
  for (int k = 0; k < W; ++k) {
    if (i + k < N) x[i + k] = v[k];
  }
}

/// cos where bit k of `cos_bits` is set, else sin, lane by lane: one libmvec call when the lanes
/// agree (the usual case: the bits are constants and fold away), both and a blend when not.
template <int W>
HOTLAP_MF_INLINE typename Vec<W>::D SinOrCosVec(const typename Vec<W>::D& v, unsigned cos_bits) {
  constexpr unsigned kAll = (1u << W) - 1u;
  cos_bits &= kAll;
  if (cos_bits == 0u) return MvecSin(v);
  if (cos_bits == kAll) return MvecCos(v);
  const typename Vec<W>::D s = MvecSin(v);
  const typename Vec<W>::D c = MvecCos(v);
  typename Vec<W>::I use_cos{};
  for (int k = 0; k < W; ++k) use_cos[k] = -static_cast<long>((cos_bits >> k) & 1u);
  return use_cos ? c : s;
}

/// The model's batched functions on doubles (one operating point), W lanes at a time, for code
/// compiled for the instruction set with W-lane registers. Every transcendental function of the
/// model goes through here, so a point gets the same bits as in a batch (LaneMath).
template <int W>
struct SimdMath {
  using D = typename Vec<W>::D;

  /// atan of every element.
  template <std::size_t N>
  static HOTLAP_MF_INLINE std::array<double, N> Atan(const std::array<double, N>& x) {
    std::array<double, N> out;
    for (std::size_t i = 0; i < N; i += W) StoreChunk<W>(MvecAtan(LoadChunk<W>(x, i)), i, out);
    return out;
  }

  /// cos of the elements whose bit is set in `cos_mask`, sin of the others.
  template <std::size_t N>
  static HOTLAP_MF_INLINE std::array<double, N> SinOrCos(const std::array<double, N>& x,
                                                         unsigned cos_mask) {
    static_assert(N <= 32);
    std::array<double, N> out;
    for (std::size_t i = 0; i < N; i += W) {
      // Lanes past the end take the first lane's function, so that a chunk of one kind stays one
      // call.
      unsigned bits = (cos_mask >> i) & ((1u << W) - 1u);
      for (std::size_t k = N - i; k < std::size_t{W}; ++k)
        bits = (bits & ~(1u << k)) | ((bits & 1u) << k);
      StoreChunk<W>(SinOrCosVec<W>(LoadChunk<W>(x, i), bits), i, out);
    }
    return out;
  }

  static HOTLAP_MF_INLINE double Sin(double x) { return MvecSin(Broadcast<W>(x))[0]; }
  static HOTLAP_MF_INLINE double Cos(double x) { return MvecCos(Broadcast<W>(x))[0]; }
  static HOTLAP_MF_INLINE double Tan(double x) { return MvecTan(Broadcast<W>(x))[0]; }
  static HOTLAP_MF_INLINE double Exp(double x) { return MvecExp(Broadcast<W>(x))[0]; }
  static HOTLAP_MF_INLINE double Log(double x) { return MvecLog(Broadcast<W>(x))[0]; }
};

/// Which lanes a comparison holds in.
template <int W>
struct LaneMask {
  typename Vec<W>::I m;

  friend HOTLAP_MF_INLINE LaneMask operator||(const LaneMask& a, const LaneMask& b) {
    return {a.m | b.m};
  }
  friend HOTLAP_MF_INLINE LaneMask operator&&(const LaneMask& a, const LaneMask& b) {
    return {a.m & b.m};
  }
  friend HOTLAP_MF_INLINE LaneMask operator!(const LaneMask& a) { return {~a.m}; }
  /// Whether the comparison holds in any lane, in all lanes.
  friend HOTLAP_MF_INLINE bool Any(const LaneMask& a) {
    long any = 0;
    for (int k = 0; k < W; ++k) any |= a.m[k];
    return any != 0;
  }
  friend HOTLAP_MF_INLINE bool All(const LaneMask& a) {
    long all = -1;
    for (int k = 0; k < W; ++k) all &= a.m[k];
    return all != 0;
  }
};

/// W doubles, one operating point per lane, with the operations of a scalar: IEEE arithmetic lane
/// by lane (the same bits as on doubles), comparisons giving a LaneMask, Where to select, and the
/// model's elementary functions (sqrt and abs exact; the others libmvec's). A double converts to
/// all lanes, as a double converts to a Jet.
template <int W>
struct Lanes {
  using D = typename Vec<W>::D;
  D v;

  Lanes() = default;
  HOTLAP_MF_INLINE Lanes(double x) : v(Broadcast<W>(x)) {}  // NOLINT: implicit, as for a Jet
  HOTLAP_MF_INLINE explicit Lanes(const D& x) : v(x) {}

  HOTLAP_MF_INLINE Lanes& operator+=(const Lanes& b) {
    v += b.v;
    return *this;
  }
  HOTLAP_MF_INLINE Lanes& operator-=(const Lanes& b) {
    v -= b.v;
    return *this;
  }
  HOTLAP_MF_INLINE Lanes& operator*=(const Lanes& b) {
    v *= b.v;
    return *this;
  }
  HOTLAP_MF_INLINE Lanes& operator/=(const Lanes& b) {
    v /= b.v;
    return *this;
  }
  friend HOTLAP_MF_INLINE Lanes operator-(const Lanes& a) { return Lanes(-a.v); }
  friend HOTLAP_MF_INLINE Lanes operator+(const Lanes& a, const Lanes& b) {
    return Lanes(a.v + b.v);
  }
  friend HOTLAP_MF_INLINE Lanes operator-(const Lanes& a, const Lanes& b) {
    return Lanes(a.v - b.v);
  }
  friend HOTLAP_MF_INLINE Lanes operator*(const Lanes& a, const Lanes& b) {
    return Lanes(a.v * b.v);
  }
  friend HOTLAP_MF_INLINE Lanes operator/(const Lanes& a, const Lanes& b) {
    return Lanes(a.v / b.v);
  }

  friend HOTLAP_MF_INLINE LaneMask<W> Lt(const Lanes& a, const Lanes& b) { return {a.v < b.v}; }
  friend HOTLAP_MF_INLINE LaneMask<W> Le(const Lanes& a, const Lanes& b) { return {a.v <= b.v}; }
  friend HOTLAP_MF_INLINE LaneMask<W> Gt(const Lanes& a, const Lanes& b) { return {a.v > b.v}; }
  friend HOTLAP_MF_INLINE LaneMask<W> Ge(const Lanes& a, const Lanes& b) { return {a.v >= b.v}; }
  friend HOTLAP_MF_INLINE LaneMask<W> Eq(const Lanes& a, const Lanes& b) { return {a.v == b.v}; }
  friend HOTLAP_MF_INLINE LaneMask<W> Ne(const Lanes& a, const Lanes& b) { return {a.v != b.v}; }
  /// `a` in the lanes where `m` holds, `b` in the others.
  friend HOTLAP_MF_INLINE Lanes Where(const LaneMask<W>& m, const Lanes& a, const Lanes& b) {
    return Lanes(m.m ? a.v : b.v);
  }

  friend HOTLAP_MF_INLINE Lanes abs(const Lanes& a) {
    using I = typename Vec<W>::I;
    return Lanes((D)((I)a.v & (I{} + 0x7fffffffffffffffL)));
  }
  friend HOTLAP_MF_INLINE Lanes sqrt(const Lanes& a) { return Lanes(VecSqrt(a.v)); }
  friend HOTLAP_MF_INLINE Lanes atan(const Lanes& a) { return Lanes(MvecAtan(a.v)); }
  friend HOTLAP_MF_INLINE Lanes sin(const Lanes& a) { return Lanes(MvecSin(a.v)); }
  friend HOTLAP_MF_INLINE Lanes cos(const Lanes& a) { return Lanes(MvecCos(a.v)); }
  friend HOTLAP_MF_INLINE Lanes tan(const Lanes& a) { return Lanes(MvecTan(a.v)); }
  friend HOTLAP_MF_INLINE Lanes exp(const Lanes& a) { return Lanes(MvecExp(a.v)); }
  friend HOTLAP_MF_INLINE Lanes log(const Lanes& a) { return Lanes(MvecLog(a.v)); }
};

/// The model's batched functions on Lanes (W operating points): every element is a full
/// register, one libmvec call each.
template <int W>
struct LaneMath {
  using L = Lanes<W>;

  template <std::size_t N>
  static HOTLAP_MF_INLINE std::array<L, N> Atan(const std::array<L, N>& x) {
    std::array<L, N> out;
    for (std::size_t i = 0; i < N; ++i) out[i] = atan(x[i]);
    return out;
  }

  template <std::size_t N>
  static HOTLAP_MF_INLINE std::array<L, N> SinOrCos(const std::array<L, N>& x, unsigned cos_mask) {
    static_assert(N <= 32);
    std::array<L, N> out;
    for (std::size_t i = 0; i < N; ++i) out[i] = (cos_mask >> i) & 1u ? cos(x[i]) : sin(x[i]);
    return out;
  }

  static HOTLAP_MF_INLINE L Sin(const L& x) { return sin(x); }
  static HOTLAP_MF_INLINE L Cos(const L& x) { return cos(x); }
  static HOTLAP_MF_INLINE L Tan(const L& x) { return tan(x); }
  static HOTLAP_MF_INLINE L Exp(const L& x) { return exp(x); }
  static HOTLAP_MF_INLINE L Log(const L& x) { return log(x); }
};

}  // namespace hotlap::tyre::internal::simd

#pragma GCC diagnostic pop

#endif  // HOTLAP_MF_SIMD
