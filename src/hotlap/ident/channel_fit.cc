#include "hotlap/ident/channel_fit.h"
#include "hotlap/common/special_values.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <utility>

#include <ceres/ceres.h>
#include <ceres/covariance.h>
#include <fmt/format.h>

#include <Eigen/Dense>

#include "hotlap/common/error.h"
#include "hotlap/common/median.h"
#include "hotlap/ident/channel_fit_internal.h"

namespace hotlap::ident {

namespace {

// Singular values of the whitened Jacobian below this fraction of the largest count as zero
// (ceres::Covariance's own default test is 1e-7, the square root of its
// min_reciprocal_condition_number 1e-14; this is a little stricter, so Ceres never refuses).
constexpr double kRankTolerance = 1e-6;
constexpr double kOutlierSigmas = 5.0;
// A parameter with more than this share of its unit vector in the null space (a component above
// 0.01 in units of the scales) is undetermined: moving along the null space moves it freely.
constexpr double kNullShare = 1e-4;

// The model's predictions at the last point asked for, shared by every residual block: Ceres
// evaluates the blocks one after another at the same parameters, and the model (an integration
// over the whole log) runs once per point.
class PredictionCache {
 public:
  PredictionCache(const ChannelModel& model, std::vector<double> scale)
      : model_(model), scale_(std::move(scale)), x_(scale_.size()) {}

  // Predictions at scaled parameters `u`; nullptr where the model fails there.
  const Predictions* At(const double* u, bool with_jacobian) {
    const size_t n = scale_.size();
    if (valid_ && (has_jacobian_ || !with_jacobian) && std::equal(u, u + n, u_.begin())) {
      return ok_ ? &predictions_ : nullptr;
    }
    u_.assign(u, u + n);
    for (size_t i = 0; i < n; ++i) x_[i] = u[i] * scale_[i];
    ok_ = model_.Predict(x_, with_jacobian, &predictions_);
    valid_ = true;
    has_jacobian_ = with_jacobian;
    return ok_ ? &predictions_ : nullptr;
  }

  const std::vector<double>& scale() const { return scale_; }

 private:
  const ChannelModel& model_;
  std::vector<double> scale_;
  std::vector<double> u_, x_;
  Predictions predictions_;
  bool valid_ = false, has_jacobian_ = false, ok_ = false;
};

// One measured sample: r = sqrt(w) (model - measured) / sigma, in scaled parameters.
class SampleResidual final : public ceres::CostFunction {
 public:
  SampleResidual(PredictionCache* cache, int channel, size_t sample, double measured,
                 double sqrt_weight, const double* inv_sigma)
      : cache_(cache),
        channel_(channel),
        sample_(sample),
        measured_(measured),
        sqrt_weight_(sqrt_weight),
        inv_sigma_(inv_sigma) {
    set_num_residuals(1);
    mutable_parameter_block_sizes()->push_back(static_cast<int>(cache->scale().size()));
  }

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const bool with_jacobian = jacobians != nullptr && jacobians[0] != nullptr;
    const Predictions* p = cache_->At(parameters[0], with_jacobian);
    if (p == nullptr) return false;
    const double f = sqrt_weight_ * *inv_sigma_;
    residuals[0] = f * (p->value[channel_][sample_] - measured_);
    if (with_jacobian) {
      const std::vector<double>& scale = cache_->scale();
      const size_t n = scale.size();
      const double* row = &p->jacobian[channel_][sample_ * n];
      for (size_t i = 0; i < n; ++i) jacobians[0][i] = f * row[i] * scale[i];
    }
    return true;
  }

