#pragma once
/// @file
/// Fitting Magic Formula pure-slip coefficients (lateral Fy0 and longitudinal Fx0) to tyre-rig
/// measurements, and writing them as a `.tir` file.
///
/// How to use: read RigSample rows (ident/rig_data.h) or make them with
/// SynthesizeMagicFormulaRigData, call FitMagicFormula, write `result.params` with
/// tyre::WriteTirFile. The fit evaluates the model exactly as a loaded `.tir` is evaluated
/// (mfeval's useMode 111), so what is fitted is what hotlap later computes.
///
/// What is fitted (Ceres, Levenberg-Marquardt, derivatives by automatic differentiation through
/// the templated Magic Formula, every coefficient bounded), chosen by what the data can identify:
/// - pure side slip (slip ratio 0) at zero camber: PCY1, PDY1, PEY1, PKY1, PHY1, PVY1; with two
///   or more loads also PDY2, PEY2, PKY2, PHY2, PVY2; with three or more loads also PKY4; with
///   slip angles of both signs also the curvature asymmetry PEY3;
/// - side slip at non-zero camber: PDY3, PKY6, PVY3 (and PKY7, PVY4 with several loads);
/// - pure longitudinal slip (slip angle 0, fx measured) at zero camber: PCX1, PDX1, PEX1, PKX1,
///   PHX1, PVX1; with two or more loads also PDX2, PEX2, PKX2, PHX2, PVX2; with three or more
///   also PEX3, PKX3; with slip of both signs PEX4 (braking and driving curvature differ); at
///   non-zero camber PDX3.
/// Residuals are force errors divided by the channel's peak |F|. The shape and curvature factors
/// can stop in a local minimum, so each channel is solved from several starting curvatures and
/// the lowest cost is kept; the start itself comes from the data (slopes at zero slip and peak
/// forces per load), never from the answer. Combined-slip samples are not used (reported).
/// Everything else (dimensions, ranges, aligning moment, combined-slip and rolling coefficients)
/// is taken from `options.base` unchanged.
///
/// Physically plausible by construction where bounds allow, checked after: the sign of the
/// cornering stiffness is that of the least-squares slope of Fy on alpha over every zero-camber
/// load group together, each group's mean removed (its offset), so one group's offset or noise
/// cannot flip it; PKY4 is bounded to [1, 2.9] and PKY2 from below so that PKY4 atan(Fz / (PKY2
/// Fz0)) stays at or below pi - 0.05 up to Fz = 2 FNOMIN (at zero camber and nominal pressure):
/// the stiffness cannot change sign over 0-2 x FNOMIN. Every fit ends with
/// CheckMagicFormulaPlausibility (result.plausibility).
///
/// Pitfall: the Magic Formula has no temperature. Rig data at several tread temperatures is fitted
/// as one tyre, with a warning; fit the temperature-dependent UniTire model for that.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "hotlap/ident/unitire_fit.h"
#include "hotlap/tyre/magic_formula_params.h"

