#pragma once
/// @file
/// Fitting the temperature-dependent UniTire model (tyre/unitire.h) to tyre-rig measurements,
/// following the UniTire paper's protocol (001 §5): the base parameters and the temperature
/// factors are identified together on the samples at the fit temperatures (the paper's 0, 10, 32
/// and 43 degC), and the fitted model then predicts the held-out temperatures (18 and 53 degC).
///
/// How to use: collect RigSample rows (or make them with SynthesizeRigData), set
/// UniTireFitOptions::fit_temps, call FitUniTire, and read UniTireFitResult::metrics: one row per
/// measured temperature, fitted or held out. Write the result with WriteUniTireParams
/// (tyre/tyre_force_params_io.h).
///
/// What is fitted (least squares with Ceres, derivatives by automatic differentiation through the
/// templated model, every free parameter bounded):
/// - always: s11, s12, s13 (s13 >= 0, which removes sech's sign symmetry), mu_y0, E_y, d_0, D_e,
///   D1, D2;
/// - with more than one load: c_mu (friction fall with load) and q (trail load exponent);
/// - with more than one fit temperature: the decays b of f_K and f_D (and of f_mu if asked);
/// - with camber other than zero in the data: s14;
/// - with fx measured at non-zero slip ratio: sx1, sx2, sx3 (sx3 >= 0), mu_x0, E_x.
/// Residuals are Fy / (peak |Fy|), Mz / (peak |Mz|) * mz_weight and Fx / (peak |Fx|) over the fit
/// samples, unweighted otherwise (Levenberg-Marquardt, dense QR). The curvatures E can stop in a
/// local minimum far from their start, so the fit is run from E = 0, -1, 1 and -2 (the rest
/// from the initial guess) and the lowest cost is kept.
/// Held at the initial guess: Fz_n and T_ref (conventions, see the options), the scales `a` of the
/// temperature factors (redundant with s11, d_0 and D_e at a fixed T_ref; held at 1), and the
/// sliding-speed friction law (one rig speed cannot identify it; held at r = 1, no effect).
///
/// Pitfall: with slip angles only up to 1-2 deg (as on the paper's rig) the forces stay nearly
/// linear, and friction and curvature are not identifiable; the fit still reproduces the data,
/// but those parameters stay near their initial guesses.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "hotlap/tyre/unitire.h"

