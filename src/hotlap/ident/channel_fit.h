#pragma once
/// @file
/// Least-squares fitting of a model's predicted channels to measured channels, with robust losses,
/// noise levels estimated from the data, multi-start, and the uncertainty of the answer (Ceres
/// covariance): the engine under the tyre, wear, brake and contact-length fits (docs/fitting.md).
///
/// How to use: describe the free parameters (FitParameter: bounds and a typical magnitude), the
/// measured channels (MeasuredChannel: values at the model's samples, NaN where there is no
/// measurement, and trapezoid weights so the sum of squares approximates the integral of the
/// squared error), give a ChannelModel that predicts those channels and their exact derivatives
/// (jet_predictor.h does that for a scalar-templated model), some starting points, and call
/// FitChannels. The result holds the values, standard errors, 95% intervals, the correlation
/// matrix, whether each parameter is well determined, per-channel residual statistics and
/// warnings in plain words.
///
/// The protocol (each step is in docs/fitting.md):
/// 1. every start is scored by its cost; the best are solved in turn (Levenberg-Marquardt,
///    bounds, Huber loss at loss_scale prior noise levels) until, after at least
///    `min_refine_starts`, the best leaves residuals that look like white noise, or
///    `refine_starts` have been solved; the lowest cost is kept;
/// 2. each channel's noise level is estimated from its residuals (1.4826 x median absolute
///    deviation), the residuals are divided by it, and the fit is solved again with the chosen
///    robust loss (its scale is then in noise standard deviations);
/// 3. the noise levels are estimated again, inflated by the lag-one autocorrelation of the
///    residuals ((1 + rho) / (1 - rho), which is 1 for white noise), and the covariance of the
///    parameters is (J'J)^-1 of the whitened, loss-corrected residuals (ceres::Covariance,
///    DENSE_SVD). If J is rank deficient, the directions it cannot see are found by SVD, every
///    parameter with a share of them is reported as undetermined (std error infinite, interval
///    the bounds), and the others get the pseudo-inverse covariance;
/// 4. the model is not linear in its parameters, so each interval is checked against the cost
///    itself: along the direction in which the linearised fit moves all parameters when one is
///    moved (the covariance's column: the profile direction of a linear model), the cost is
///    followed outwards until it has risen by 1.92 (the 95% likelihood-ratio level); where that
///    is beyond the Wald endpoint (value -/+ 1.96 std errors) the interval is widened to it. Near
///    the minimum of a valley that curves or flattens the quadratic underestimates its extent.
///    Re-optimising along the way (a true profile) could only widen it further. The joint
///    intervals (FitOptions::joint_family_size) are checked the same way at their own level.
///
/// Pitfall: the optimiser works on value / scale; give every parameter a scale of its typical
/// magnitude (a zero scale is an error), or the covariance's rank test compares apples with pears.

#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "hotlap/common/fit_hint.h"

