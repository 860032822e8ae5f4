#include "hotlap/tyre/magic_formula_math.h"

#include <algorithm>
#include <cmath>

#include "hotlap/tyre/magic_formula_simd.h"

// GCC warns that a 4-lane vector returned from baseline code changes the ABI: the 4-lane
// functions are only ever inlined into AVX2 code (magic_formula_simd.h).
#pragma GCC diagnostic ignored "-Wpsabi"

namespace hotlap::tyre::internal {

namespace {

#if defined(HOTLAP_MF_SIMD)

// Lanes [i, i + m) of `x` as a vector; the lanes past m repeat x[i] (a harmless argument).
template <int W>
HOTLAP_MF_INLINE typename simd::Vec<W>::D LoadLanes(const double* x, int i, int m) {
  using D = typename simd::Vec<W>::D;
  D v = simd::Broadcast<W>(x[i]);
  for (int k = 1; k < m; ++k) v[k] = x[i + k];
  return v;
}

template <int W>
HOTLAP_MF_INLINE void AtanChunks(double* x, int n) {
  for (int i = 0; i < n; i += W) {
    const int m = std::min(W, n - i);
    const typename simd::Vec<W>::D r = simd::MvecAtan(LoadLanes<W>(x, i, m));
    for (int k = 0; k < m; ++k) x[i + k] = r[k];
  }
}

template <int W>
HOTLAP_MF_INLINE void SinOrCosChunks(double* x, unsigned cos_mask, int n) {
  for (int i = 0; i < n; i += W) {
    const int m = std::min(W, n - i);
    // Lanes past the end take lane i's function, so that a chunk of one kind stays one call.
    unsigned bits = (cos_mask >> i) & ((1u << W) - 1u);
    for (int k = m; k < W; ++k) bits = (bits & ~(1u << k)) | ((bits & 1u) << k);
    const typename simd::Vec<W>::D r = simd::SinOrCosVec<W>(LoadLanes<W>(x, i, m), bits);
    for (int k = 0; k < m; ++k) x[i + k] = r[k];
  }
}

template <int W>
HOTLAP_MF_INLINE void SinAndCosChunks(const double* x, double* s, double* c, int n) {
  using D = typename simd::Vec<W>::D;
  for (int i = 0; i < n; i += W) {
    // Through a copy: `s` or `c` may be `x`.
    const int m = std::min(W, n - i);
    const D v = LoadLanes<W>(x, i, m);
    const D sine = simd::MvecSin(v);
    const D cosine = simd::MvecCos(v);
    for (int k = 0; k < m; ++k) {
      s[i + k] = sine[k];
      c[i + k] = cosine[k];
    }
  }
}

// Two SSE2 lanes: the x86-64 baseline.
void AtanGeneric(double* x, int n) { AtanChunks<2>(x, n); }
void SinOrCosGeneric(double* x, unsigned cos_mask, int n) { SinOrCosChunks<2>(x, cos_mask, n); }
void SinAndCosGeneric(const double* x, double* s, double* c, int n) {
  SinAndCosChunks<2>(x, s, c, n);
}

HOTLAP_MF_AVX2 void AtanAvx2(double* x, int n) { AtanChunks<4>(x, n); }
HOTLAP_MF_AVX2 void SinOrCosAvx2(double* x, unsigned cos_mask, int n) {
  SinOrCosChunks<4>(x, cos_mask, n);
}
HOTLAP_MF_AVX2 void SinAndCosAvx2(const double* x, double* s, double* c, int n) {
  SinAndCosChunks<4>(x, s, c, n);
}

#else  // no libmvec: libm, one argument at a time

void AtanGeneric(double* x, int n) {
  for (int i = 0; i < n; ++i) x[i] = std::atan(x[i]);
}
void SinOrCosGeneric(double* x, unsigned cos_mask, int n) {
  for (int i = 0; i < n; ++i) x[i] = (cos_mask >> i) & 1u ? std::cos(x[i]) : std::sin(x[i]);
}
void SinAndCosGeneric(const double* x, double* s, double* c, int n) {
  for (int i = 0; i < n; ++i) {
    const double xi = x[i];
    s[i] = std::sin(xi);
    c[i] = std::cos(xi);
  }
}

#endif

struct Kernels {
  MathIsa isa;
  void (*atan)(double*, int);
  void (*sin_or_cos)(double*, unsigned, int);
  void (*sin_and_cos)(const double*, double*, double*, int);
};

constexpr Kernels kGenericKernels{MathIsa::kGeneric, AtanGeneric, SinOrCosGeneric,
                                  SinAndCosGeneric};
#if defined(HOTLAP_MF_SIMD)
constexpr Kernels kAvx2Kernels{MathIsa::kAvx2, AtanAvx2, SinOrCosAvx2, SinAndCosAvx2};
#endif

const Kernels& KernelsFor(MathIsa isa) {
#if defined(HOTLAP_MF_SIMD)
  if (isa == MathIsa::kAvx2) return kAvx2Kernels;
#endif
  return kGenericKernels;
}

// The kernels in use, chosen on first use.
const Kernels*& Active() {
  static const Kernels* active =
      &KernelsFor(MathIsaSupported(MathIsa::kAvx2) ? MathIsa::kAvx2 : MathIsa::kGeneric);
  return active;
}

}  // namespace

bool MathIsaSupported(MathIsa isa) {
  switch (isa) {
    case MathIsa::kGeneric:
      return true;
    case MathIsa::kAvx2:
#if defined(HOTLAP_MF_SIMD)
      __builtin_cpu_init();
      return __builtin_cpu_supports("avx2");
#else
      return false;
#endif
  }
  return false;
}

MathIsa ActiveMathIsa() { return Active()->isa; }

bool SetMathIsa(MathIsa isa) {
  if (!MathIsaSupported(isa)) return false;
  Active() = &KernelsFor(isa);
  return true;
}

const char* MathIsaName(MathIsa isa) { return isa == MathIsa::kAvx2 ? "avx2" : "generic"; }

void AtanLanes(double* x, int n) { Active()->atan(x, n); }

void SinOrCosLanes(double* x, unsigned cos_mask, int n) { Active()->sin_or_cos(x, cos_mask, n); }

void SinAndCosLanes(const double* x, double* s, double* c, int n) {
  Active()->sin_and_cos(x, s, c, n);
}

}  // namespace hotlap::tyre::internal
