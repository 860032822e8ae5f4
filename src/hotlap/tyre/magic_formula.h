#pragma once
/// @file
/// Magic Formula steady-state tyre forces and moments (MF 5.2, 6.1, 6.2), as mfeval 4.3.1
/// computes them (Marco Furlan's MATLAB implementation, which reproduces TNO MF-Tyre), from the
/// coefficients of a `.tir` file.
///
/// How to use:
///
///   const auto params = tyre::LoadMagicFormula("front.tir");
///   tyre::TyreOperatingPoint<double> op{.fz = 4000, .slip_ratio = 0.05, .slip_angle = 0.03,
///                                       .speed = 20};
///   const tyre::TyreForces<double> f = tyre::CalcMagicFormula(params, op, {});
///
/// Inputs used: fz, slip_ratio, slip_angle, camber, speed, pressure (0 means the file's INFLPRES,
/// as in mfeval); tread_temp is not used. Turn slip is taken as zero (mfeval's phit = 0 and no
/// turn-slip terms: useMode 1x1).
///
/// Axes and signs: mfeval works in ISO-W (TYDEX W) contact-point axes, x forward, y left, z up,
/// with kappa = -Vsx/|Vx| and alpha = atan(Vsy/|Vx|) where Vs is the contact point's slip velocity;
/// these are exactly the axes and slip definitions of TyreOperatingPoint and TyreForces (see
/// tyre_force.h), so the conversion is the identity: a positive slip angle gives a negative Fy
/// (for the usual PKY1 < 0), a positive slip ratio a positive Fx, and My < 0 when rolling forwards
/// (rolling resistance opposes the wheel's spin; mfeval's My, eq. (A48) of Besselink et al., has
/// this sign in ISO-W, unlike the book's (4.E70)). Fz is the load pressing the tyre down, > 0.
///
/// Options are mfeval's useMode digits: limits (1xx: clamp Fz, kappa, alpha, gamma and pressure to
/// the file's FZMAX, KPUMIN/KPUMAX, ALPMIN/ALPMAX, CAMMIN/CAMMAX, PRESMIN/PRESMAX, scale kappa,
/// alpha and the shifts down below VXLOW, and cap the curvature factors Ey, Eyk, Et at 1; 2xx:
/// none of this) and the slip form (x1x: alpha and gamma as given, as TNO MF-Tyre; x2x: the book's
/// alpha* = tan(alpha) sgn(Vx) and gamma* = sin(gamma)).
///
/// Speed and accuracy: the arctangents, sines and cosines (some 25 and 14 per evaluation) go
/// through SIMD lanes in a few batches, and every transcendental function of the double model is
/// glibc's vector maths library libmvec's (four AVX2 lanes where the CPU has AVX2, else two SSE2
/// lanes; magic_formula_simd.h). libmvec is accurate to a few ulp, so results can differ from a
/// plain libm evaluation in the last bits (4e-14 of an output's size at most,
/// tests/tyre/magic_formula_reference_test.cc) and between instruction sets. One point is bound
/// by its chain of seven dependent function batches; CalcMagicFormulaBatch evaluates several
/// points at once, one per SIMD lane, with the same bits as CalcMagicFormula on the same machine.
///
/// Derivatives: every function is templated on the scalar (double, ceres::Jet, SecondOrder).
/// Branches (limits, signs, low speed) are chosen on values only, so derivatives are exact
/// everywhere except on the switching surfaces, and zero with respect to an input while it is
/// clamped.
///
/// Pitfalls: Mz follows mfeval's corrections for TNO (Dt with QDZ3 gamma not |gamma|, Bt with
/// QBZ4, s with FNOMIN, t times LFZO, alpha_eq from tangents, Mz' from Fy0 at zero camber), so it
/// can differ from the book's (4.E71). Below FZMIN, Mx and My use mfeval's load reductions
/// (Fz^3/FZMIN^2 and Fz^2/FZMIN); the trail and residual torque use FZMIN itself.

#include <filesystem>
#include <span>

#include "hotlap/common/scalar.h"
#include "hotlap/tyre/magic_formula_params.h"
#include "hotlap/tyre/tir_file.h"
#include "hotlap/tyre/tyre_force.h"

namespace hotlap::tyre {

/// mfeval's useMode hundreds digit.
enum class MagicFormulaLimits {
  kClamp,  ///< 1xx: clamp inputs to the file's ranges, low-speed model, E factors <= 1
  kNone,   ///< 2xx: evaluate the equations as they are
};

/// mfeval's useMode tens digit: how alpha and gamma enter the equations.
enum class MagicFormulaSlipForm {
  kAngle,    ///< x1x: alpha and gamma as given (TNO MF-Tyre)
  kTangent,  ///< x2x: alpha* = tan(alpha) sgn(Vx), gamma* = sin(gamma) (Pacejka 2012, 4.E3-4)
};

/// How to evaluate the Magic Formula. The default is mfeval's useMode 111.
struct MagicFormulaOptions {
  MagicFormulaLimits limits = MagicFormulaLimits::kClamp;
  MagicFormulaSlipForm slip_form = MagicFormulaSlipForm::kAngle;

  /// The options for mfeval's useMode 111, 121, 211 or 221; InputError for any other (turn slip,
  /// units digit 2, is not modelled).
  static MagicFormulaOptions FromUseMode(int use_mode);
};

/// Steady-state forces and moments at the contact point, ISO-W = our wheel axes (see the file
/// comment). Combined slip; load, camber, pressure and speed effects; no turn slip.
template <Scalar T>
TyreForces<T> CalcMagicFormula(const MagicFormulaParams<T>& params, const TyreOperatingPoint<T>& op,
                               const MagicFormulaOptions& options);

/// CalcMagicFormula(params, points[i], options) into out[i] for every i, for doubles: several
/// points at once (one per SIMD lane, their chains of functions overlapping), with the same
/// results bit for bit, about twice as fast per point (docs/benchmarks.md). std::invalid_argument
/// unless `out` has the size of `points`.
void CalcMagicFormulaBatch(const MagicFormulaParams<double>& params,
                           std::span<const TyreOperatingPoint<double>> points,
                           const MagicFormulaOptions& options, std::span<TyreForces<double>> out);

/// The coefficients of a `.tir` file, SI units (ReadTirFile(path).params). InputError as
/// ReadTirFile.
MagicFormulaParams<double> LoadMagicFormula(const std::filesystem::path& path);

}  // namespace hotlap::tyre