 private:
  PredictionCache* cache_;
  int channel_;
  size_t sample_;
  double measured_;
  double sqrt_weight_;
  const double* inv_sigma_;
};

// Robust noise level: 1.4826 times the median absolute deviation (the standard deviation for
// Gaussian noise, unmoved by a few outliers).
double RobustSigma(const std::vector<double>& r) {
  if (r.size() < 3) return kNaN;
  const double m = Median(r);
  std::vector<double> dev(r.size());
  for (size_t i = 0; i < r.size(); ++i) dev[i] = std::abs(r[i] - m);
  return 1.4826 * Median(std::move(dev));
}

ceres::LossFunction* MakeLoss(LossKind kind, double scale) {
  switch (kind) {
    case LossKind::kHuber:
      return new ceres::HuberLoss(scale);
    case LossKind::kCauchy:
      return new ceres::CauchyLoss(scale);
    case LossKind::kNone:
      break;
  }
  return nullptr;
}

// True when every channel's residuals (model - measured) have a lag-one autocorrelation below
// `threshold`: nothing systematic is left that another local minimum could explain better.
bool ResidualsLookWhite(const Predictions* p, std::span<const MeasuredChannel> channels,
                        double threshold) {
  if (p == nullptr) return false;
  for (size_t c = 0; c < channels.size(); ++c) {
    const std::vector<double>& m = channels[c].values;
    double num = 0.0, den = 0.0;
    int pairs = 0;
    for (size_t k = 0; k + 1 < m.size(); ++k) {
      if (!std::isfinite(m[k]) || !std::isfinite(m[k + 1])) continue;
      const double a = p->value[c][k] - m[k], b = p->value[c][k + 1] - m[k + 1];
      num += a * b;
      den += a * a;
      ++pairs;
    }
    if (pairs < 20) continue;  // too few to tell; judged by the other channels
    if (!(den > 0.0) || num / den >= threshold) return false;
  }
  return true;
}

}  // namespace

FitParameter FitParameterOf(std::string key, const FitHint& hint, double value) {
  return {std::move(key),
          std::string(hint.label),
          std::string(hint.unit),
          hint.lower,
          hint.upper,
          std::max(std::abs(value), hint.scale_floor)};
}

namespace {

// Scaled bounds: a parameter's lower and upper bound over its scale.
struct ScaledBounds {
  std::vector<double> scale, lower, upper;
};

ScaledBounds ScaledBoundsOf(std::span<const FitParameter> parameters) {
  const size_t n_par = parameters.size();
  ScaledBounds b{std::vector<double>(n_par), std::vector<double>(n_par),
                 std::vector<double>(n_par)};
  for (size_t i = 0; i < n_par; ++i) {
    const FitParameter& p = parameters[i];
    if (!(p.scale > 0.0) || !(p.lower < p.upper)) {
      throw std::invalid_argument("FitChannels: bad scale or bounds for " + p.key);
    }
    b.scale[i] = p.scale;
    b.lower[i] = p.lower / p.scale;
    b.upper[i] = p.upper / p.scale;
  }
  return b;
}

ceres::Problem::Options ProblemOptions() {
  ceres::Problem::Options o;
  o.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  return o;
}

// One weighted least-squares fit of the model's channels, in the steps FitChannels' comment
// names: the problem in scaled parameters, the starts scored and the best few solved, noise
// levels from the residuals and a second solve, per-channel statistics, the covariance (with the
// directions the data cannot see) and the likelihood intervals.
class ChannelFitter {
 public:
  ChannelFitter(const ChannelModel& model, std::span<const FitParameter> parameters,
                std::span<const MeasuredChannel> channels, const FitOptions& options)
      : parameters_(parameters),
        channels_(channels),
        options_(options),
        n_par_(static_cast<int>(parameters.size())),
        n_ch_(static_cast<int>(channels.size())),
        n_(model.num_samples()),
        bounds_(ScaledBoundsOf(parameters)),
        cache_(model, bounds_.scale),
        inv_sigma_(n_ch_),
        sigma_(n_ch_),
        problem_(ProblemOptions()),
        u_(n_par_, 0.0),
        used_(n_ch_, 0) {
    BuildProblem();
    solver_.linear_solver_type = ceres::DENSE_QR;
    solver_.max_num_iterations = options.max_iterations;
    solver_.gradient_tolerance = 1e-12;
    solver_.parameter_tolerance = 1e-10;
    solver_.logging_type = ceres::SILENT;
    solver_.num_threads = 1;
    result_.parameters.assign(parameters.begin(), parameters.end());
  }

  FitResult Run(std::span<const std::vector<double>> starts, std::span<const double> time) {
    // 1. Score every start, solve the best few, keep the lowest cost.
    loss_.Reset(MakeLoss(options_.loss == LossKind::kNone ? LossKind::kNone : LossKind::kHuber,
                         options_.loss_scale),
                ceres::TAKE_OWNERSHIP);
    SolveBestStarts(ScoreStarts(starts));
    // 2. Noise levels from the residuals; solve again with the chosen loss in sigma units.
    EstimateSigmas();
    loss_.Reset(MakeLoss(options_.loss, options_.loss_scale), ceres::TAKE_OWNERSHIP);
    Refine();
    // 3. Final noise levels, inflated for correlated residuals; per-channel statistics.
    EstimateSigmas();
    const Predictions* at_best = cache_.At(best_.data(), false);
    if (at_best == nullptr) throw NumericalError("the fitted model's prediction is not finite");
    result_.predicted = *at_best;
    for (int c = 0; c < n_ch_; ++c) result_.channels.push_back(ChannelStatistics(c));
    if (!time.empty() && n_ >= 3) {
      if (const Predictions* p = cache_.At(best_.data(), true)) {
        internal::EstimateApparentLags(*p, cache_.scale(), channels_, time, &result_);
      }
    }
    Covariance();
    // 4. The intervals against the cost itself, along each parameter's profile direction.
    LikelihoodIntervals();
    u_ = best_;
    SummarizeEstimates(result_, options_);
    return std::move(result_);
  }