namespace hotlap::ident {

/// Options of FitMagicFormula.
struct MagicFormulaFitOptions {
  /// Coefficients to start from and to keep where the data says nothing. Default:
  /// MagicFormulaDefaults() with FNOMIN the median load, LONGVL the median speed and the load
  /// range FZMIN..FZMAX widened to cover the data.
  std::optional<tyre::MagicFormulaParams<double>> base;
  int max_iterations = 200;
};

/// How well the fitted model reproduces one channel at one load.
struct MagicFormulaFitMetrics {
  std::string channel;        ///< "fy" (pure side slip) or "fx" (pure longitudinal slip)
  double fz_N = 0.0;          ///< mean load of the group
  int samples = 0;            ///< samples in the group
  double rms_N = 0.0;         ///< RMS of model - measured, N
  double peak_N = 0.0;        ///< largest measured |F|, N
  double rms_rel_peak = 0.0;  ///< rms_N / peak_N
};

/// Whether a Magic Formula tyre is physically plausible over loads 0.1-2 x FNOMIN (20 loads) at
/// zero camber: for each load, the cornering stiffness dFy/dalpha at 0 and Fy at a small positive
/// slip angle (1 degree, or the range's end if smaller) have `lateral_sign` (ISO: negative Fy for
/// positive alpha), `PKY4 atan(Fz / (PKY2 Fz0))` lies inside (0, pi) (outside it the stiffness
/// changes sign), and the peak |Fy|/Fz over the slip angles +-slip_angle_max is finite and
/// positive; with `slip_ratio_max` > 0 the same for Fx (positive for positive slip ratio).
struct MagicFormulaPlausibility {
  bool passed = true;
  double fz_min_N = 0.0;               ///< 0.1 x FNOMIN
  double fz_max_N = 0.0;               ///< 2 x FNOMIN
  double slip_angle_max_rad = 0.0;     ///< slip angles checked: +-this
  double slip_ratio_max = 0.0;         ///< slip ratios checked: +-this (0: Fx not checked)
  double lateral_sign = -1.0;          ///< expected sign of Fy for positive alpha
  double peak_mu_y_min = 0.0;          ///< smallest peak |Fy|/Fz over the loads
  double peak_mu_y_max = 0.0;          ///< largest peak |Fy|/Fz over the loads
  std::vector<std::string> failures;   ///< why it failed, one line per kind of failure
  std::vector<std::string> at_bounds;  ///< fitted coefficients that stopped at a bound (a fit's)
};

/// Checks `params` as MagicFormulaPlausibility describes; `lateral_sign` -1 is ISO.
MagicFormulaPlausibility CheckMagicFormulaPlausibility(
    const tyre::MagicFormulaParams<double>& params, double slip_angle_max,
    double slip_ratio_max = 0.0, double lateral_sign = -1.0);

/// The outcome of FitMagicFormula.
struct MagicFormulaFitResult {
  tyre::MagicFormulaParams<double> params;         ///< fitted coefficients
  tyre::MagicFormulaParams<double> initial_guess;  ///< where the fit started
  std::vector<std::string> fitted_coefficients;    ///< `.tir` names of the free coefficients
  std::vector<MagicFormulaFitMetrics> metrics;     ///< per channel and load group
  std::vector<std::string> warnings;  ///< e.g. several temperatures, unused combined samples
  bool converged = false;             ///< Ceres reported convergence on every channel
  int iterations = 0;                 ///< summed over channels and starts
  int lateral_samples = 0;            ///< pure side-slip samples used
  int longitudinal_samples = 0;       ///< pure longitudinal-slip samples used
  /// The fitted tyre checked over 0.1-2 x FNOMIN and the data's slip range, with the sign the
  /// data have (see lateral_sign) and every coefficient that stopped at a bound.
  MagicFormulaPlausibility plausibility;
};

/// Fits the pure-slip coefficients (see the file comment). InputError if the samples hold no
/// pure-slip curve, or a value is not finite or a load not positive.
MagicFormulaFitResult FitMagicFormula(std::span<const RigSample> samples,
                                      const MagicFormulaFitOptions& options);

/// Rig samples of `truth` (evaluated as useMode 111): pure side slip at every slip angle and pure
/// longitudinal slip at every slip ratio, for every load and camber, at `speed` m/s and
/// `tread_temp` K; Gaussian noise of `noise_fraction` times each curve's peak on Fy, Mz and Fx,
/// from std::mt19937(seed). Longitudinal samples carry fx; lateral ones carry fx = Fx at zero
/// slip ratio (rolling resistance aside, near zero).
std::vector<RigSample> SynthesizeMagicFormulaRigData(const tyre::MagicFormulaParams<double>& truth,
                                                     std::span<const double> loads,
                                                     std::span<const double> cambers,
                                                     std::span<const double> slip_angles,
                                                     std::span<const double> slip_ratios,
                                                     double speed, double tread_temp,
                                                     double noise_fraction, std::uint32_t seed);

}  // namespace hotlap::ident