namespace hotlap::ident {

/// One steady-state measurement of a tyre rig. SI units, signs of tyre/tyre_force.h.
struct RigSample {
  double slip_angle = 0.0;   ///< alpha, rad
  double slip_ratio = 0.0;   ///< kappa, 1
  double fz = 0.0;           ///< vertical load, N (> 0)
  double camber = 0.0;       ///< inclination gamma, rad
  double speed = 0.0;        ///< wheel-centre speed V_x, m/s
  double tread_temp = 0.0;   ///< K
  double fy = 0.0;           ///< measured lateral force, N
  double mz = 0.0;           ///< measured aligning moment, N m
  std::optional<double> fx;  ///< measured longitudinal force, N, if recorded
};

/// Whether the friction temperature factor's decay is fitted.
enum class FrictionTemperatureFit {
  kHeld,    ///< held at the initial guess (b = 0): the paper's model
  kFitted,  ///< fitted with the other decays
};

/// Options of FitUniTire.
struct UniTireFitOptions {
  /// Temperatures to fit on, K. Samples within `temp_tolerance` of one of them are fitted; the
  /// others are only predicted. Required (at least one).
  std::vector<double> fit_temps;
  double temp_tolerance = 1.5;  ///< K; also groups temperatures in the metrics
  /// Fz_n, N. Default: the median load of the fitted samples.
  std::optional<double> nominal_load;
  /// T_ref of the three temperature factors, K. Default: the mean of fit_temps.
  std::optional<double> reference_temp;
  /// The starting point. Default: CalcUniTireInitialGuess(samples, options).
  std::optional<tyre::UniTireParams<double>> initial_guess;
  FrictionTemperatureFit friction_temperature = FrictionTemperatureFit::kHeld;
  /// Weight of the Mz residuals against the Fy residuals (each is scaled by its channel's peak).
  double mz_weight = 1.0;
  int max_iterations = 200;
};

/// How well a parameter set reproduces the samples at one temperature.
struct UniTireTempMetrics {
  double temp = 0.0;               ///< K, the mean of the group
  bool fitted = false;             ///< true: a fit temperature; false: held out (a prediction)
  int samples = 0;                 ///< samples in the group
  double fy_rms_N = 0.0;           ///< RMS of Fy model - measured, N
  double fy_peak_N = 0.0;          ///< largest measured |Fy| at this temperature, N
  double fy_rms_rel_peak = 0.0;    ///< fy_rms_N / fy_peak_N, 1
  double mz_rms_Nm = 0.0;          ///< RMS of Mz model - measured, N m
  std::optional<double> fx_rms_N;  ///< RMS of Fx model - measured over samples with fx, N
};

/// The outcome of FitUniTire.
struct UniTireFitResult {
  tyre::UniTireParams<double> params;         ///< the fitted parameters
  tyre::UniTireParams<double> initial_guess;  ///< where the fit started
  std::vector<std::string> fitted_fields;     ///< names (kUniTireFieldNames) of the free fields
  std::vector<UniTireTempMetrics> metrics;    ///< one row per temperature, ascending
  bool converged = false;                     ///< Ceres reported convergence for the kept start
  int iterations = 0;                         ///< Ceres iterations, summed over the starts
  double final_cost = 0.0;  ///< Ceres cost of the kept start, 1/2 sum of squared scaled residuals
  std::string report;       ///< Ceres' brief report of the kept start
};

/// A starting point computed from the data alone (it does not need to be near the answer): per
/// (temperature, load) curve of pure side slip, the initial slopes of Fy and Mz against
/// tan(alpha) (extrapolated to zero slip from the two smallest slip angles) and the peak |Fy|;
/// then log-linear regressions across temperatures for the decays b of f_K and f_D, across loads
/// for s11..s13 (sech fitted through acosh), c_mu and the trail load law; E = 0, D_e = 0.2 d_0,
/// D1 = 1, D2 = 0. Longitudinal parameters likewise from pure-slip Fx curves if present, else
/// copied from the lateral ones. Throws InputError if no sample is at a fit temperature or the
/// samples hold no pure side-slip curve.
tyre::UniTireParams<double> CalcUniTireInitialGuess(std::span<const RigSample> samples,
                                                    const UniTireFitOptions& options);

/// Fits UniTire parameters to the samples at options.fit_temps and evaluates every temperature
/// (see the file comment). Throws InputError on unusable input (no fit samples, non-positive
/// loads, non-finite values).
UniTireFitResult FitUniTire(std::span<const RigSample> samples, const UniTireFitOptions& options);

/// InputError, naming `source` (the data file), unless every fit temperature and every predict
/// temperature (K) has a sample within options.temp_tolerance, and no predict temperature is also
/// a fit temperature: the checks to run before FitUniTire when the temperatures come from a user.
void RequireFitAndPredictTemps(std::span<const RigSample> samples, const UniTireFitOptions& options,
                               const std::vector<double>& predict_temps, const std::string& source);

/// Metrics of `params` on `samples`, one row per temperature group (groups are runs of sorted
/// temperatures no more than `temp_tolerance` apart); `fitted` marks groups within
/// `temp_tolerance` of one of `fit_temps`.
std::vector<UniTireTempMetrics> EvaluateUniTire(const tyre::UniTireParams<double>& params,
                                                std::span<const RigSample> samples,
                                                std::span<const double> fit_temps,
                                                double temp_tolerance);

/// Speed of the synthesized rig runs, m/s: the UniTire paper's 5 km/h (001 Table 1).
inline constexpr double kRigSpeed = 5.0 / 3.6;

/// Rig samples of the model `truth` in pure side slip at every combination of `temps` (K), `loads`
/// (N) and `slip_angles` (rad), at zero camber and slip ratio and speed kRigSpeed, with Gaussian
/// noise of standard deviation `noise_fraction` times the curve's peak |Fy| on Fy and its peak
/// |Mz| on Mz (a curve: one temperature and load), from std::mt19937(seed). fx is not set.
std::vector<RigSample> SynthesizeRigData(const tyre::UniTireParams<double>& truth,
                                         std::span<const double> temps,
                                         std::span<const double> loads,
                                         std::span<const double> slip_angles, double noise_fraction,
                                         std::uint32_t seed);

}  // namespace hotlap::ident