 private:
  // A residual block for every usable sample of every channel, and the bounds.
  void BuildProblem() {
    problem_.AddParameterBlock(u_.data(), n_par_);
    for (int c = 0; c < n_ch_; ++c) {
      const MeasuredChannel& ch = channels_[c];
      if (ch.values.size() != n_ || (!ch.weights.empty() && ch.weights.size() != n_)) {
        throw std::invalid_argument("FitChannels: channel size differs from the model's: " +
                                    ch.name);
      }
      sigma_[c] = ch.prior_sigma;
      inv_sigma_[c] = 1.0 / ch.prior_sigma;
      for (size_t k = 0; k < n_; ++k) {
        const double w = Weight(c, k);
        if (!std::isfinite(ch.values[k]) || !(w > 0.0)) continue;
        problem_.AddResidualBlock(
            new SampleResidual(&cache_, c, k, ch.values[k], std::sqrt(w), &inv_sigma_[c]), &loss_,
            u_.data());
        ++used_[c];
      }
    }
    if (problem_.NumResidualBlocks() == 0) throw InputError("no measurements to fit");
    for (int i = 0; i < n_par_; ++i) {
      if (std::isfinite(bounds_.lower[i])) {
        problem_.SetParameterLowerBound(u_.data(), i, bounds_.lower[i]);
      }
      if (std::isfinite(bounds_.upper[i])) {
        problem_.SetParameterUpperBound(u_.data(), i, bounds_.upper[i]);
      }
    }
  }

  double Weight(int c, size_t k) const {
    return channels_[c].weights.empty() ? 1.0 : channels_[c].weights[k];
  }

  // The cost at scaled parameters `at`; infinite where the model fails.
  double CostAt(const std::vector<double>& at) {
    u_ = at;
    double cost = kInf;
    if (!problem_.Evaluate(eval_options_, &cost, nullptr, nullptr, nullptr)) return kInf;
    return std::isfinite(cost) ? cost : kInf;
  }

  ceres::Solver::Summary Solve(std::vector<double>& at, double function_tolerance) {
    u_ = at;
    solver_.function_tolerance = function_tolerance;
    ceres::Solver::Summary summary;
    ceres::Solve(solver_, &problem_, &summary);
    at = u_;
    result_.iterations += static_cast<int>(summary.iterations.size());
    return summary;
  }