namespace hotlap::ident {

/// Whether a parameter is part of the model or only needed by the fit (an initial temperature).
enum class ParameterRole { kModel, kNuisance };

/// One free parameter. Values are in the model's units (SI, or as in the parameter file).
struct FitParameter {
  std::string key{};    ///< file key and JSON name, e.g. "p2_J_per_kgN"
  std::string label{};  ///< short name for tables, e.g. "p2"
  std::string unit{};   ///< for reports, e.g. "J/(kg N)"; "" if dimensionless
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
  double scale = 1.0;  ///< typical magnitude (> 0); the solver varies value / scale
  ParameterRole role = ParameterRole::kModel;
  /// Added to values for display (e.g. -273.15 to show a temperature in degC).
  double display_offset = 0.0;
};

/// A model parameter as a field table describes it (common/fit_hint.h): key `key`, the hint's
/// label, unit and bounds, and scale max(|value|, hint.scale_floor).
FitParameter FitParameterOf(std::string key, const FitHint& hint, double value);

/// One measured channel at the model's samples.
struct MeasuredChannel {
  std::string name{};             ///< e.g. "tread_temp"
  std::string unit{};             ///< display unit, e.g. "C"
  double display_offset = 0.0;    ///< added to values for display
  double display_scale = 1.0;     ///< multiplies values for display (e.g. 1000: m -> mm)
  std::vector<double> values{};   ///< measured, model units; NaN where none
  std::vector<double> weights{};  ///< >= 0 per sample (trapezoid, mean 1); empty: all 1
  double prior_sigma = 1.0;       ///< rough noise level for the first stage, model units
  double min_sigma = 0.0;         ///< floor of the estimated noise level
  /// Use prior_sigma as the noise level instead of estimating it (a single measurement, or a
  /// measurement whose uncertainty is known).
  bool fixed_sigma = false;
};

/// The model's predictions of every channel at every sample and, on request, their derivatives
/// with respect to the free parameters.
struct Predictions {
  std::vector<std::vector<double>> value;     ///< [channel][sample]
  std::vector<std::vector<double>> jacobian;  ///< [channel][sample * parameters + parameter]
};

/// A model of the channels as a function of the free parameters.
class ChannelModel {
 public:
  virtual ~ChannelModel() = default;
  virtual int num_parameters() const = 0;
  virtual int num_channels() const = 0;
  virtual size_t num_samples() const = 0;
  /// Predictions at `x` (num_parameters values); false if they are not finite (the solver then
  /// treats the point as infeasible and shortens its step).
  virtual bool Predict(std::span<const double> x, bool with_jacobian, Predictions* out) const = 0;
};

enum class LossKind { kNone, kHuber, kCauchy };

/// Reads "none", "huber" or "cauchy"; InputError otherwise.
LossKind ParseLossKind(const std::string& text);
const char* LossKindName(LossKind kind);

struct FitOptions {
  LossKind loss = LossKind::kHuber;
  double loss_scale = 3.0;  ///< where the robust loss starts, in noise standard deviations
  /// A model parameter is well determined when the half-width of its 95% interval is at most
  /// this fraction of its value (and it is not at a bound nor in the null space).
  double max_relative_ci = 0.05;
  /// The same for nuisance parameters, as an absolute half-width in model units.
  double max_nuisance_ci = 1.0;
  int max_iterations = 100;
  int refine_starts = 3;      ///< at most this many of the best-scoring starts are solved
  int min_refine_starts = 2;  ///< and at least this many (when there are as many)
  /// Stop refining starts once every channel's residuals have a lag-one autocorrelation below
  /// this (they look like white noise: no other minimum can fit better).
  double white_residuals = 0.5;
  /// Inflate the noise levels by the residuals' lag-one autocorrelation (step 3 above).
  bool inflate_for_autocorrelation = true;
  /// False: no solving; the noise levels, statistics and covariance are those at the first
  /// start (to report a solution found elsewhere in other coordinates).
  bool solve = true;
  /// How many model parameters the caller reports together (e.g. every parameter of every
  /// corner of one `hotlap fit` command). Their joint intervals hold all of them at once with
  /// 95% probability: each is a 1 - 0.05 / joint_family_size interval (Bonferroni). 1: the
  /// joint interval is the 95% interval.
  int joint_family_size = 1;
};

/// The two-sided normal quantile of a family of `family_size` intervals that hold together with
/// probability 0.95 (Bonferroni): Phi^-1(1 - 0.025 / family_size); 1.96 for one. family_size >= 1.
double JointNormalQuantile(int family_size);

/// Phi^-1(p), the standard normal quantile, for p in (0, 1) (to 1e-12).
double NormalQuantile(double p);

/// What the fit says about one parameter.
struct ParameterEstimate {
  double value = 0.0;
  double std_error = 0.0;  ///< infinite when undetermined
  /// 95% interval: value -/+ 1.96 std errors, widened to the likelihood interval along the
  /// linearised profile direction where that is wider (see FitChannels), clipped to the bounds.
  double ci_low = 0.0;
  double ci_high = 0.0;
  /// Where the cost rises by 1.92 (chi-square 3.84 / 2) along the linearised profile direction,
  /// NaN where not computed; the bounds where it never does.
  double likelihood_low = std::numeric_limits<double>::quiet_NaN();
  double likelihood_high = std::numeric_limits<double>::quiet_NaN();
  /// Joint 95% interval (FitOptions::joint_family_size): value -/+ z_joint std errors, widened
  /// the same way to where the cost rises by z_joint^2 / 2 (joint_likelihood_*), clipped.
  double joint_low = 0.0;
  double joint_high = 0.0;
  double joint_likelihood_low = std::numeric_limits<double>::quiet_NaN();
  double joint_likelihood_high = std::numeric_limits<double>::quiet_NaN();
  bool well_determined = false;
  bool at_bound = false;      ///< within 1e-6 of its range from a bound
  bool undetermined = false;  ///< in the null space of the Jacobian
  double start = 0.0;         ///< the starting value of the solution that was kept
};

/// Residual statistics of one channel at the solution (model units).
struct ChannelStats {
  std::string name;
  int samples = 0;               ///< measurements used
  double rms = 0.0;              ///< root mean square of (model - measured) over them
  double sigma = 0.0;            ///< estimated noise level (robust)
  double autocorrelation = 0.0;  ///< lag-one autocorrelation of the inlier residuals
  int outliers = 0;              ///< residuals beyond 5 sigma (down-weighted by the loss)
  /// Sensor lag the residuals suggest, s (positive: the measurement trails the model): one
  /// Gauss-Newton step of the fit with a lag added (measured ~ model - tau d(model)/dt) over the
  /// inliers; NaN for static models.
  double apparent_lag = std::numeric_limits<double>::quiet_NaN();
  double apparent_lag_std_error = std::numeric_limits<double>::quiet_NaN();
};

struct FitResult {
  std::vector<FitParameter> parameters;
  std::vector<ParameterEstimate> estimates;
  /// Model units. Where the Jacobian is rank deficient, the pseudo-inverse: finite, but
  /// meaningless for the undetermined parameters (their std errors are infinite).
  Eigen::MatrixXd covariance;
  Eigen::MatrixXd correlation;      ///< NaN where undefined (an undetermined parameter)
  Eigen::MatrixXd null_directions;  ///< columns: parameter changes (model units) the data miss
  std::vector<ChannelStats> channels;
  Predictions predicted;                       ///< values at the solution (no Jacobian)
  std::vector<std::string> warnings;           ///< about the data and the solver
  std::vector<std::string> estimate_warnings;  ///< about parameters (SummarizeEstimates)
  bool converged = false;
  int iterations = 0;
  double final_cost = 0.0;
  int starts_scored = 0;
  int starts_solved = 0;

