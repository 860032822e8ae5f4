#include "hotlap/tyre/magic_formula_math.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/scalar.h"
#include "hotlap/common/second_order.h"
#include "hotlap/common/units.h"
#include "hotlap/tyre/magic_formula_simd.h"

// The 4-lane inline calls below are compiled into AVX2 functions only (magic_formula_simd.h).
#pragma GCC diagnostic ignored "-Wpsabi"

namespace hotlap::tyre::internal {
namespace {

// Distance in units in the last place, counting across zero (+0 and -0 are the same); 0 when
// both are NaN.
std::int64_t UlpDistance(double a, double b) {
  if (std::isnan(a) && std::isnan(b)) return 0;
  if (std::isnan(a) || std::isnan(b)) return std::numeric_limits<std::int64_t>::max();
  std::int64_t ia, ib;
  std::memcpy(&ia, &a, sizeof a);
  std::memcpy(&ib, &b, sizeof b);
  if (ia < 0) ia = std::numeric_limits<std::int64_t>::min() - ia;
  if (ib < 0) ib = std::numeric_limits<std::int64_t>::min() - ib;
  return ia > ib ? ia - ib : ib - ia;
}

bool SameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Random arguments over many magnitudes, the model's range, values near multiples of pi/4 (where
// range reduction cancels), and the special values.
std::vector<double> Arguments() {
  std::vector<double> x;
  std::mt19937_64 rng(20261122);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int i = 0; i < 200000; ++i) x.push_back(unit(rng) * std::pow(10.0, 4.0 * unit(rng)));
  for (int i = 0; i < 20000; ++i) x.push_back(unit(rng) * 5.0);  // the model's range
  for (int k = -400; k <= 400; ++k) {
    double up = k * (kPi / 4.0), down = up;
    for (int j = 0; j < 4; ++j) {
      x.push_back(up);
      x.push_back(down);
      up = std::nextafter(up, 1e300);
      down = std::nextafter(down, -1e300);
    }
  }
  for (const double v :
       {0.0, -0.0, 5e-324, -5e-324, 1e-300, 1e-9, 1e6, 1e10, 1e300, -1e300,
        std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
        std::numeric_limits<double>::quiet_NaN()}) {
    x.push_back(v);
  }
  return x;
}

std::vector<MathIsa> SupportedIsas() {
  std::vector<MathIsa> isas;
  for (const MathIsa isa : {MathIsa::kGeneric, MathIsa::kAvx2}) {
    if (MathIsaSupported(isa)) isas.push_back(isa);
  }
  return isas;
}

// Restores the instruction set the library chose.
class MagicFormulaMathTest : public ::testing::Test {
 protected:
  void TearDown() override { SetMathIsa(initial_); }
  const MathIsa initial_ = ActiveMathIsa();
};

TEST_F(MagicFormulaMathTest, GenericIsAlwaysSupportedAndSelectable) {
  EXPECT_TRUE(MathIsaSupported(MathIsa::kGeneric));
  EXPECT_TRUE(SetMathIsa(MathIsa::kGeneric));
  EXPECT_EQ(ActiveMathIsa(), MathIsa::kGeneric);
  EXPECT_EQ(std::string(MathIsaName(MathIsa::kGeneric)), "generic");
  EXPECT_EQ(std::string(MathIsaName(MathIsa::kAvx2)), "avx2");
  if (!MathIsaSupported(MathIsa::kAvx2)) {
    EXPECT_FALSE(SetMathIsa(MathIsa::kAvx2));
    EXPECT_EQ(ActiveMathIsa(), MathIsa::kGeneric);
  }
}

// libmvec against libm: a few ulp apart at most (glibc documents libmvec's functions to 4 ulp
// of the exact value, libm's to 1), measured here on every instruction set; and SinOrCos gives
// SinAndCos's bits lane by lane, in batches of every length.
TEST_F(MagicFormulaMathTest, LanesAreWithinAFewUlpOfLibm) {
  const std::vector<double> x = Arguments();
  const int n = static_cast<int>(x.size());
  constexpr unsigned kCosMask = 0b101100101u;
  const auto for_batches = [n](auto f) {
    for (int i = 0; i < n;) {
      const int m = std::min(1 + i % 9, n - i);
      f(i, m);
      i += m;
    }
  };
  for (const MathIsa isa : SupportedIsas()) {
    ASSERT_TRUE(SetMathIsa(isa));
    std::vector<double> a = x, sc = x, s(x.size()), c(x.size());
    AtanLanes(a.data(), n);
    for_batches([&](int i, int m) {
      SinOrCosLanes(sc.data() + i, kCosMask, m);
      SinAndCosLanes(x.data() + i, s.data() + i, c.data() + i, m);
    });
    std::int64_t worst_atan = 0, worst_sin = 0, worst_cos = 0;
    for (int i = 0; i < n; ++i) {
      worst_atan = std::max(worst_atan, UlpDistance(a[i], std::atan(x[i])));
      worst_sin = std::max(worst_sin, UlpDistance(s[i], std::sin(x[i])));
      worst_cos = std::max(worst_cos, UlpDistance(c[i], std::cos(x[i])));
    }
    for_batches([&](int i, int m) {
      for (int k = 0; k < m; ++k) {
        const bool cosine = (kCosMask >> k) & 1u;
        EXPECT_TRUE(SameBits(sc[i + k], cosine ? c[i + k] : s[i + k])) << x[i + k];
      }
    });
    EXPECT_LE(worst_atan, 4) << MathIsaName(isa);
    EXPECT_LE(worst_sin, 4) << MathIsaName(isa);
    EXPECT_LE(worst_cos, 4) << MathIsaName(isa);
    std::printf("[ libmvec  ] %s: worst distance to libm: atan %lld, sin %lld, cos %lld ulp\n",
                MathIsaName(isa), static_cast<long long>(worst_atan),
                static_cast<long long>(worst_sin), static_cast<long long>(worst_cos));
  }
}

TEST_F(MagicFormulaMathTest, SpecialValues) {
  const double inf = std::numeric_limits<double>::infinity();
  for (const MathIsa isa : SupportedIsas()) {
    ASSERT_TRUE(SetMathIsa(isa));
    std::array<double, 5> a = {0.0, -0.0, inf, -inf, std::nan("")};
    AtanLanes(a.data(), 5);
    EXPECT_TRUE(SameBits(a[0], 0.0));
    EXPECT_TRUE(SameBits(a[1], -0.0));
    EXPECT_EQ(a[2], kPi / 2);
    EXPECT_EQ(a[3], -kPi / 2);
    EXPECT_TRUE(std::isnan(a[4]));
    std::array<double, 5> s = {-0.0, inf, -inf, std::nan(""), 0.0};
    SinOrCosLanes(s.data(), 0u, 5);
    EXPECT_TRUE(SameBits(s[0], -0.0));
    for (int i = 1; i < 4; ++i) EXPECT_TRUE(std::isnan(s[i]));
    EXPECT_TRUE(SameBits(s[4], 0.0));
  }
}

#if defined(HOTLAP_MF_SIMD)
constexpr std::array<double, 7> kInlineArgs = {-3.0, -0.7, -0.01, 0.3, 0.9, 2.0, 40.0};
constexpr unsigned kInlineCosMask = 0b0110101u;

std::array<double, 7> InlineAtanGeneric() { return simd::SimdMath<2>::Atan(kInlineArgs); }
std::array<double, 7> InlineTrigGeneric() {
  return simd::SimdMath<2>::SinOrCos(kInlineArgs, kInlineCosMask);
}
HOTLAP_MF_AVX2 std::array<double, 7> InlineAtanAvx2() {
  return simd::SimdMath<4>::Atan(kInlineArgs);
}
HOTLAP_MF_AVX2 std::array<double, 7> InlineTrigAvx2() {
  return simd::SimdMath<4>::SinOrCos(kInlineArgs, kInlineCosMask);
}
// Lanes<4> of the first four arguments, lane by lane.
HOTLAP_MF_AVX2 std::array<double, 4> LanesTanAvx2() {
  const simd::Lanes<4> x(
      simd::Vec<4>::D{kInlineArgs[0], kInlineArgs[1], kInlineArgs[2], kInlineArgs[3]});
  const simd::Lanes<4> t = tan(x);
  return {t.v[0], t.v[1], t.v[2], t.v[3]};
}
// The single-argument functions keep the sign of zero.
HOTLAP_MF_AVX2 std::array<double, 4> SignedZerosAvx2() {
  return {simd::SimdMath<4>::Tan(-0.0), simd::SimdMath<4>::Sin(-0.0),
          simd::SimdMath<4>::Atan(std::array<double, 1>{-0.0})[0], simd::Lanes<4>(-0.0).v[3]};
}
std::array<double, 4> SignedZerosGeneric() {
  return {simd::SimdMath<2>::Tan(-0.0), simd::SimdMath<2>::Sin(-0.0),
          simd::SimdMath<2>::Atan(std::array<double, 1>{-0.0})[0], simd::Lanes<2>(-0.0).v[1]};
}
HOTLAP_MF_AVX2 std::array<double, 4> SimdTanAvx2() {
  return {simd::SimdMath<4>::Tan(kInlineArgs[0]), simd::SimdMath<4>::Tan(kInlineArgs[1]),
          simd::SimdMath<4>::Tan(kInlineArgs[2]), simd::SimdMath<4>::Tan(kInlineArgs[3])};
}
#endif

// The inline calls the double model makes give the bits of the out-of-line lanes on the same
// instruction set, and a value gets the same bits in whichever lane it is.
TEST_F(MagicFormulaMathTest, InlineCallsGiveTheLanesBits) {
#if defined(HOTLAP_MF_SIMD)
  for (const MathIsa isa : SupportedIsas()) {
    ASSERT_TRUE(SetMathIsa(isa));
    const bool avx2 = isa == MathIsa::kAvx2;
    const std::array<double, 7> atan_inline = avx2 ? InlineAtanAvx2() : InlineAtanGeneric();
    const std::array<double, 7> trig_inline = avx2 ? InlineTrigAvx2() : InlineTrigGeneric();
    std::array<double, 7> atan_lanes = kInlineArgs, trig_lanes = kInlineArgs;
    AtanLanes(atan_lanes.data(), 7);
    SinOrCosLanes(trig_lanes.data(), kInlineCosMask, 7);
    for (size_t i = 0; i < kInlineArgs.size(); ++i) {
      EXPECT_TRUE(SameBits(atan_inline[i], atan_lanes[i])) << MathIsaName(isa) << kInlineArgs[i];
      EXPECT_TRUE(SameBits(trig_inline[i], trig_lanes[i])) << MathIsaName(isa) << kInlineArgs[i];
    }
    for (const double zero : avx2 ? SignedZerosAvx2() : SignedZerosGeneric()) {
      EXPECT_TRUE(SameBits(zero, -0.0)) << MathIsaName(isa);
    }
    // One argument per call (all lanes the same) against four different ones in one call.
    if (avx2) {
      const std::array<double, 4> lanes = LanesTanAvx2(), single = SimdTanAvx2();
      for (size_t i = 0; i < 4; ++i) EXPECT_TRUE(SameBits(lanes[i], single[i])) << i;
    }
  }
#else
  GTEST_SKIP() << "no libmvec";
#endif
}

// Jets: values from the lanes, derivatives as ceres computes them.
TEST_F(MagicFormulaMathTest, JetsGetCeresDerivatives) {
  using J = Jet2;
  const std::array<J, 3> x = {J(0.3, 0), J(-1.7, 1), J(4.0, 0)};
  const std::array<J, 3> a = LanesMath::Atan(x);
  const std::array<J, 3> sc = LanesMath::SinOrCos(x, 0b010u);
  for (size_t i = 0; i < x.size(); ++i) {
    const J ref_atan = ceres::atan(x[i]);
    const J ref_trig = i == 1 ? ceres::cos(x[i]) : ceres::sin(x[i]);
    EXPECT_LE(UlpDistance(a[i].a, ref_atan.a), 4);
    EXPECT_LE(UlpDistance(sc[i].a, ref_trig.a), 4);
    for (int k = 0; k < 2; ++k) {
      EXPECT_NEAR(a[i].v[k], ref_atan.v[k], 1e-15 * std::abs(ref_atan.v[k]));
      EXPECT_NEAR(sc[i].v[k], ref_trig.v[k], 4e-16);
    }
  }
}

// SecondOrders: values from the lanes, gradient and Hessian as SecondOrder's own functions.
TEST_F(MagicFormulaMathTest, SecondOrdersGetTheirDerivatives) {
  using S = SecondOrder<2>;
  // x0 and x0 * x1 + x1: non-zero Hessians to carry through the chain rule.
  const S u = S::Variable(0.4, 0), w = S::Variable(-1.3, 1);
  const std::array<S, 3> x = {u, u * w + w, w};
  const std::array<S, 3> a = LanesMath::Atan(x);
  const std::array<S, 3> sc = LanesMath::SinOrCos(x, 0b101u);
  for (size_t i = 0; i < x.size(); ++i) {
    const S ref_atan = atan(x[i]);
    const S ref_trig = i == 1 ? sin(x[i]) : cos(x[i]);
    EXPECT_LE(UlpDistance(a[i].a, ref_atan.a), 4);
    EXPECT_LE(UlpDistance(sc[i].a, ref_trig.a), 4);
    for (int r = 0; r < 2; ++r) {
      EXPECT_NEAR(a[i].v[r], ref_atan.v[r], 1e-15);
      EXPECT_NEAR(sc[i].v[r], ref_trig.v[r], 1e-15);
      for (int k = 0; k < 2; ++k) {
        EXPECT_NEAR(a[i].Hessian(r, k), ref_atan.Hessian(r, k), 1e-15);
        EXPECT_NEAR(sc[i].Hessian(r, k), ref_trig.Hessian(r, k), 1e-15);
      }
    }
  }
}

}  // namespace
}  // namespace hotlap::tyre::internal
