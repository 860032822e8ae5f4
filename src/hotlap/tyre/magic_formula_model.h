#pragma once
/// @file
/// The Magic Formula's equations (magic_formula.h describes the model), written once for every
/// value type the library evaluates them on: a Scalar (one operating point: double, ceres::Jet,
/// SecondOrder) or simd::Lanes<W> (W operating points at once, one per SIMD lane, parameters
/// double). Included by magic_formula.cc only; internal, not an API.
///
/// Equation numbers: (4.Ex) Pacejka, Tyre and Vehicle Dynamics, 3rd ed. 2012, section 4.3.2;
/// (Ax) Besselink, Schmeitz and Pacejka, "An improved Magic Formula/Swift tyre model that can
/// handle inflation pressure changes", VSD 48 S1 (2010); "mfeval" marks a choice mfeval 4.3.1
/// makes to match TNO MF-Tyre where the sources disagree or are silent.
///
/// How one text serves both (magic_formula_values.h): a branch on a value becomes a comparison
/// (Lt, Le, ..., a bool for a scalar, a LaneMask for lanes) and a selection, Where(mask, a, b).
/// Work that only some points need is guarded by Any(mask) (a scalar's `if`; for lanes, the work is
/// done for all lanes and selected), and an early return by All(mask). A scalar therefore takes
/// exactly the branches it took before, and each lane computes what a scalar would with the same
/// operations in the same order, so a lane gives the bits of a single-point evaluation on the same
/// instruction set. Pitfall: Where computes both sides, for scalars too; the side it drops may be
/// infinite or NaN (log(0), a Jet's sqrt at 0), but it must be cheap, or guarded by Any.
///
/// Speed: an evaluation needs some 25 arctangents and 14 sines and cosines. Most do not depend on
/// one another, so the model runs in stages: each stage computes the arguments of the functions
/// it needs, evaluates them together through `Math` (simd::SimdMath: libmvec's SIMD lanes for one
/// double point; simd::LaneMath for lanes; internal::LanesMath for Jets and SecondOrders), and the
/// next stage uses the results. Every transcendental function goes through `Math`. The
/// evaluation of one point is bound by its longest chain of dependent functions (seven deep, see
/// Evaluate); points in lanes overlap their chains.

#include <array>
#include <cmath>
#include <type_traits>
#include <utility>

#include "hotlap/common/scalar.h"
#include "hotlap/common/units.h"
#include "hotlap/tyre/magic_formula.h"
#include "hotlap/tyre/magic_formula_simd.h"
#include "hotlap/tyre/magic_formula_values.h"

