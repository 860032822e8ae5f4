// CalcMagicFormula against a reference: the model as it was written before it was made fast
// (every equation in turn, one libm call per function, the Fy0 of Mz' computed again), kept here
// verbatim. The two may differ only by rounding: the fast model takes every transcendental
// function from glibc's libmvec (magic_formula_simd.h; a few ulp from libm, and not the same
// bits on every instruction set) and visits the equations in another order, with the same
// operations.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/units.h"
#include "hotlap/tyre/magic_formula.h"
#include "hotlap/tyre/magic_formula_math.h"
#include "test_util.h"

namespace hotlap::tyre {
namespace {

// ---------------------------------------------------------------------------------------------
// The reference model (magic_formula.cc before the batched version).

// The small number that keeps denominators away from zero (4.E6a).
constexpr double kEpsilon = 1e-6;

// MATLAB's sign(): -1, 0 or 1.
template <Scalar T>
double Sign(const T& x) {
  const double v = ValueOf(x);
  return v > 0.0 ? 1.0 : (v < 0.0 ? -1.0 : 0.0);
}

// sign() with sign(0) = 1, as mfeval uses it to keep denominators non-zero.
template <Scalar T>
double SignOr1(const T& x) {
  return ValueOf(x) < 0.0 ? -1.0 : 1.0;
}

template <Scalar T>
T Clamp(const T& x, const T& lo, const T& hi) {
  if (ValueOf(x) < ValueOf(lo)) return lo;
  if (ValueOf(x) > ValueOf(hi)) return hi;
  return x;
}

// cos(atan(x)) = 1/sqrt(1 + x^2), cheaper and the same value.
template <Scalar T>
T CosAtan(const T& x) {
  using std::sqrt;
  return 1.0 / sqrt(1.0 + x * x);
}

// The Magic Formula's argument: C atan(B x - E (B x - atan(B x))) (4.E9).
template <Scalar T>
T MagicArgument(const T& b, const T& c, const T& e, const T& x) {
  using std::atan;
  const T bx = b * x;
  return c * atan(bx - e * (bx - atan(bx)));
}

// The inputs after mfeval's limit checks, and the quantities every force and moment uses.
template <Scalar T>
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
  bool low_speed = false;
  T reduction_smooth;  // 1 above VXLOW, -> 0 at standstill
  T dfz;               // (4.E2a)
  T dpi;               // (4.E2b)
  T fz0_prime;         // (4.E1)
  T alpha_star;        // (4.E3) or alpha
  T gamma_star;        // (4.E4) or gamma
  T cos_alpha_prime;   // cos of (4.E6): Vcx / Vc'
};

template <Scalar T>
Inputs<T> PrepareInputs(const MagicFormulaParams<T>& p, const TyreOperatingPoint<T>& op,
                        const MagicFormulaOptions& options) {
  using std::abs;
  using std::cos;
  using std::sin;
  using std::sqrt;
  using std::tan;
  Inputs<T> in;
  in.fz = ValueOf(op.fz) < 0.0 ? T(0.0) : op.fz;
  in.fz_unlimited = in.fz;
  in.fz_trail = in.fz;
  in.kappa = op.slip_ratio;
  in.kappa_unlimited = op.slip_ratio;
  in.alpha = op.slip_angle;
  in.gamma = op.camber;
  in.vx = op.speed;
  in.pressure = ValueOf(op.pressure) != 0.0 ? op.pressure : p.INFLPRES;
  in.reduction_smooth = T(1.0);
  if (options.limits == MagicFormulaLimits::kClamp) {
    // Low-speed model: slip and shifts fade out below VXLOW (mfeval parseInputs).
    if (abs(ValueOf(in.vx)) <= ValueOf(p.VXLOW)) {
      in.low_speed = true;
      in.reduction_smooth = 1.0 - 0.5 * (1.0 + cos(kPi * in.vx / p.VXLOW));
      in.kappa *= abs(in.vx / p.VXLOW);
    }
    const T speed_sum = abs(in.vx) + abs(tan(in.alpha) * in.vx);
    if (ValueOf(speed_sum) < ValueOf(p.VXLOW)) in.alpha *= speed_sum / p.VXLOW;
    in.alpha = Clamp(in.alpha, p.ALPMIN, p.ALPMAX);
    in.gamma = Clamp(in.gamma, p.CAMMIN, p.CAMMAX);
    if (ValueOf(in.fz) > ValueOf(p.FZMAX)) in.fz = p.FZMAX;
    in.fz_trail = in.fz;
    if (ValueOf(in.fz) < ValueOf(p.FZMIN)) in.fz_trail = p.FZMIN;
    if (ValueOf(in.fz) <= 0.0) in.fz_trail = T(0.0);
    in.pressure = Clamp(in.pressure, p.PRESMIN, p.PRESMAX);
    in.kappa = Clamp(in.kappa, p.KPUMIN, p.KPUMAX);
  }
  in.fz0_prime = p.LFZO * p.FNOMIN;                // (4.E1)
  in.dfz = (in.fz - in.fz0_prime) / in.fz0_prime;  // (4.E2a)
  in.dpi = (in.pressure - p.NOMPRES) / p.NOMPRES;  // (4.E2b)
  const T tan_alpha = tan(in.alpha);
  if (options.slip_form == MagicFormulaSlipForm::kTangent) {
    in.alpha_star = tan_alpha * Sign(in.vx);  // (4.E3)
    in.gamma_star = sin(in.gamma);            // (4.E4)
  } else {
    in.alpha_star = in.alpha;
    in.gamma_star = in.gamma;
  }
  // Contact-centre speed, Vcy = Vsy = tan(alpha) |Vx| (2.12), and cos(alpha') (4.E6).
  const T vcy = tan_alpha * abs(in.vx);
  const T vc2 = in.vx * in.vx + vcy * vcy;
  const T vc = ValueOf(vc2) > 0.0 ? sqrt(vc2) : T(0.0);
  in.cos_alpha_prime = in.vx / (vc + kEpsilon);
  return in;
}

// Pure longitudinal force (4.E9-E18). Returns Fx0; writes mux and Kxk.
template <Scalar T>
T CalcFx0(const MagicFormulaParams<T>& p, const Inputs<T>& in, T& kxk) {
  using std::exp;
  using std::sin;
  const T& dfz = in.dfz;
  const T& dpi = in.dpi;
  const T cx = p.PCX1 * p.LCX;  // (4.E11)
  T mux = (p.PDX1 + p.PDX2 * dfz) * (1.0 + p.PPX3 * dpi + p.PPX4 * dpi * dpi) *
          (1.0 - p.PDX3 * in.gamma * in.gamma) * p.LMUX;  // (4.E13)
  if (ValueOf(in.fz) == 0.0) mux = T(0.0);
  const T dx = mux * in.fz;  // (4.E12)
  kxk = in.fz * (p.PKX1 + p.PKX2 * dfz) * exp(p.PKX3 * dfz) *
        (1.0 + p.PPX1 * dpi + p.PPX2 * dpi * dpi) * p.LKX;   // (4.E15)
  const T bx = kxk / (cx * dx + kEpsilon * SignOr1(dx));     // (4.E16)
  T shx = (p.PHX1 + p.PHX2 * dfz) * p.LHX;                   // (4.E17)
  T svx = in.fz * (p.PVX1 + p.PVX2 * dfz) * p.LVX * p.LMUX;  // (4.E18)
  if (in.low_speed) {
    svx *= in.reduction_smooth;
    shx *= in.reduction_smooth;
  }
  const T kappa_x = in.kappa + shx;  // (4.E10)
  const T ex = (p.PEX1 + p.PEX2 * dfz + p.PEX3 * dfz * dfz) * (1.0 - p.PEX4 * Sign(kappa_x)) *
               p.LEX;                                          // (4.E14)
  T fx0 = dx * sin(MagicArgument(bx, cx, ex, kappa_x)) + svx;  // (4.E9)
  if (ValueOf(in.vx) < 0.0) fx0 = -fx0;
  return fx0;
}

// Pure lateral force and the coefficients the aligning torque reuses.
template <Scalar T>
struct PureLateral {
  T fy0;
  T muy;
  T kya;  // cornering stiffness (4.E25)
  T shy;
  T svy;
  T by;
  T cy;
};

// Pure lateral force (4.E19-E30) at camber `gamma_star`.
template <Scalar T>
PureLateral<T> CalcFy0(const MagicFormulaParams<T>& p, const Inputs<T>& in, const T& gamma_star,
                       const MagicFormulaOptions& options) {
  using std::abs;
  using std::atan;
  using std::sin;
  const T& fz = in.fz;
  const T& dfz = in.dfz;
  const T& dpi = in.dpi;
  const T& fz0p = in.fz0_prime;
  const T g2 = gamma_star * gamma_star;
  PureLateral<T> r;
  r.kya = p.PKY1 * fz0p * (1.0 + p.PPY1 * dpi) * (1.0 - p.PKY3 * abs(gamma_star)) *
          sin(p.PKY4 * atan((fz / fz0p) / ((p.PKY2 + p.PKY5 * g2) * (1.0 + p.PPY2 * dpi)))) *
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
  if (in.low_speed) {
    r.svy *= in.reduction_smooth;
    r.shy *= in.reduction_smooth;
  }
  const T alpha_y = in.alpha_star + r.shy;  // (4.E20)
  r.cy = p.PCY1 * p.LCY;                    // (4.E21)
  r.muy = (p.PDY1 + p.PDY2 * dfz) * (1.0 + p.PPY3 * dpi + p.PPY4 * dpi * dpi) *
          (1.0 - p.PDY3 * g2) * p.LMUY;  // (4.E23)
  const T dy = r.muy * fz;               // (4.E22)
  T ey = (p.PEY1 + p.PEY2 * dfz) *
         (1.0 + p.PEY5 * g2 - (p.PEY3 + p.PEY4 * gamma_star) * SignOr1(alpha_y)) *
         p.LEY;  // (4.E24)
  if (options.limits == MagicFormulaLimits::kClamp && ValueOf(ey) > 1.0) ey = T(1.0);
  r.by = r.kya / (r.cy * dy + kEpsilon * SignOr1(dy));               // (4.E26)
  r.fy0 = dy * sin(MagicArgument(r.by, r.cy, ey, alpha_y)) + r.svy;  // (4.E19)
  if (options.slip_form == MagicFormulaSlipForm::kTangent && ValueOf(in.vx) < 0.0) r.fy0 = -r.fy0;
  return r;
}

// Combined-slip weighting of Fx0 by slip angle, Gxa (4.E51-E57).
template <Scalar T>
T CalcGxa(const MagicFormulaParams<T>& p, const Inputs<T>& in) {
  using std::cos;
  const T cxa = p.RCX1;                    // (4.E55)
  const T exa = p.REX1 + p.REX2 * in.dfz;  // (4.E56)
  const T shxa = p.RHX1;                   // (4.E57)
  const T bxa = (p.RBX1 + p.RBX3 * in.gamma_star * in.gamma_star) * CosAtan(T(p.RBX2 * in.kappa)) *
                p.LXAL;                    // (4.E54)
  const T alpha_s = in.alpha_star + shxa;  // (4.E53)
  return cos(MagicArgument(bxa, cxa, exa, alpha_s)) /
         cos(MagicArgument(bxa, cxa, exa, shxa));  // (4.E51-52)
}

// Combined-slip weighting of Fy0 by slip ratio, Gyk (4.E59-E65), and the kappa-induced side
// force SVyk (4.E66-E67).
template <Scalar T>
void CalcGyk(const MagicFormulaParams<T>& p, const Inputs<T>& in, const T& muy,
             const MagicFormulaOptions& options, T& gyk, T& svyk) {
  using std::atan;
  using std::cos;
  using std::sin;
  const T& dfz = in.dfz;
  const T dvyk = muy * in.fz * (p.RVY1 + p.RVY2 * dfz + p.RVY3 * in.gamma_star) *
                 CosAtan(T(p.RVY4 * in.alpha_star));              // (4.E67)
  svyk = dvyk * sin(p.RVY5 * atan(p.RVY6 * in.kappa)) * p.LVYKA;  // (4.E66)
  const T shyk = p.RHY1 + p.RHY2 * dfz;                           // (4.E65)
  T eyk = p.REY1 + p.REY2 * dfz;                                  // (4.E64)
  if (options.limits == MagicFormulaLimits::kClamp && ValueOf(eyk) > 1.0) eyk = T(1.0);
  const T cyk = p.RCY1;  // (4.E63)
  const T byk = (p.RBY1 + p.RBY4 * in.gamma_star * in.gamma_star) *
                CosAtan(T(p.RBY2 * (in.alpha_star - p.RBY3))) * p.LYKA;  // (4.E62)
  const T kappa_s = in.kappa + shyk;                                     // (4.E61)
  gyk = cos(MagicArgument(byk, cyk, eyk, kappa_s)) /
        cos(MagicArgument(byk, cyk, eyk, shyk));  // (4.E59-60)
  if (in.low_speed) svyk *= in.reduction_smooth;
}

// Overturning moment: the TNO equation manual's form of (4.E69) with QSX12-14 (mfeval). Below
// FZMIN the load is reduced to Fz^3 / FZMIN^2 (mfeval, "empirically discovered").
template <Scalar T>
T CalcMx(const MagicFormulaParams<T>& p, const Inputs<T>& in, const T& fy) {
  using std::abs;
  using std::atan;
  using std::cos;
  using std::sin;
  T fz = in.fz;
  if (ValueOf(fz) < ValueOf(p.FZMIN)) fz = fz * (fz / p.FZMIN) * (fz / p.FZMIN);
  const T& gamma = in.gamma;
  const T fz_n = fz / p.FNOMIN;
  const T fy_n = fy / p.FNOMIN;
  const T r0 = p.UNLOADED_RADIUS;
  T bracket = p.QSX1 * p.LVMX - p.QSX2 * gamma * (1.0 + p.PPMX1 * in.dpi) + p.QSX3 * fy_n +
              p.QSX10 * atan(p.QSX11 * fz_n) * gamma;
  const bool skip_qsx4 = std::is_same_v<T, double> && ValueOf(p.QSX4) == 0.0;
  if (!skip_qsx4) {
    const T q6 = p.QSX6 * fz_n;
    bracket +=
        p.QSX4 * cos(p.QSX5 * atan(q6 * q6)) * sin(p.QSX7 * gamma + p.QSX8 * atan(p.QSX9 * fy_n));
  }
  return r0 * fz * p.LMX * bracket +
         r0 * p.LMX * (fy * (p.QSX13 + p.QSX14 * abs(gamma)) - fz * p.QSX12 * gamma * abs(gamma));
}

// Rolling-resistance moment: (A48) for MF 6.x, the MF-Tyre 5.2 manual's form for 5.2, with
// mfeval's sign and low-speed handling. Uses the load as given (reduced to Fz^2/FZMIN below
// FZMIN) and the slip ratio as given.
template <Scalar T>
T CalcMy(const MagicFormulaParams<T>& p, const Inputs<T>& in, const T& fx) {
  using std::abs;
  using std::exp;
  using std::log;
  using std::sin;
  if (ValueOf(in.vx) == 0.0) return T(0.0);
  T fz = in.fz_unlimited;
  if (ValueOf(fz) < ValueOf(p.FZMIN)) fz = fz * (fz / p.FZMIN);
  const T fz0 = p.FNOMIN;
  const T r0 = p.UNLOADED_RADIUS;
  const T v = in.vx / p.LONGVL;
  const T v2 = v * v;
  const T base = p.QSY1 + p.QSY2 * (fx / fz0) + p.QSY3 * abs(v) + p.QSY4 * v2 * v2;
  T my;
  if (p.version == MagicFormulaVersion::kMf52) {
    my = -r0 * fz * p.LMY * base;
  } else {
    // (Fz/Fz0)^QSY7 (p/p0)^QSY8, zero at zero load.
    T power(0.0);
    if (ValueOf(fz) > 0.0) {
      power = exp(p.QSY7 * log(fz / fz0) + p.QSY8 * log(in.pressure / p.NOMPRES));
    }
    my = -r0 * fz0 * p.LMY * (base + (p.QSY5 + p.QSY6 * (fz / fz0)) * in.gamma * in.gamma) * power;
  }
  if (ValueOf(in.vx) < 0.0) my = -my;
  // Low speed (mfeval): between kappa = -1 and VXLOW/|Vx| - 1 the moment fades in with a sine;
  // below the mirrored limit the wheel spins backwards and the moment changes sign.
  const T high = p.VXLOW / abs(in.vx) - 1.0;
  const T low = -1.0 - p.VXLOW - high;
  const T& kappa = in.kappa_unlimited;
  if (ValueOf(kappa) >= ValueOf(low) && ValueOf(kappa) <= ValueOf(high)) {
    my *= sin(0.5 * kPi * (kappa + 1.0) / (high + 1.0));
  }
  if (ValueOf(kappa) < ValueOf(low)) my = -my;
  return my;
}

// Equivalent slip angle for combined slip, from tangents (A54-A55), mfeval's form.
template <Scalar T>
T EquivalentSlip(const T& alpha, const T& kappa_term2) {
  using std::atan;
  using std::sqrt;
  using std::tan;
  const double sign = Sign(alpha);
  if (sign == 0.0) return T(0.0);
  const T t = tan(alpha);
  return atan(sqrt(t * t + kappa_term2)) * sign;
}

template <Scalar T>
TyreForces<T> CalcMagicFormulaReference(const MagicFormulaParams<T>& p,
                                        const TyreOperatingPoint<T>& op,
                                        const MagicFormulaOptions& options) {
  using std::abs;
  using std::atan;
  using std::cos;
  const Inputs<T> in = PrepareInputs(p, op, options);
  const bool mf52 = p.version == MagicFormulaVersion::kMf52;
  const bool limits = options.limits == MagicFormulaLimits::kClamp;
  const T& dfz = in.dfz;
  const T& gamma = in.gamma;
  const T& gamma_star = in.gamma_star;

  // Pure slip.
  T kxk;
  const T fx0 = CalcFx0(p, in, kxk);
  const PureLateral<T> lat = CalcFy0(p, in, gamma_star, options);

  // Combined slip (4.E50, 4.E58).
  TyreForces<T> out;
  out.fx = CalcGxa(p, in) * fx0;
  T gyk, svyk;
  CalcGyk(p, in, lat.muy, options, gyk, svyk);
  out.fy = gyk * lat.fy0 + svyk;

  out.mx = CalcMx(p, in, out.fy);
  out.my = CalcMy(p, in, out.fx);

  // Aligning torque: pneumatic trail (4.E33-E44 with mfeval's choices) ...
  const T r0 = p.UNLOADED_RADIUS;
  const T& fz_t = limits ? in.fz_trail : in.fz;
  const T sht = p.QHZ1 + p.QHZ2 * dfz + (p.QHZ3 + p.QHZ4 * dfz) * gamma_star;  // (4.E35)
  const T kya_prime = lat.kya + kEpsilon * SignOr1(lat.kya);                   // (4.E39)
  const T alpha_r = in.alpha_star + lat.shy + lat.svy / kya_prime;             // (4.E37-38)
  const T alpha_t = in.alpha_star + sht;                                       // (4.E34)
  const T dt = (p.QDZ1 + p.QDZ2 * dfz) * (1.0 - p.PPZ1 * in.dpi) *
               (1.0 + p.QDZ3 * gamma + p.QDZ4 * gamma * gamma) * fz_t * (r0 / in.fz0_prime) *
               p.LTR;  // (A60)
  const T bt = (p.QBZ1 + p.QBZ2 * dfz + p.QBZ3 * dfz * dfz) *
               (1.0 + p.QBZ4 * gamma + p.QBZ5 * abs(gamma)) * p.LKY / p.LMUY;  // (A58)
  const T ct = p.QCZ1;                                                         // (4.E41)
  T et = (p.QEZ1 + p.QEZ2 * dfz + p.QEZ3 * dfz * dfz) *
         (1.0 + (p.QEZ4 + p.QEZ5 * gamma_star) * (2.0 / kPi) * atan(bt * ct * alpha_t));  // (4.E44)
  if (limits && ValueOf(et) > 1.0) et = T(1.0);
  const T kappa_term = kxk / kya_prime * in.kappa;
  const T kappa_term2 = kappa_term * kappa_term;
  const T alpha_t_eq = EquivalentSlip(alpha_t, kappa_term2);  // (A55)
  T t = dt * cos(MagicArgument(bt, ct, et, alpha_t_eq)) * in.cos_alpha_prime *
        p.LFZO;  // (4.E73), mfeval

  // ... and residual torque (4.E45-E47, 4.E75).
  const T dr =
      fz_t * r0 *
      ((p.QDZ6 + p.QDZ7 * dfz) * p.LRES + ((p.QDZ8 + p.QDZ9 * dfz) * (1.0 + p.PPZ2 * in.dpi) +
                                           (p.QDZ10 + p.QDZ11 * dfz) * abs(gamma_star)) *
                                              gamma_star * p.LKZC) *
      p.LMUY * Sign(in.vx) * cos(in.alpha_star);                     // (4.E47)
  const T br = p.QBZ9 * p.LKY / p.LMUY + p.QBZ10 * lat.by * lat.cy;  // (4.E45)
  const T alpha_r_eq = EquivalentSlip(alpha_r, kappa_term2);         // (A54)
  T mzr = dr * CosAtan(T(br * alpha_r_eq));                          // (4.E75), Cr = 1
  if (in.low_speed) {
    t *= in.reduction_smooth;
    mzr *= in.reduction_smooth;
  }
  const T s = r0 * (p.SSZ1 + p.SSZ2 * (out.fy / p.FNOMIN) + (p.SSZ3 + p.SSZ4 * dfz) * gamma) *
              p.LS;  // (A56)
  if (mf52) {
    out.mz = -t * (out.fy - svyk) + mzr + s * out.fx;  // MF-Tyre 5.2 manual (mfeval)
  } else {
    // Mz' from Fy0 at zero camber, weighted by Gyk at the actual camber (4.E72, 4.E74, mfeval).
    T fy0_flat;
    if constexpr (std::is_same_v<T, double>) {
      fy0_flat = gamma_star == 0.0 ? lat.fy0 : CalcFy0(p, in, T(0.0), options).fy0;
    } else {
      fy0_flat = CalcFy0(p, in, T(0.0), options).fy0;
    }
    out.mz = -t * gyk * fy0_flat + mzr + s * out.fx;  // (4.E71)
  }
  return out;
}

// ---------------------------------------------------------------------------------------------

MagicFormulaParams<double> LoadReferenceTir(const std::string& name) {
  return LoadMagicFormula(test::SourcePath("tests/data/tir/mfeval/" + name + ".tir"));
}

// Operating points over and beyond the files' ranges: loads from below zero to twice FNOMIN,
// slip ratios to 1.2, slip angles to 80 deg, cambers to 7 deg, speeds from -10 to 70 m/s
// (standstill and low speed included), pressures around INFLPRES or 0 (= INFLPRES), and exact
// zeros of slip and camber.
std::vector<TyreOperatingPoint<double>> RandomReferencePoints(const MagicFormulaParams<double>& p,
                                                              int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<TyreOperatingPoint<double>> points;
  for (int i = 0; i < n; ++i) {
    TyreOperatingPoint<double> op;
    op.fz = p.FNOMIN * (2.1 * unit(rng) - 0.1);
    op.slip_ratio = (2.0 * unit(rng) - 1.0) * (i % 3 == 0 ? 1.2 : 0.3);
    op.slip_angle = (2.0 * unit(rng) - 1.0) * (i % 5 == 0 ? 1.4 : 0.3);
    op.camber = (2.0 * unit(rng) - 1.0) * 0.12;
    op.speed = i % 7 == 0 ? 4.0 * unit(rng) - 2.0 : 80.0 * unit(rng) - 10.0;
    op.pressure = i % 2 == 1 ? 0.0 : p.INFLPRES * (0.7 + 0.6 * unit(rng));
    if (i % 11 == 0) op.camber = 0.0;
    if (i % 13 == 0) op.slip_angle = 0.0;
    if (i % 17 == 0) op.slip_ratio = 0.0;
    if (i % 19 == 0) op.speed = 0.0;
    points.push_back(op);
  }
  return points;
}

std::array<double, 5> ReferenceOutputs(const TyreForces<double>& f) {
  return {f.fx, f.fy, f.mx, f.my, f.mz};
}

// Rounding-level agreement: 1e-12 of the output's size, with N and N m scales at least 1000.
// libmvec's results are up to 3 ulp from libm's (magic_formula_math_test.cc); through the model's
// chains of functions, and where it subtracts nearly equal terms (Mz's sum of moments, the
// weighting cosines' quotients), the worst differences measured are 3.5e-14 of an output's size
// for the values and 1.1e-13 for the Jets' derivatives (printed by the tests; the SSE2 and AVX2
// lanes differ from each other by 5e-15 at most), so 1e-12 leaves a margin of about ten and still
// fails on any error in the equations.
constexpr double kTolerance = 1e-12;

// The difference of `got` from `want` in units of the output's size (0 when both are NaN).
double ScaledDifference(double got, double want) {
  if (std::isnan(want) && std::isnan(got)) return 0.0;
  return std::abs(got - want) / std::max(std::abs(want), 1e3);
}

void ExpectSameUpToRounding(double got, double want, const std::string& what, double& worst) {
  if (std::isnan(want)) {
    EXPECT_TRUE(std::isnan(got)) << what;
    return;
  }
  const double d = ScaledDifference(got, want);
  worst = std::max(worst, d);
  EXPECT_LE(d, kTolerance) << what << ": " << got << " vs " << want;
}

struct ReferenceCase {
  const char* tir;
  int use_mode;
};

std::string ReferenceCaseName(const ::testing::TestParamInfo<ReferenceCase>& info) {
  return std::string(info.param.tir) + "_mode" + std::to_string(info.param.use_mode);
}

class MagicFormulaReferenceTest : public ::testing::TestWithParam<ReferenceCase> {
 protected:
  void TearDown() override { internal::SetMathIsa(initial_isa_); }
  const internal::MathIsa initial_isa_ = internal::ActiveMathIsa();
};

TEST_P(MagicFormulaReferenceTest, DoublesAgreeWithTheReferenceUpToRounding) {
  const auto p = LoadReferenceTir(GetParam().tir);
  const auto options = MagicFormulaOptions::FromUseMode(GetParam().use_mode);
  for (const auto isa : {internal::MathIsa::kGeneric, internal::MathIsa::kAvx2}) {
    if (!internal::SetMathIsa(isa)) continue;
    double worst = 0.0;
    int row = 0;
    for (const auto& op : RandomReferencePoints(p, 20000, 7 + GetParam().use_mode)) {
      const auto got = ReferenceOutputs(CalcMagicFormula(p, op, options));
      const auto want = ReferenceOutputs(CalcMagicFormulaReference(p, op, options));
      for (size_t k = 0; k < 5; ++k) {
        ExpectSameUpToRounding(got[k], want[k],
                               std::string(internal::MathIsaName(isa)) + " point " +
                                   std::to_string(row) + " output " + std::to_string(k),
                               worst);
      }
      ++row;
    }
    std::printf("[ libmvec  ] %s: worst difference from libm's %.2g of an output's size\n",
                internal::MathIsaName(isa), worst);
  }
}

TEST_P(MagicFormulaReferenceTest, JetsAgreeWithTheReferenceUpToRounding) {
  const auto p = LoadReferenceTir(GetParam().tir);
  const auto p_jet = p.Cast<Jet2>();
  const auto options = MagicFormulaOptions::FromUseMode(GetParam().use_mode);
  double worst = 0.0;
  int row = 0;
  for (const auto& op : RandomReferencePoints(p, 2000, 99 + GetParam().use_mode)) {
    TyreOperatingPoint<Jet2> op_jet;
    op_jet.fz = Jet2(op.fz);
    op_jet.slip_ratio = Jet2(op.slip_ratio, 0);
    op_jet.slip_angle = Jet2(op.slip_angle, 1);
    op_jet.camber = Jet2(op.camber);
    op_jet.speed = Jet2(op.speed);
    op_jet.pressure = Jet2(op.pressure);
    const auto got = CalcMagicFormula(p_jet, op_jet, options);
    const auto want = CalcMagicFormulaReference(p_jet, op_jet, options);
    const std::array<const Jet2*, 5> g = {&got.fx, &got.fy, &got.mx, &got.my, &got.mz};
    const std::array<const Jet2*, 5> w = {&want.fx, &want.fy, &want.mx, &want.my, &want.mz};
    for (size_t k = 0; k < 5; ++k) {
      const std::string what = "point " + std::to_string(row) + " output " + std::to_string(k);
      ExpectSameUpToRounding(g[k]->a, w[k]->a, what, worst);
      ExpectSameUpToRounding(g[k]->v[0], w[k]->v[0], what + " d/dkappa", worst);
      ExpectSameUpToRounding(g[k]->v[1], w[k]->v[1], what + " d/dalpha", worst);
    }
    ++row;
  }
  std::printf("[ libmvec  ] Jet2: worst difference from libm's %.2g of an output's size\n", worst);
}

// The instruction sets agree to rounding (not bit for bit: libmvec's SSE and AVX2 functions
// differ in the last bits).
TEST_P(MagicFormulaReferenceTest, InstructionSetsAgreeUpToRounding) {
  if (!internal::MathIsaSupported(internal::MathIsa::kAvx2)) GTEST_SKIP() << "no AVX2 here";
  const auto p = LoadReferenceTir(GetParam().tir);
  const auto options = MagicFormulaOptions::FromUseMode(GetParam().use_mode);
  double worst = 0.0;
  for (const auto& op : RandomReferencePoints(p, 5000, 3 + GetParam().use_mode)) {
    internal::SetMathIsa(internal::MathIsa::kGeneric);
    const auto generic = ReferenceOutputs(CalcMagicFormula(p, op, options));
    internal::SetMathIsa(internal::MathIsa::kAvx2);
    const auto avx2 = ReferenceOutputs(CalcMagicFormula(p, op, options));
    for (size_t k = 0; k < 5; ++k) {
      ExpectSameUpToRounding(avx2[k], generic[k], "output " + std::to_string(k), worst);
    }
  }
  std::printf("[ libmvec  ] avx2 against generic: worst difference %.2g of an output's size\n",
              worst);
}

INSTANTIATE_TEST_SUITE_P(Mfeval431, MagicFormulaReferenceTest,
                         ::testing::Values(ReferenceCase{"MagicFormula52_Parameters", 111},
                                           ReferenceCase{"MagicFormula52_Parameters", 121},
                                           ReferenceCase{"MagicFormula52_Parameters", 211},
                                           ReferenceCase{"MagicFormula52_Parameters", 221},
                                           ReferenceCase{"MagicFormula61_Parameters", 111},
                                           ReferenceCase{"MagicFormula61_Parameters", 121},
                                           ReferenceCase{"MagicFormula61_Parameters", 211},
                                           ReferenceCase{"MagicFormula61_Parameters", 221},
                                           ReferenceCase{"MagicFormula62_Parameters", 111},
                                           ReferenceCase{"MagicFormula62_Parameters", 221},
                                           ReferenceCase{"PacejkaBook_Defaults", 111},
                                           ReferenceCase{"PacejkaBook_Defaults", 221}),
                         ReferenceCaseName);

}  // namespace
}  // namespace hotlap::tyre