  /// warnings, then estimate_warnings.
  std::vector<std::string> AllWarnings() const {
    std::vector<std::string> all = warnings;
    all.insert(all.end(), estimate_warnings.begin(), estimate_warnings.end());
    return all;
  }
};

/// Runs the protocol of the file comment. `time` (seconds, one per sample) enables the sensor-lag
/// diagnostic; pass an empty span for a static model. `starts` holds starting points (each with
/// one value per parameter; clamped into the bounds). Throws std::invalid_argument for
/// inconsistent sizes or a non-positive scale, InputError if no channel has a measurement or no
/// start can be evaluated.
FitResult FitChannels(const ChannelModel& model, std::span<const FitParameter> parameters,
                      std::span<const MeasuredChannel> channels,
                      std::span<const std::vector<double>> starts, std::span<const double> time,
                      const FitOptions& options);

/// Fills `result.estimates` (std errors, intervals, well-determined flags) and the correlation
/// from `result.covariance`, the values and the `undetermined` flags (a non-finite variance also
/// counts as undetermined); rewrites `estimate_warnings`. Used by FitChannels and again by a
/// caller that updates the covariance (the wear fit adds the thermal parameters' uncertainty; the
/// brake fit reports in other coordinates).
void SummarizeEstimates(FitResult& result, const FitOptions& options);

/// One warning per null direction (columns of `directions`, model units), naming the
/// parameters that make it up.
std::vector<std::string> NullSpaceWarnings(std::span<const FitParameter> parameters,
                                           const Eigen::MatrixXd& directions);

}  // namespace hotlap::ident