namespace hotlap::tyre::internal::model {

// ---------------------------------------------------------------------------------------------
// The model.

// An operating point and the model's outputs (TyreOperatingPoint and TyreForces hold scalars
// only).
template <Value T>
struct Point {
  T fz, kappa, alpha, gamma, vx, pressure;
};

template <Value T>
struct Outputs {
  T fx, fy, mx, my, mz;
};

// The Magic Formula curve sin|cos(C atan(B x - E (B x - atan(B x)))) (4.E9), evaluated in three
// steps so that several curves share each batch: atan(B x), then the outer arctangent, then the
// sine or cosine of C times it.
template <Value T>
struct Curve {
  T c;
  T e;
  T bx;  // B x
};

template <Value T>
HOTLAP_MF_MODEL_INLINE Curve<T> MakeCurve(const T& b, const T& c, const T& e, const T& x) {
  return {c, e, b * x};
}

// The outer arctangent's argument, given atan(B x).
template <Value T>
HOTLAP_MF_MODEL_INLINE T OuterArgument(const Curve<T>& k, const T& atan_bx) {
  return k.bx - k.e * (k.bx - atan_bx);
}

// The inputs after mfeval's limit checks, and the quantities every force and moment uses.
template <Value T>
struct Inputs {
  T fz;            // load, clamped to FZMAX, N
  T fz_unlimited;  // load as given (>= 0), N
  T fz_trail;      // load for the trail and residual torque: at least FZMIN, N
  T kappa;         // clamped and reduced at low speed
  T kappa_unlimited;
  T alpha;     // clamped and reduced at low speed, rad
  T gamma;     // clamped, rad
  T vx;        // m/s
  T pressure;  // clamped, Pa
  MaskOf<T> low_speed{};
  T reduction_smooth;  // 1 above VXLOW, -> 0 at standstill
  T dfz;               // (4.E2a)
  T dpi;               // (4.E2b)
  T fz0_prime;         // (4.E1)
  T alpha_star;        // (4.E3) or alpha
  T gamma_star;        // (4.E4) or gamma
  T cos_alpha_prime;   // cos of (4.E6): Vcx / Vc'
};

template <Value T, class Math>
HOTLAP_MF_MODEL_INLINE Inputs<T> PrepareInputs(const Params<T>& p, const Point<T>& op,
                                               const MagicFormulaOptions& options) {
  using std::abs;
  using std::sqrt;
  Inputs<T> in;
  in.fz = Where(Lt(op.fz, 0.0), T(0.0), op.fz);
  in.fz_unlimited = in.fz;
  in.fz_trail = in.fz;
  in.kappa = op.kappa;
  in.kappa_unlimited = op.kappa;
  in.alpha = op.alpha;
  in.gamma = op.gamma;
  in.vx = op.vx;
  in.pressure = Where(Eq(op.pressure, 0.0), T(p.INFLPRES), op.pressure);
  in.reduction_smooth = T(1.0);
  // tan(alpha) of the input; computed again below only if the limits change alpha.
  T tan_alpha = Math::Tan(in.alpha);
  if (options.limits == MagicFormulaLimits::kClamp) {
    // Low-speed model: slip and shifts fade out below VXLOW (mfeval parseInputs).
    in.low_speed = Le(abs(in.vx), p.VXLOW);
    if (Any(in.low_speed)) {
      in.reduction_smooth =
          Where(in.low_speed, T(1.0 - 0.5 * (1.0 + Math::Cos(T(kPi * in.vx / p.VXLOW)))), T(1.0));
      in.kappa = Where(in.low_speed, T(in.kappa * abs(in.vx / p.VXLOW)), in.kappa);
    }
    const T speed_sum = abs(in.vx) + abs(tan_alpha * in.vx);
    const MaskOf<T> scaled = Lt(speed_sum, p.VXLOW);
    if (Any(scaled)) in.alpha = Where(scaled, T(in.alpha * (speed_sum / p.VXLOW)), in.alpha);
    const MaskOf<T> clamped = Lt(in.alpha, p.ALPMIN) || Gt(in.alpha, p.ALPMAX);
    in.alpha = Clamp(in.alpha, p.ALPMIN, p.ALPMAX);
    if (Any(scaled || clamped)) tan_alpha = Math::Tan(in.alpha);
    in.gamma = Clamp(in.gamma, p.CAMMIN, p.CAMMAX);
    in.fz = Where(Gt(in.fz, p.FZMAX), T(p.FZMAX), in.fz);
    in.fz_trail = Where(Le(in.fz, 0.0), T(0.0), Where(Lt(in.fz, p.FZMIN), T(p.FZMIN), in.fz));
    in.pressure = Clamp(in.pressure, p.PRESMIN, p.PRESMAX);
    in.kappa = Clamp(in.kappa, p.KPUMIN, p.KPUMAX);
  }
  in.fz0_prime = p.LFZO * p.FNOMIN;                // (4.E1)
  in.dfz = (in.fz - in.fz0_prime) / in.fz0_prime;  // (4.E2a)
  in.dpi = (in.pressure - p.NOMPRES) / p.NOMPRES;  // (4.E2b)
  if (options.slip_form == MagicFormulaSlipForm::kTangent) {
    in.alpha_star = tan_alpha * Sign(in.vx);  // (4.E3)
    in.gamma_star = Math::Sin(in.gamma);      // (4.E4)
  } else {
    in.alpha_star = in.alpha;
    in.gamma_star = in.gamma;
  }
  // Contact-centre speed, Vcy = Vsy = tan(alpha) |Vx| (2.12), and cos(alpha') (4.E6).
  const T vcy = tan_alpha * abs(in.vx);
  const T vc2 = in.vx * in.vx + vcy * vcy;
  const T vc = Where(Gt(vc2, 0.0), T(sqrt(vc2)), T(0.0));
  in.cos_alpha_prime = in.vx / (vc + kEpsilon);
  return in;
}

// Pure longitudinal force (4.E9-E18): everything but the curve's sine.
template <Value T>
struct PureLongitudinal {
  T kxk;  // slip stiffness (4.E15)
  T dx;
  T svx;
  Curve<T> curve;
};

template <Value T, class Math>
HOTLAP_MF_MODEL_INLINE PureLongitudinal<T> CalcFx0Coefficients(const Params<T>& p,
                                                               const Inputs<T>& in) {
  const T& dfz = in.dfz;
  const T& dpi = in.dpi;
  PureLongitudinal<T> r;
  const T cx = p.PCX1 * p.LCX;  // (4.E11)
  T mux = (p.PDX1 + p.PDX2 * dfz) * (1.0 + p.PPX3 * dpi + p.PPX4 * dpi * dpi) *
          (1.0 - p.PDX3 * in.gamma * in.gamma) * p.LMUX;  // (4.E13)
  mux = Where(Eq(in.fz, 0.0), T(0.0), mux);
  r.dx = mux * in.fz;  // (4.E12)
  r.kxk = in.fz * (p.PKX1 + p.PKX2 * dfz) * Math::Exp(T(p.PKX3 * dfz)) *
          (1.0 + p.PPX1 * dpi + p.PPX2 * dpi * dpi) * p.LKX;    // (4.E15)
  const T bx = r.kxk / (cx * r.dx + kEpsilon * SignOr1(r.dx));  // (4.E16)
  T shx = (p.PHX1 + p.PHX2 * dfz) * p.LHX;                      // (4.E17)
  r.svx = in.fz * (p.PVX1 + p.PVX2 * dfz) * p.LVX * p.LMUX;     // (4.E18)
  if (Any(in.low_speed)) {
    // (Lanes above VXLOW multiply by exactly 1.)
    r.svx *= in.reduction_smooth;
    shx *= in.reduction_smooth;
  }
  const T kappa_x = in.kappa + shx;  // (4.E10)
  const T ex = (p.PEX1 + p.PEX2 * dfz + p.PEX3 * dfz * dfz) * (1.0 - p.PEX4 * Sign(kappa_x)) *
               p.LEX;                        // (4.E14)
  r.curve = MakeCurve(bx, cx, ex, kappa_x);  // (4.E9)
  return r;
}

// Fx0 (4.E9) from the curve's sine.
template <Value T>
HOTLAP_MF_MODEL_INLINE T CalcFx0(const PureLongitudinal<T>& lon, const Inputs<T>& in,
                                 const T& sine) {
  const T fx0 = lon.dx * sine + lon.svx;
  return Where(Lt(in.vx, 0.0), T(-fx0), fx0);
}

// The arctangent's argument in the cornering stiffness (4.E25) at camber `gamma_star`.
template <Value T>
HOTLAP_MF_MODEL_INLINE T KyaArgument(const Params<T>& p, const Inputs<T>& in, const T& gamma_star) {
  const T g2 = gamma_star * gamma_star;
  return (in.fz / in.fz0_prime) / ((p.PKY2 + p.PKY5 * g2) * (1.0 + p.PPY2 * in.dpi));
}

// Lateral friction coefficient (4.E23) at camber `gamma_star`.
template <Value T>
HOTLAP_MF_MODEL_INLINE T CalcMuy(const Params<T>& p, const Inputs<T>& in, const T& gamma_star) {
  const T& dpi = in.dpi;
  const T g2 = gamma_star * gamma_star;
  return (p.PDY1 + p.PDY2 * in.dfz) * (1.0 + p.PPY3 * dpi + p.PPY4 * dpi * dpi) *
         (1.0 - p.PDY3 * g2) * p.LMUY;  // (4.E23)
}

// Pure lateral force (4.E19-E30) and the coefficients the aligning torque reuses: everything but
// the curve's sine.
template <Value T>
struct PureLateral {
  T kya;  // cornering stiffness (4.E25)
  T shy;
  T svy;
  T by;
  T cy;
  T dy;
  Curve<T> curve;
};

// At camber `gamma_star`, given sin(PKY4 atan(KyaArgument)).
template <Value T>
HOTLAP_MF_MODEL_INLINE PureLateral<T> CalcFy0Coefficients(const Params<T>& p, const Inputs<T>& in,
                                                          const T& gamma_star, const T& sin_kya,
                                                          const MagicFormulaOptions& options) {
  using std::abs;
  const T& fz = in.fz;
  const T& dfz = in.dfz;
  const T& dpi = in.dpi;
  const T& fz0p = in.fz0_prime;
  const T g2 = gamma_star * gamma_star;
  PureLateral<T> r;
  r.kya = p.PKY1 * fz0p * (1.0 + p.PPY1 * dpi) * (1.0 - p.PKY3 * abs(gamma_star)) * sin_kya *
          p.LKY;                                                               // (4.E25)
  const T svyg = fz * (p.PVY3 + p.PVY4 * dfz) * gamma_star * p.LKYC * p.LMUY;  // (4.E28)
  if (p.version == MagicFormulaVersion::kMf52) {
    // MF-Tyre 5.2 equation manual (mfeval).
    r.shy = (p.PHY1 + p.PHY2 * dfz) * p.LHY + p.PHY3 * gamma_star * p.LKYC;
  } else {
    const T kyg0 = fz * (p.PKY6 + p.PKY7 * dfz) * (1.0 + p.PPY5 * dpi) * p.LKYC;  // (4.E30)
    r.shy = (p.PHY1 + p.PHY2 * dfz) * p.LHY +
            (kyg0 * gamma_star - svyg) / (r.kya + kEpsilon * SignOr1(r.kya));  // (4.E27)
  }
  r.svy = fz * (p.PVY1 + p.PVY2 * dfz) * p.LVY * p.LMUY + svyg;  // (4.E29)
  if (Any(in.low_speed)) {
    r.svy *= in.reduction_smooth;
    r.shy *= in.reduction_smooth;
  }
  const T alpha_y = in.alpha_star + r.shy;   // (4.E20)
  r.cy = p.PCY1 * p.LCY;                     // (4.E21)
  const T muy = CalcMuy(p, in, gamma_star);  // (4.E23)
  r.dy = muy * fz;                           // (4.E22)
  T ey = (p.PEY1 + p.PEY2 * dfz) *
         (1.0 + p.PEY5 * g2 - (p.PEY3 + p.PEY4 * gamma_star) * SignOr1(alpha_y)) *
         p.LEY;  // (4.E24)
  if (options.limits == MagicFormulaLimits::kClamp) ey = CapAtOne(ey);
  r.by = r.kya / (r.cy * r.dy + kEpsilon * SignOr1(r.dy));  // (4.E26)
  r.curve = MakeCurve(r.by, r.cy, ey, alpha_y);             // (4.E19)
  return r;
}

// Fy0 (4.E19) from the curve's sine.
template <Value T>
HOTLAP_MF_MODEL_INLINE T CalcFy0(const PureLateral<T>& lat, const Inputs<T>& in, const T& sine,
                                 const MagicFormulaOptions& options) {
  const T fy0 = lat.dy * sine + lat.svy;
  if (options.slip_form != MagicFormulaSlipForm::kTangent) return fy0;
  return Where(Lt(in.vx, 0.0), T(-fy0), fy0);
}

// Combined-slip weighting of Fx0 by slip angle, Gxa (4.E51-E57): the curves of its numerator and
// denominator, cos(...) / cos(...).
template <Value T>
struct Weighting {
  Curve<T> num;
  Curve<T> den;
};

template <Value T>
HOTLAP_MF_MODEL_INLINE Weighting<T> CalcGxaCurves(const Params<T>& p, const Inputs<T>& in) {
  const T cxa = p.RCX1;                    // (4.E55)
  const T exa = p.REX1 + p.REX2 * in.dfz;  // (4.E56)
  const T shxa = p.RHX1;                   // (4.E57)
  const T bxa = (p.RBX1 + p.RBX3 * in.gamma_star * in.gamma_star) * CosAtan(T(p.RBX2 * in.kappa)) *
                p.LXAL;                                                        // (4.E54)
  const T alpha_s = in.alpha_star + shxa;                                      // (4.E53)
  return {MakeCurve(bxa, cxa, exa, alpha_s), MakeCurve(bxa, cxa, exa, shxa)};  // (4.E51-52)
}

// Combined-slip weighting of Fy0 by slip ratio, Gyk (4.E59-E65), as Gxa.
template <Value T>
HOTLAP_MF_MODEL_INLINE Weighting<T> CalcGykCurves(const Params<T>& p, const Inputs<T>& in,
                                                  const MagicFormulaOptions& options) {
  const T& dfz = in.dfz;
  const T shyk = p.RHY1 + p.RHY2 * dfz;  // (4.E65)
  T eyk = p.REY1 + p.REY2 * dfz;         // (4.E64)
  if (options.limits == MagicFormulaLimits::kClamp) eyk = CapAtOne(eyk);
  const T cyk = p.RCY1;  // (4.E63)
  const T byk = (p.RBY1 + p.RBY4 * in.gamma_star * in.gamma_star) *
                CosAtan(T(p.RBY2 * (in.alpha_star - p.RBY3))) * p.LYKA;        // (4.E62)
  const T kappa_s = in.kappa + shyk;                                           // (4.E61)
  return {MakeCurve(byk, cyk, eyk, kappa_s), MakeCurve(byk, cyk, eyk, shyk)};  // (4.E59-60)
}

// The kappa-induced side force SVyk (4.E66-E67), given sin(RVY5 atan(RVY6 kappa)).
template <Value T>
HOTLAP_MF_MODEL_INLINE T CalcSvyk(const Params<T>& p, const Inputs<T>& in, const T& muy,
                                  const T& sin_rvy) {
  const T dvyk = muy * in.fz * (p.RVY1 + p.RVY2 * in.dfz + p.RVY3 * in.gamma_star) *
                 CosAtan(T(p.RVY4 * in.alpha_star));  // (4.E67)
  T svyk = dvyk * sin_rvy * p.LVYKA;                  // (4.E66)
  if (Any(in.low_speed)) svyk *= in.reduction_smooth;
  return svyk;
}

// The load the overturning moment uses: below FZMIN reduced to Fz^3 / FZMIN^2 (mfeval,
// "empirically discovered").
template <Value T>
HOTLAP_MF_MODEL_INLINE T MxLoad(const Params<T>& p, const Inputs<T>& in) {
  const T& fz = in.fz;
  return Where(Lt(fz, p.FZMIN), T(fz * (fz / p.FZMIN) * (fz / p.FZMIN)), fz);
}

// Whether the QSX4 term of Mx is left out: for double parameters when QSX4 is zero (for a Jet it
// may carry a derivative).
template <class P>
HOTLAP_MF_MODEL_INLINE bool SkipQsx4(const MagicFormulaParams<P>& p) {
  return std::is_same_v<P, double> && ValueOf(p.QSX4) == 0.0;
}

// Overturning moment: the TNO equation manual's form of (4.E69) with QSX12-14 (mfeval), given
// atan(QSX11 Fz/Fz0), cos(QSX5 atan((QSX6 Fz/Fz0)^2)) and sin(QSX7 gamma + QSX8 atan(QSX9
// Fy/Fz0)) (the last two unused when SkipQsx4).
template <Value T>
HOTLAP_MF_MODEL_INLINE T CalcMx(const Params<T>& p, const Inputs<T>& in, const T& fy,
                                const T& atan_qsx11, const T& cos_qsx5, const T& sin_qsx7) {
  using std::abs;
  const T fz = MxLoad(p, in);
  const T& gamma = in.gamma;
  const T fy_n = fy / p.FNOMIN;
  const T r0 = p.UNLOADED_RADIUS;
  T bracket = p.QSX1 * p.LVMX - p.QSX2 * gamma * (1.0 + p.PPMX1 * in.dpi) + p.QSX3 * fy_n +
              p.QSX10 * atan_qsx11 * gamma;
  if (!SkipQsx4(p)) bracket += p.QSX4 * cos_qsx5 * sin_qsx7;
  return r0 * fz * p.LMX * bracket +
         r0 * p.LMX * (fy * (p.QSX13 + p.QSX14 * abs(gamma)) - fz * p.QSX12 * gamma * abs(gamma));
}

// The load the rolling-resistance moment uses: the load as given, reduced to Fz^2/FZMIN below
// FZMIN.
template <Value T>
HOTLAP_MF_MODEL_INLINE T MyLoad(const Params<T>& p, const Inputs<T>& in) {
  const T& fz = in.fz_unlimited;
  return Where(Lt(fz, p.FZMIN), T(fz * (fz / p.FZMIN)), fz);
}

// (Fz/Fz0)^QSY7 (p/p0)^QSY8 of (A48), zero at zero load (MF 6.x only).
template <Value T, class Math>
HOTLAP_MF_MODEL_INLINE T MyPower(const Params<T>& p, const Inputs<T>& in) {
  const T fz = MyLoad(p, in);
  T power(0.0);
  const MaskOf<T> loaded = Gt(fz, 0.0);
  if (p.version != MagicFormulaVersion::kMf52 && Any(loaded)) {
    const T fz0 = p.FNOMIN;
    power = Where(loaded,
                  Math::Exp(T(p.QSY7 * Math::Log(T(fz / fz0)) +
                              p.QSY8 * Math::Log(T(in.pressure / p.NOMPRES)))),
                  power);
  }
  return power;
}

// Rolling-resistance moment: (A48) for MF 6.x, the MF-Tyre 5.2 manual's form for 5.2, with
// mfeval's sign and low-speed handling, given MyPower. Uses the slip ratio as given.
template <Value T, class Math>
HOTLAP_MF_MODEL_INLINE T CalcMy(const Params<T>& p, const Inputs<T>& in, const T& fx,
                                const T& power) {
  using std::abs;
  const MaskOf<T> standstill = Eq(in.vx, 0.0);
  if (All(standstill)) return T(0.0);
  const T fz = MyLoad(p, in);
  const T fz0 = p.FNOMIN;
  const T r0 = p.UNLOADED_RADIUS;
  const T v = in.vx / p.LONGVL;
  const T v2 = v * v;
  const T base = p.QSY1 + p.QSY2 * (fx / fz0) + p.QSY3 * abs(v) + p.QSY4 * v2 * v2;
  T my;
  if (p.version == MagicFormulaVersion::kMf52) {
    my = -r0 * fz * p.LMY * base;
  } else {
    my = -r0 * fz0 * p.LMY * (base + (p.QSY5 + p.QSY6 * (fz / fz0)) * in.gamma * in.gamma) * power;
  }
  my = Where(Lt(in.vx, 0.0), T(-my), my);
  // Low speed (mfeval): between kappa = -1 and VXLOW/|Vx| - 1 the moment fades in with a sine;
  // below the mirrored limit the wheel spins backwards and the moment changes sign.
  const T high = p.VXLOW / abs(in.vx) - 1.0;
  const T low = -1.0 - p.VXLOW - high;
  const T& kappa = in.kappa_unlimited;
  const MaskOf<T> fading = Ge(kappa, low) && Le(kappa, high);
  if (Any(fading)) {
    my = Where(fading, T(my * Math::Sin(T(0.5 * kPi * (kappa + 1.0) / (high + 1.0)))), my);
  }
  my = Where(Lt(kappa, low), T(-my), my);
  return Where(standstill, T(0.0), my);
}

// Equivalent slip angle for combined slip, from tangents (A54-A55), mfeval's form:
// atan(sqrt(tan(alpha)^2 + kappa_term2)) sgn(alpha). The arctangent's argument given tan(alpha),
// or zero where sgn(alpha) = 0 (the result is then zero, see EquivalentSlip).
template <Value T>
HOTLAP_MF_MODEL_INLINE T EquivalentSlipArgument(const T& alpha, const T& tan_alpha,
                                                const T& kappa_term2) {
  using std::sqrt;
  const MaskOf<T> no_sign = Eq(Sign(alpha), 0.0);
  if (All(no_sign)) return T(0.0);
  return Where(no_sign, T(0.0), T(sqrt(tan_alpha * tan_alpha + kappa_term2)));
}

template <Value T>
HOTLAP_MF_MODEL_INLINE T EquivalentSlip(const T& alpha, const T& atan_argument) {
  const auto sign = Sign(alpha);
  return Where(Eq(sign, 0.0), T(0.0), T(atan_argument * sign));
}

// The pneumatic trail's slip angle (4.E34-E35) and its curve's B (A58) and C (4.E41).
template <Value T>
struct TrailCoefficients {
  T alpha_t, bt, ct;
};

template <Value T>
HOTLAP_MF_MODEL_INLINE TrailCoefficients<T> CalcTrailCoefficients(const Params<T>& p,
                                                                  const Inputs<T>& in) {
  using std::abs;
  const T& dfz = in.dfz;
  const T& gamma = in.gamma;
  const T sht = p.QHZ1 + p.QHZ2 * dfz + (p.QHZ3 + p.QHZ4 * dfz) * in.gamma_star;  // (4.E35)
  const T alpha_t = in.alpha_star + sht;                                          // (4.E34)
  const T bt = (p.QBZ1 + p.QBZ2 * dfz + p.QBZ3 * dfz * dfz) *
               (1.0 + p.QBZ4 * gamma + p.QBZ5 * abs(gamma)) * p.LKY / p.LMUY;  // (A58)
  const T ct = p.QCZ1;                                                         // (4.E41)
  return {alpha_t, bt, ct};
}

// The trail's curvature factor Et (4.E44), given atan(Bt Ct alpha_t); at most 1 with the limits.
template <Value T>
HOTLAP_MF_MODEL_INLINE T CalcTrailCurvature(const Params<T>& p, const Inputs<T>& in,
                                            const T& atan_bt_ct_alpha_t, bool limits) {
  const T& dfz = in.dfz;
  T et = (p.QEZ1 + p.QEZ2 * dfz + p.QEZ3 * dfz * dfz) *
         (1.0 + (p.QEZ4 + p.QEZ5 * in.gamma_star) * (2.0 / kPi) * atan_bt_ct_alpha_t);  // (4.E44)
  if (limits) et = CapAtOne(et);
  return et;
}

// The residual torque's slip angle alpha_r (4.E37-38) and the square of the term the slip ratio
// adds to both equivalent slip angles (A54-A55).
template <Value T>
HOTLAP_MF_MODEL_INLINE std::pair<T, T> CalcResidualSlip(const Inputs<T>& in,
                                                        const PureLateral<T>& lat,
                                                        const PureLongitudinal<T>& lon) {
  const T kya_prime = lat.kya + kEpsilon * SignOr1(lat.kya);        // (4.E39)
  const T alpha_r = in.alpha_star + lat.shy + lat.svy / kya_prime;  // (4.E37-38)
  const T kappa_term = lon.kxk / kya_prime * in.kappa;
  const T kappa_term2 = kappa_term * kappa_term;
  return {alpha_r, kappa_term2};
}

// The cosines that finish the weightings, given their curves' outer arctangents: Gxa (4.E51)
// and Gyk (4.E59).
template <Value T, class Math>
HOTLAP_MF_MODEL_INLINE std::pair<T, T> FinishWeightings(const Weighting<T>& gxa_curves,
                                                        const Weighting<T>& gyk_curves,
                                                        const std::array<T, 4>& outer_atan) {
  const std::array<T, 4> cosines = Math::SinOrCos(
      std::array<T, 4>{
          T(gxa_curves.num.c * outer_atan[0]),
          T(gxa_curves.den.c * outer_atan[1]),
          T(gyk_curves.num.c * outer_atan[2]),
          T(gyk_curves.den.c * outer_atan[3]),
      },
      0b1111u);
  return {cosines[0] / cosines[1], cosines[2] / cosines[3]};  // (4.E51), (4.E59)
}

// The aligning torque's parts: the pneumatic trail t, the residual torque mzr and the arm s of
// Fx (4.E71).
template <Value T>
struct AligningTorqueParts {
  T t, mzr, s;
};

// Pneumatic trail (4.E33-E44 with mfeval's choices), given cos(Ct atan(...)) of its curve, and
// residual torque (4.E45-E47, 4.E75), given cos(alpha*) and the equivalent slip angle alpha_r,eq;
// both reduced at low speed. And the arm s of Fx (A56).
template <Value T>
HOTLAP_MF_MODEL_INLINE AligningTorqueParts<T> CalcAligningTorqueParts(
    const Params<T>& p, const Inputs<T>& in, const PureLateral<T>& lat, const T& fz_t,
    const T& trail_cos, const T& cos_alpha_star, const T& alpha_r_eq, const T& fy) {
  using std::abs;
  const T& dfz = in.dfz;
  const T& gamma = in.gamma;
  const T& gamma_star = in.gamma_star;
  const T r0 = p.UNLOADED_RADIUS;
  const T dt = (p.QDZ1 + p.QDZ2 * dfz) * (1.0 - p.PPZ1 * in.dpi) *
               (1.0 + p.QDZ3 * gamma + p.QDZ4 * gamma * gamma) * fz_t * (r0 / in.fz0_prime) *
               p.LTR;                                  // (A60)
  T t = dt * trail_cos * in.cos_alpha_prime * p.LFZO;  // (4.E73), mfeval
  const T dr =
      fz_t * r0 *
      ((p.QDZ6 + p.QDZ7 * dfz) * p.LRES + ((p.QDZ8 + p.QDZ9 * dfz) * (1.0 + p.PPZ2 * in.dpi) +
                                           (p.QDZ10 + p.QDZ11 * dfz) * abs(gamma_star)) *
                                              gamma_star * p.LKZC) *
      p.LMUY * Sign(in.vx) * cos_alpha_star;                         // (4.E47)
  const T br = p.QBZ9 * p.LKY / p.LMUY + p.QBZ10 * lat.by * lat.cy;  // (4.E45)
  T mzr = dr * CosAtan(T(br * alpha_r_eq));                          // (4.E75), Cr = 1
  if (Any(in.low_speed)) {
    t *= in.reduction_smooth;
    mzr *= in.reduction_smooth;
  }
  const T s =
      r0 * (p.SSZ1 + p.SSZ2 * (fy / p.FNOMIN) + (p.SSZ3 + p.SSZ4 * dfz) * gamma) * p.LS;  // (A56)
  return {t, mzr, s};
}

// The whole model, in stages of batched transcendental functions (see the file comment).
//
// The longest chains of dependent functions run through the cornering stiffness: Kya (atan,
// sin), then Fy0's curve (atan, atan, sin) and Mx's (atan, sin), or the equivalent slip angle
// (tan, atan) and the trail's curve (atan, atan, cos). Each stage puts that chain's next batch
// first and the work that does not wait for it after, so the processor has the independent work
// in view while a batch is in flight.
template <Value T, class Math>
HOTLAP_MF_MODEL_INLINE Outputs<T> Evaluate(const Params<T>& p, const Point<T>& op,
                                           const MagicFormulaOptions& options) {
  const Inputs<T> in = PrepareInputs<T, Math>(p, op, options);
  const bool mf52 = p.version == MagicFormulaVersion::kMf52;
  const bool limits = options.limits == MagicFormulaLimits::kClamp;
  const T& gamma = in.gamma;
  const T& gamma_star = in.gamma_star;
  const T zero(0.0);

  // Stage 1: the arctangents of the cornering stiffness (4.E25) at the camber and at zero camber
  // (MF 6.x Mz), of SVyk (4.E66) and of Mx's load term.
  const T mx_fz_n = MxLoad(p, in) / p.FNOMIN;
  const std::array<T, 4> atan1 =
      Math::Atan(std::array<T, 4>{KyaArgument(p, in, gamma_star), KyaArgument(p, in, zero),
                                  T(p.RVY6 * in.kappa), T(p.QSX11 * mx_fz_n)});
  // ... and meanwhile Fx0's coefficients, Gxa's and Gyk's curves, the trail's factors, and the
  // first arctangents of all of them.
  const PureLongitudinal<T> lon = CalcFx0Coefficients<T, Math>(p, in);
  const Weighting<T> gxa_curves = CalcGxaCurves(p, in);
  const Weighting<T> gyk_curves = CalcGykCurves(p, in, options);
  const T q6 = p.QSX6 * mx_fz_n;
  const T& fz_t = limits ? in.fz_trail : in.fz;
  const auto [alpha_t, bt, ct] = CalcTrailCoefficients(p, in);
  const std::array<T, 7> atan1b = Math::Atan(std::array<T, 7>{
      lon.curve.bx,          // 0: Fx0
      gxa_curves.num.bx,     // 1: Gxa
      gxa_curves.den.bx,     // 2
      gyk_curves.num.bx,     // 3: Gyk
      gyk_curves.den.bx,     // 4
      T(bt * ct * alpha_t),  // 5: Et (4.E44)
      T(q6 * q6),            // 6: Mx
  });

  // Stage 2: the sines that finish Kya and SVyk ...
  const std::array<T, 3> sin2 = Math::SinOrCos(
      std::array<T, 3>{T(p.PKY4 * atan1[0]), T(p.PKY4 * atan1[1]), T(p.RVY5 * atan1[2])}, 0u);
  // ... and meanwhile the outer arctangents of the weightings' curves (Fx0's waits for a free
  // lane in stage 3), the trail's curvature factor and tan(alpha_t).
  const std::array<T, 4> atan2 = Math::Atan(std::array<T, 4>{
      OuterArgument(gxa_curves.num, atan1b[1]),
      OuterArgument(gxa_curves.den, atan1b[2]),
      OuterArgument(gyk_curves.num, atan1b[3]),
      OuterArgument(gyk_curves.den, atan1b[4]),
  });
  const T et = CalcTrailCurvature(p, in, atan1b[5], limits);
  const T tan_alpha_t = Math::Tan(alpha_t);

  // Stage 3: the pure lateral force's coefficients at both cambers and their curves' first
  // arctangents, and the equivalent slip angles of the aligning torque (A54-A55) ...
  const PureLateral<T> lat = CalcFy0Coefficients(p, in, gamma_star, sin2[0], options);
  // (MF 5.2's Mz does not use Fy0 at zero camber: its lanes then repeat the cambered one's.)
  const PureLateral<T> lat_flat = mf52 ? lat : CalcFy0Coefficients(p, in, zero, sin2[1], options);
  const auto [alpha_r, kappa_term2] = CalcResidualSlip(in, lat, lon);
  const std::array<T, 4> atan3 = Math::Atan(std::array<T, 4>{
      lat.curve.bx,
      lat_flat.curve.bx,
      EquivalentSlipArgument(alpha_t, tan_alpha_t, kappa_term2),
      OuterArgument(lon.curve, atan1b[0]),
  });
  // (The residual torque's slip angle waits for stage 6: its tangent would hold up this batch.)
  const T tan_alpha_r = Math::Tan(alpha_r);
  // ... and meanwhile the cosines that finish the weightings (4.E51, 4.E59).
  const auto [gxa, gyk] = FinishWeightings<T, Math>(gxa_curves, gyk_curves, atan2);
  const T alpha_t_eq = EquivalentSlip(alpha_t, atan3[2]);          // (A55)
  const Curve<T> trail_curve = MakeCurve(bt, ct, et, alpha_t_eq);  // (4.E73)

  // Stage 4: the outer arctangents of the lateral curves and the first of the trail's ...
  const std::array<T, 3> atan4 = Math::Atan(std::array<T, 3>{
      OuterArgument(lat.curve, atan3[0]),
      OuterArgument(lat_flat.curve, atan3[1]),
      trail_curve.bx,
  });
  // ... and meanwhile SVyk and the power of the load in My.
  const T svyk = CalcSvyk(p, in, CalcMuy(p, in, gamma_star), sin2[2]);
  const T power = MyPower<T, Math>(p, in);

  // Stage 5: the lateral curves' sines and Fx0's.
  const std::array<T, 3> sin5 =
      Math::SinOrCos(std::array<T, 3>{T(lat.curve.c * atan4[0]), T(lat_flat.curve.c * atan4[1]),
                                      T(lon.curve.c * atan3[3])},
                     0u);
  Outputs<T> out;
  out.fx = gxa * CalcFx0(lon, in, sin5[2]);  // (4.E50)

  // The lateral force (4.E58), then stage 6: the arctangent of Fy in Mx, the trail's outer
  // arctangent and the residual torque's slip angle; stage 7: Mx's sine and cosine, the trail's
  // cosine and Dr's cos(alpha*).
  const T fy0 = CalcFy0(lat, in, sin5[0], options);
  out.fy = gyk * fy0 + svyk;
  const T fy_n = out.fy / p.FNOMIN;
  const std::array<T, 3> atan6 = Math::Atan(std::array<T, 3>{
      OuterArgument(trail_curve, atan4[2]),
      SkipQsx4(p) ? zero : T(p.QSX9 * fy_n),
      EquivalentSlipArgument(alpha_r, tan_alpha_r, kappa_term2),
  });
  const T alpha_r_eq = EquivalentSlip(alpha_r, atan6[2]);  // (A54)
  const std::array<T, 4> trig7 = Math::SinOrCos(
      std::array<T, 4>{
          T(trail_curve.c * atan6[0]),            // 0: cos, trail (4.E73)
          T(p.QSX7 * gamma + p.QSX8 * atan6[1]),  // 1: sin, Mx
          T(p.QSX5 * atan1b[6]),                  // 2: cos, Mx
          in.alpha_star,                          // 3: cos, Dr (4.E47)
      },
      0b1101u);
  out.mx = CalcMx(p, in, out.fy, atan1[3], trig7[2], trig7[1]);
  out.my = CalcMy<T, Math>(p, in, out.fx, power);

  // Aligning torque: pneumatic trail, residual torque and Fx's arm.
  const auto [t, mzr, s] =
      CalcAligningTorqueParts(p, in, lat, fz_t, trig7[0], trig7[3], alpha_r_eq, out.fy);
  if (mf52) {
    out.mz = -t * (out.fy - svyk) + mzr + s * out.fx;  // MF-Tyre 5.2 manual (mfeval)
  } else {
    // Mz' from Fy0 at zero camber, weighted by Gyk at the actual camber (4.E72, 4.E74, mfeval).
    const T fy0_flat = CalcFy0(lat_flat, in, sin5[1], options);
    out.mz = -t * gyk * fy0_flat + mzr + s * out.fx;  // (4.E71)
  }
  return out;
}

}  // namespace hotlap::tyre::internal::model