  // Every start inside the bounds with its cost, lowest first (those with a finite one).
  std::vector<std::pair<double, std::vector<double>>> ScoreStarts(
      std::span<const std::vector<double>> starts) {
    std::vector<std::pair<double, std::vector<double>>> scored;
    for (const std::vector<double>& start : starts) {
      if (static_cast<int>(start.size()) != n_par_) {
        throw std::invalid_argument("FitChannels: start size");
      }
      std::vector<double> s(n_par_);
      for (int i = 0; i < n_par_; ++i) {
        // Inside the bounds and a little away from them, so the first step can go either way.
        const double lower = bounds_.lower[i], upper = bounds_.upper[i];
        const double margin = std::isfinite(upper - lower) ? 1e-6 * (upper - lower) : 0;
        s[i] = std::clamp(start[i] / bounds_.scale[i], lower + margin, upper - margin);
      }
      const double cost = CostAt(s);
      ++result_.starts_scored;
      if (std::isfinite(cost)) scored.emplace_back(cost, std::move(s));
    }
    if (scored.empty()) {
      throw InputError("no starting point gives a finite model prediction over this log");
    }
    std::stable_sort(scored.begin(), scored.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    return scored;
  }

  // Stage 1: the best few starts solved (loosely: stage 2 solves again), the lowest kept.
  void SolveBestStarts(const std::vector<std::pair<double, std::vector<double>>>& scored) {
    start_cost_ = scored.front().first;
    if (!options_.solve) best_ = best_start_ = scored.front().second;  // statistics at the start
    double best_cost = kInf;
    for (size_t s = 0;
         options_.solve && s < scored.size() && s < static_cast<size_t>(options_.refine_starts);
         ++s) {
      std::vector<double> at = scored[s].second;
      const ceres::Solver::Summary sum = Solve(at, 1e-6);
      ++result_.starts_solved;
      if (sum.final_cost < best_cost || best_.empty()) {
        best_cost = sum.final_cost;
        best_ = at;
        best_start_ = scored[s].second;
        summary_ = sum;
      }
      // Residuals with no structure left (white noise) leave little for another start to find,
      // but a local minimum a little above the noise can look white too: solve at least
      // `min_refine_starts`.
      if (result_.starts_solved >= options_.min_refine_starts &&
          ResidualsLookWhite(cache_.At(best_.data(), false), channels_, options_.white_residuals)) {
        break;
      }
    }
  }

  // Stage 2's solve from the best point, and whether it converged.
  void Refine() {
    if (options_.solve) summary_ = Solve(best_, 1e-7);
    result_.converged = !options_.solve || summary_.termination_type == ceres::CONVERGENCE;
    if (!result_.converged) {
      result_.warnings.push_back(
          fmt::format("the solver stopped without converging: {}", summary_.message));
    }
    result_.final_cost = options_.solve ? summary_.final_cost : start_cost_;
  }

  // Residuals (model - measured) of every used sample of channel c at the best point.
  std::vector<double> ResidualsOf(int c) {
    std::vector<double> r;
    const Predictions* p = cache_.At(best_.data(), false);
    if (p == nullptr) return r;
    for (size_t k = 0; k < n_; ++k) {
      if (std::isfinite(channels_[c].values[k]) && Weight(c, k) > 0.0) {
        r.push_back(p->value[c][k] - channels_[c].values[k]);
      }
    }
    return r;
  }

  void EstimateSigmas() {
    for (int c = 0; c < n_ch_; ++c) {
      const MeasuredChannel& ch = channels_[c];
      if (ch.fixed_sigma) continue;
      const double s = RobustSigma(ResidualsOf(c));
      sigma_[c] = std::isfinite(s) ? std::max(s, ch.min_sigma) : ch.prior_sigma;
      if (!(sigma_[c] > 0.0)) sigma_[c] = ch.prior_sigma;
      inv_sigma_[c] = 1.0 / sigma_[c];
    }
  }

  // Channel c's statistics at the prediction (RMS, outliers, autocorrelation); its noise level
  // inflated for correlated residuals where the options ask; a warning for outliers.
  ChannelStats ChannelStatistics(int c) {
    const MeasuredChannel& ch = channels_[c];
    ChannelStats st;
    st.name = ch.name;
    st.samples = used_[c];
    st.sigma = sigma_[c];
    double sum2 = 0.0, num = 0.0, den = 0.0;
    std::vector<double> r(n_, kNaN);
    for (size_t k = 0; k < n_; ++k) {
      if (!std::isfinite(ch.values[k]) || !(Weight(c, k) > 0.0)) continue;
      r[k] = result_.predicted.value[c][k] - ch.values[k];
      sum2 += r[k] * r[k];
      if (std::abs(r[k]) > kOutlierSigmas * sigma_[c]) ++st.outliers;
    }
    st.rms = used_[c] > 0 ? std::sqrt(sum2 / used_[c]) : kNaN;
    const auto inlier = [&](size_t k) {
      return std::isfinite(r[k]) && std::abs(r[k]) <= 3.0 * sigma_[c];
    };
    for (size_t k = 0; k + 1 < n_; ++k) {
      if (inlier(k) && inlier(k + 1)) {
        num += r[k] * r[k + 1];
        den += r[k] * r[k];
      }
    }
    st.autocorrelation = den > 0.0 ? num / den : 0.0;
    if (options_.inflate_for_autocorrelation && !ch.fixed_sigma) {
      const double rho = std::clamp(st.autocorrelation, 0.0, 0.95);
      sigma_[c] *= std::sqrt((1.0 + rho) / (1.0 - rho));
      inv_sigma_[c] = 1.0 / sigma_[c];
    }
    if (st.outliers > 0) {
      result_.warnings.push_back(fmt::format(
          "{}: {} of {} samples lie beyond {:.0f} noise levels and were down-weighted as "
          "outliers{}",
          ch.name, st.outliers, used_[c], kOutlierSigmas,
          options_.loss == LossKind::kNone ? " (no: --loss none keeps their full weight)" : ""));
    }
    return st;
  }

  // The whitened, loss-corrected Jacobian at the best point, dense.
  Eigen::MatrixXd JacobianAtBest() {
    u_ = best_;
    ceres::CRSMatrix crs;
    problem_.Evaluate(eval_options_, nullptr, nullptr, nullptr, &crs);
    Eigen::MatrixXd jac = Eigen::MatrixXd::Zero(crs.num_rows, crs.num_cols);
    for (int row = 0; row < crs.num_rows; ++row) {
      for (int idx = crs.rows[row]; idx < crs.rows[row + 1]; ++idx) {
        jac(row, crs.cols[idx]) = crs.values[idx];
      }
    }
    return jac;
  }

  // The directions the data cannot see (SVD of the Jacobian), each parameter with too large a
  // share in them marked undetermined; returns their count.
  int FindNullDirections() {
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(JacobianAtBest(), Eigen::ComputeFullV);
    const Eigen::VectorXd& sv = svd.singularValues();
    const Eigen::MatrixXd& v = svd.matrixV();
    const double s_max = sv.size() > 0 ? sv(0) : 0.0;
    std::vector<int> null_dirs;
    for (int j = 0; j < n_par_; ++j) {
      if (j >= sv.size() || !(sv(j) > kRankTolerance * s_max)) null_dirs.push_back(j);
    }
    undetermined_.assign(n_par_, false);
    for (int i = 0; i < n_par_; ++i) {
      double share = 0.0;
      for (int j : null_dirs) share += v(i, j) * v(i, j);
      undetermined_[i] = share > kNullShare;
    }
    result_.null_directions = Eigen::MatrixXd(n_par_, null_dirs.size());
    for (size_t j = 0; j < null_dirs.size(); ++j) {
      for (int i = 0; i < n_par_; ++i) {
        result_.null_directions(i, j) = v(i, null_dirs[j]) * bounds_.scale[i];
      }
    }
    for (const std::string& w : NullSpaceWarnings(parameters_, result_.null_directions)) {
      result_.warnings.push_back(w);
    }
    return static_cast<int>(null_dirs.size());
  }

  // Covariance of the scaled parameters, whitened and loss-corrected residuals. The rank of the
  // Jacobian is checked first (SVD) so that Ceres is only asked for what it can give: the
  // inverse of J'J when J has full rank, else the pseudo-inverse, with the directions the data
  // cannot see reported. Then the estimates and their covariance in the parameters' units.
  void Covariance() {
    cov_u_ = Eigen::MatrixXd::Zero(n_par_, n_par_);
    const int null_dirs = FindNullDirections();
    ceres::Covariance::Options cov_options;
    cov_options.algorithm_type = ceres::DENSE_SVD;
    cov_options.num_threads = 1;
    if (null_dirs > 0) {
      cov_options.null_space_rank = -1;  // pseudo-inverse: drop the directions found above
      cov_options.min_reciprocal_condition_number = kRankTolerance * kRankTolerance;
    }
    const std::vector<std::pair<const double*, const double*>> blocks = {{u_.data(), u_.data()}};
    ceres::Covariance covariance(cov_options);
    // GetCovarianceBlock writes row-major; the matrix is symmetric.
    if (!(covariance.Compute(blocks, &problem_) &&
          covariance.GetCovarianceBlock(u_.data(), u_.data(), cov_u_.data()))) {
      for (int i = 0; i < n_par_; ++i) undetermined_[i] = true;
      result_.warnings.push_back(
          "the covariance could not be computed: every parameter is "
          "reported as undetermined");
    }
    const std::vector<double>& scale = bounds_.scale;
    result_.covariance = Eigen::MatrixXd::Zero(n_par_, n_par_);
    result_.estimates.resize(n_par_);
    for (int i = 0; i < n_par_; ++i) {
      result_.estimates[i].value = best_[i] * scale[i];
      result_.estimates[i].start = best_start_[i] * scale[i];
      result_.estimates[i].undetermined = undetermined_[i];
      for (int j = 0; j < n_par_; ++j) {
        result_.covariance(i, j) = cov_u_(i, j) * scale[i] * scale[j];
      }
    }
  }

  // One end of parameter i's interval at `z` sigmas on `side` (-1 or 1) along `d`, in the
  // parameter's units: where the cost has risen by z^2/2 from `cost_best`; the bound where it
  // never does; nullopt where the quadratic is already wide enough (the end is left as it was).
  std::optional<double> IntervalEnd(int i, const Eigen::VectorXd& d, double z, double side,
                                    double cost_best) {
    const auto rise = [&](double t) {
      std::vector<double> at(n_par_);
      for (int j = 0; j < n_par_; ++j) {
        at[j] = std::clamp(best_[j] + t * d(j), bounds_.lower[j], bounds_.upper[j]);
      }
      return CostAt(at) - cost_best;  // infinite where the model fails
    };
    const double level_rise = 0.5 * z * z;  // chi-square(1) at the level, over 2
    double inside = 0.0, outside = side * z;
    if (rise(outside) >= level_rise) return std::nullopt;  // the quadratic is wide enough
    // Out until the cost has risen enough (or a bound stops the parameter), then bisect.
    bool found = false;
    for (int k = 0; k < 12 && !found; ++k) {
      inside = outside;
      outside *= 2.0;
      found = rise(outside) >= level_rise;
      const double ui = best_[i] + outside * d(i);
      if (!found && (ui <= bounds_.lower[i] || ui >= bounds_.upper[i])) break;
    }
    if (!found) return (side < 0 ? bounds_.lower[i] : bounds_.upper[i]) * bounds_.scale[i];
    for (int k = 0; k < 20; ++k) {
      const double mid = 0.5 * (inside + outside);
      (rise(mid) >= level_rise ? outside : inside) = mid;
    }
    return (best_[i] + outside * d(i)) * bounds_.scale[i];
  }

  // Each determined parameter's 95% and joint likelihood intervals (the same when the family is
  // one).
  void LikelihoodIntervals() {
    const double cost_best = CostAt(best_);
    const double z_joint = JointNormalQuantile(options_.joint_family_size);
    for (int i = 0; i < n_par_ && std::isfinite(cost_best); ++i) {
      if (undetermined_[i] || !(cov_u_(i, i) > 0.0)) continue;
      const Eigen::VectorXd d = cov_u_.col(i) / std::sqrt(cov_u_(i, i));  // moves u_i by 1 sigma
      ParameterEstimate& e = result_.estimates[i];
      for (const bool joint : {false, true}) {
        if (joint && options_.joint_family_size <= 1) {
          e.joint_likelihood_low = e.likelihood_low;
          e.joint_likelihood_high = e.likelihood_high;
          continue;
        }
        for (const double side : {-1.0, 1.0}) {
          double& out = joint ? (side < 0 ? e.joint_likelihood_low : e.joint_likelihood_high)
                              : (side < 0 ? e.likelihood_low : e.likelihood_high);
          const std::optional<double> end =
              IntervalEnd(i, d, joint ? z_joint : internal::kZ95, side, cost_best);
          if (end) out = *end;
        }
      }
    }
  }

  std::span<const FitParameter> parameters_;
  std::span<const MeasuredChannel> channels_;
  const FitOptions& options_;
  const int n_par_, n_ch_;
  const size_t n_;
  const ScaledBounds bounds_;
  PredictionCache cache_;
  std::vector<double> inv_sigma_, sigma_;
  ceres::Problem problem_;
  ceres::LossFunctionWrapper loss_{nullptr, ceres::TAKE_OWNERSHIP};
  std::vector<double> u_;  // the scaled parameters the problem evaluates at
  std::vector<int> used_;  // samples used per channel
  ceres::Solver::Options solver_;
  ceres::Problem::EvaluateOptions eval_options_;
  std::vector<double> best_, best_start_;
  double start_cost_ = kInf;
  ceres::Solver::Summary summary_;
  Eigen::MatrixXd cov_u_;
  std::vector<bool> undetermined_;
  FitResult result_;
};

}  // namespace

FitResult FitChannels(const ChannelModel& model, std::span<const FitParameter> parameters,
                      std::span<const MeasuredChannel> channels,
                      std::span<const std::vector<double>> starts, std::span<const double> time,
                      const FitOptions& options) {
  const int n_par = static_cast<int>(parameters.size());
  if (model.num_parameters() != n_par ||
      model.num_channels() != static_cast<int>(channels.size()) || n_par == 0) {
    throw std::invalid_argument("FitChannels: model and parameter/channel counts differ");
  }
  if (!time.empty() && time.size() != model.num_samples()) {
    throw std::invalid_argument("FitChannels: time size");
  }
  if (options.joint_family_size < 1) {
    throw std::invalid_argument("FitChannels: joint_family_size must be at least 1");
  }
  return ChannelFitter(model, parameters, channels, options).Run(starts, time);
}

}  // namespace hotlap::ident
