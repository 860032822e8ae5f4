#include "hotlap/ident/channel_fit.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
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

constexpr double kZ95 = 1.959963984540054;  // two-sided 95% normal quantile
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
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

FitResult FitChannels(const ChannelModel& model, std::span<const FitParameter> parameters,
                      std::span<const MeasuredChannel> channels,
                      std::span<const std::vector<double>> starts, std::span<const double> time,
                      const FitOptions& options) {
  const int n_par = static_cast<int>(parameters.size());
  const int n_ch = static_cast<int>(channels.size());
  const size_t n = model.num_samples();
  if (model.num_parameters() != n_par || model.num_channels() != n_ch || n_par == 0) {
    throw std::invalid_argument("FitChannels: model and parameter/channel counts differ");
  }
  if (!time.empty() && time.size() != n) throw std::invalid_argument("FitChannels: time size");
  if (options.joint_family_size < 1) {
    throw std::invalid_argument("FitChannels: joint_family_size must be at least 1");
  }
  std::vector<double> scale(n_par), lower(n_par), upper(n_par);
  for (int i = 0; i < n_par; ++i) {
    const FitParameter& p = parameters[i];
    if (!(p.scale > 0.0) || !(p.lower < p.upper)) {
      throw std::invalid_argument("FitChannels: bad scale or bounds for " + p.key);
    }
    scale[i] = p.scale;
    lower[i] = p.lower / p.scale;
    upper[i] = p.upper / p.scale;
  }

  PredictionCache cache(model, scale);
  std::vector<double> inv_sigma(n_ch);
  std::vector<double> sigma(n_ch);
  ceres::Problem::Options problem_options;
  problem_options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  ceres::LossFunctionWrapper loss(nullptr, ceres::TAKE_OWNERSHIP);
  std::vector<double> u(n_par, 0.0);
  problem.AddParameterBlock(u.data(), n_par);
  std::vector<int> used(n_ch, 0);
  for (int c = 0; c < n_ch; ++c) {
    const MeasuredChannel& ch = channels[c];
    if (ch.values.size() != n || (!ch.weights.empty() && ch.weights.size() != n)) {
      throw std::invalid_argument("FitChannels: channel size differs from the model's: " + ch.name);
    }
    sigma[c] = ch.prior_sigma;
    inv_sigma[c] = 1.0 / ch.prior_sigma;
    for (size_t k = 0; k < n; ++k) {
      const double w = ch.weights.empty() ? 1.0 : ch.weights[k];
      if (!std::isfinite(ch.values[k]) || !(w > 0.0)) continue;
      problem.AddResidualBlock(
          new SampleResidual(&cache, c, k, ch.values[k], std::sqrt(w), &inv_sigma[c]), &loss,
          u.data());
      ++used[c];
    }
  }
  if (problem.NumResidualBlocks() == 0) throw InputError("no measurements to fit");
  for (int i = 0; i < n_par; ++i) {
    if (std::isfinite(lower[i])) problem.SetParameterLowerBound(u.data(), i, lower[i]);
    if (std::isfinite(upper[i])) problem.SetParameterUpperBound(u.data(), i, upper[i]);
  }

  FitResult result;
  result.parameters.assign(parameters.begin(), parameters.end());
  ceres::Problem::EvaluateOptions eval_options;
  const auto cost_at = [&](const std::vector<double>& at) {
    u = at;
    double cost = kInf;
    if (!problem.Evaluate(eval_options, &cost, nullptr, nullptr, nullptr)) return kInf;
    return std::isfinite(cost) ? cost : kInf;
  };
  ceres::Solver::Options solver;
  solver.linear_solver_type = ceres::DENSE_QR;
  solver.max_num_iterations = options.max_iterations;
  solver.gradient_tolerance = 1e-12;
  solver.parameter_tolerance = 1e-10;
  solver.logging_type = ceres::SILENT;
  solver.num_threads = 1;
  // Stage 1 only has to find the right basin (stage 2 solves again), so it stops earlier.
  const auto solve = [&](std::vector<double>& at, double function_tolerance) {
    u = at;
    solver.function_tolerance = function_tolerance;
    ceres::Solver::Summary summary;
    ceres::Solve(solver, &problem, &summary);
    at = u;
    result.iterations += static_cast<int>(summary.iterations.size());
    return summary;
  };

  // 1. Score every start, solve the best few, keep the lowest cost.
  loss.Reset(MakeLoss(options.loss == LossKind::kNone ? LossKind::kNone : LossKind::kHuber,
                      options.loss_scale),
             ceres::TAKE_OWNERSHIP);
  std::vector<std::pair<double, std::vector<double>>> scored;
  for (const std::vector<double>& start : starts) {
    if (static_cast<int>(start.size()) != n_par) {
      throw std::invalid_argument("FitChannels: start size");
    }
    std::vector<double> s(n_par);
    for (int i = 0; i < n_par; ++i) {
      // Inside the bounds and a little away from them, so the first step can go either way.
      const double margin = std::isfinite(upper[i] - lower[i]) ? 1e-6 * (upper[i] - lower[i]) : 0;
      s[i] = std::clamp(start[i] / scale[i], lower[i] + margin, upper[i] - margin);
    }
    const double cost = cost_at(s);
    ++result.starts_scored;
    if (std::isfinite(cost)) scored.emplace_back(cost, std::move(s));
  }
  if (scored.empty()) {
    throw InputError("no starting point gives a finite model prediction over this log");
  }
  std::stable_sort(scored.begin(), scored.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<double> best, best_start;
  double best_cost = kInf;
  ceres::Solver::Summary summary;
  if (!options.solve) {
    best = best_start = scored.front().second;  // statistics at the (only) start
  }
  for (size_t s = 0;
       options.solve && s < scored.size() && s < static_cast<size_t>(options.refine_starts); ++s) {
    std::vector<double> at = scored[s].second;
    const ceres::Solver::Summary sum = solve(at, 1e-6);
    ++result.starts_solved;
    if (sum.final_cost < best_cost || best.empty()) {
      best_cost = sum.final_cost;
      best = at;
      best_start = scored[s].second;
      summary = sum;
    }
    // Residuals with no structure left (white noise) leave little for another start to find,
    // but a local minimum a little above the noise can look white too: solve at least
    // `min_refine_starts`.
    if (result.starts_solved >= options.min_refine_starts &&
        ResidualsLookWhite(cache.At(best.data(), false), channels, options.white_residuals)) {
      break;
    }
  }

  // Residuals (model - measured) of every used sample of channel c at `best`.
  const auto residuals_of = [&](int c) {
    std::vector<double> r;
    const Predictions* p = cache.At(best.data(), false);
    if (p == nullptr) return r;
    for (size_t k = 0; k < n; ++k) {
      const double w = channels[c].weights.empty() ? 1.0 : channels[c].weights[k];
      if (std::isfinite(channels[c].values[k]) && w > 0.0) {
        r.push_back(p->value[c][k] - channels[c].values[k]);
      }
    }
    return r;
  };
  const auto estimate_sigmas = [&] {
    for (int c = 0; c < n_ch; ++c) {
      if (channels[c].fixed_sigma) continue;
      const double s = RobustSigma(residuals_of(c));
      sigma[c] = std::isfinite(s) ? std::max(s, channels[c].min_sigma) : channels[c].prior_sigma;
      if (!(sigma[c] > 0.0)) sigma[c] = channels[c].prior_sigma;
      inv_sigma[c] = 1.0 / sigma[c];
    }
  };

  // 2. Noise levels from the residuals; solve again with the chosen loss in sigma units.
  estimate_sigmas();
  loss.Reset(MakeLoss(options.loss, options.loss_scale), ceres::TAKE_OWNERSHIP);
  if (options.solve) summary = solve(best, 1e-7);
  result.converged = !options.solve || summary.termination_type == ceres::CONVERGENCE;
  if (!result.converged) {
    result.warnings.push_back(
        fmt::format("the solver stopped without converging: {}", summary.message));
  }

  // 3. Final noise levels, inflated for correlated residuals; per-channel statistics.
  estimate_sigmas();
  const Predictions* at_best = cache.At(best.data(), false);
  if (at_best == nullptr) throw NumericalError("the fitted model's prediction is not finite");
  result.predicted = *at_best;
  for (int c = 0; c < n_ch; ++c) {
    const MeasuredChannel& ch = channels[c];
    ChannelStats st;
    st.name = ch.name;
    st.samples = used[c];
    st.sigma = sigma[c];
    double sum2 = 0.0, num = 0.0, den = 0.0;
    std::vector<double> r(n, kNaN);
    for (size_t k = 0; k < n; ++k) {
      const double w = ch.weights.empty() ? 1.0 : ch.weights[k];
      if (!std::isfinite(ch.values[k]) || !(w > 0.0)) continue;
      r[k] = result.predicted.value[c][k] - ch.values[k];
      sum2 += r[k] * r[k];
      if (std::abs(r[k]) > kOutlierSigmas * sigma[c]) ++st.outliers;
    }
    st.rms = used[c] > 0 ? std::sqrt(sum2 / used[c]) : kNaN;
    const auto inlier = [&](size_t k) {
      return std::isfinite(r[k]) && std::abs(r[k]) <= 3.0 * sigma[c];
    };
    for (size_t k = 0; k + 1 < n; ++k) {
      if (inlier(k) && inlier(k + 1)) {
        num += r[k] * r[k + 1];
        den += r[k] * r[k];
      }
    }
    st.autocorrelation = den > 0.0 ? num / den : 0.0;
    if (options.inflate_for_autocorrelation && !ch.fixed_sigma) {
      const double rho = std::clamp(st.autocorrelation, 0.0, 0.95);
      sigma[c] *= std::sqrt((1.0 + rho) / (1.0 - rho));
      inv_sigma[c] = 1.0 / sigma[c];
    }
    if (st.outliers > 0) {
      result.warnings.push_back(fmt::format(
          "{}: {} of {} samples lie beyond {:.0f} noise levels and were down-weighted as "
          "outliers{}",
          ch.name, st.outliers, used[c], kOutlierSigmas,
          options.loss == LossKind::kNone ? " (no: --loss none keeps their full weight)" : ""));
    }
    result.channels.push_back(st);
  }

  if (!time.empty() && n >= 3) {
    if (const Predictions* p = cache.At(best.data(), true)) {
      internal::EstimateApparentLags(*p, cache.scale(), channels, time, &result);
    }
  }

  // Covariance of the scaled parameters, whitened and loss-corrected residuals. The rank of
  // the Jacobian is checked first (SVD) so that Ceres is only asked for what it can give: the
  // inverse of J'J when J has full rank, else the pseudo-inverse, with the directions the data
  // cannot see reported.
  u = best;
  Eigen::MatrixXd cov_u = Eigen::MatrixXd::Zero(n_par, n_par);
  std::vector<bool> undetermined(n_par, false);
  ceres::CRSMatrix crs;
  problem.Evaluate(eval_options, nullptr, nullptr, nullptr, &crs);
  Eigen::MatrixXd jac = Eigen::MatrixXd::Zero(crs.num_rows, crs.num_cols);
  for (int row = 0; row < crs.num_rows; ++row) {
    for (int idx = crs.rows[row]; idx < crs.rows[row + 1]; ++idx) {
      jac(row, crs.cols[idx]) = crs.values[idx];
    }
  }
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(jac, Eigen::ComputeFullV);
  const Eigen::VectorXd& sv = svd.singularValues();
  const Eigen::MatrixXd& v = svd.matrixV();
  const double s_max = sv.size() > 0 ? sv(0) : 0.0;
  std::vector<int> null_dirs;
  for (int j = 0; j < n_par; ++j) {
    if (j >= sv.size() || !(sv(j) > kRankTolerance * s_max)) null_dirs.push_back(j);
  }
  for (int i = 0; i < n_par; ++i) {
    double share = 0.0;
    for (int j : null_dirs) share += v(i, j) * v(i, j);
    undetermined[i] = share > kNullShare;
  }
  result.null_directions = Eigen::MatrixXd(n_par, null_dirs.size());
  for (size_t j = 0; j < null_dirs.size(); ++j) {
    for (int i = 0; i < n_par; ++i) result.null_directions(i, j) = v(i, null_dirs[j]) * scale[i];
  }
  for (const std::string& w : NullSpaceWarnings(parameters, result.null_directions)) {
    result.warnings.push_back(w);
  }
  ceres::Covariance::Options cov_options;
  cov_options.algorithm_type = ceres::DENSE_SVD;
  cov_options.num_threads = 1;
  if (!null_dirs.empty()) {
    cov_options.null_space_rank = -1;  // pseudo-inverse: drop the directions found above
    cov_options.min_reciprocal_condition_number = kRankTolerance * kRankTolerance;
  }
  const std::vector<std::pair<const double*, const double*>> blocks = {{u.data(), u.data()}};
  ceres::Covariance covariance(cov_options);
  // GetCovarianceBlock writes row-major; the matrix is symmetric.
  if (!(covariance.Compute(blocks, &problem) &&
        covariance.GetCovarianceBlock(u.data(), u.data(), cov_u.data()))) {
    for (int i = 0; i < n_par; ++i) undetermined[i] = true;
    result.warnings.push_back(
        "the covariance could not be computed: every parameter is "
        "reported as undetermined");
  }

  result.covariance = Eigen::MatrixXd::Zero(n_par, n_par);
  result.estimates.resize(n_par);
  for (int i = 0; i < n_par; ++i) {
    result.estimates[i].value = best[i] * scale[i];
    result.estimates[i].start = best_start[i] * scale[i];
    result.estimates[i].undetermined = undetermined[i];
    for (int j = 0; j < n_par; ++j) result.covariance(i, j) = cov_u(i, j) * scale[i] * scale[j];
  }
  result.final_cost = options.solve ? summary.final_cost : scored.front().first;

  // 4. The intervals against the cost itself, along each parameter's profile direction.
  const double cost_best = cost_at(best);
  // Each interval's level: the 95% one and the joint one (the same when the family is one).
  const double z_joint = JointNormalQuantile(options.joint_family_size);
  for (int i = 0; i < n_par && std::isfinite(cost_best); ++i) {
    if (undetermined[i] || !(cov_u(i, i) > 0.0)) continue;
    const Eigen::VectorXd d = cov_u.col(i) / std::sqrt(cov_u(i, i));  // moves u_i by 1 sigma
    const auto rise = [&](double t) {
      std::vector<double> at(n_par);
      for (int j = 0; j < n_par; ++j) at[j] = std::clamp(best[j] + t * d(j), lower[j], upper[j]);
      return cost_at(at) - cost_best;  // infinite where the model fails
    };
    for (const bool joint : {false, true}) {
      ParameterEstimate& e = result.estimates[i];
      if (joint && options.joint_family_size <= 1) {
        e.joint_likelihood_low = e.likelihood_low;
        e.joint_likelihood_high = e.likelihood_high;
        continue;
      }
      const double z = joint ? z_joint : kZ95;
      const double level_rise = 0.5 * z * z;  // chi-square(1) at the level, over 2
      for (const double side : {-1.0, 1.0}) {
        double& out = joint ? (side < 0 ? e.joint_likelihood_low : e.joint_likelihood_high)
                            : (side < 0 ? e.likelihood_low : e.likelihood_high);
        double inside = 0.0, outside = side * z;
        if (rise(outside) >= level_rise) continue;  // the quadratic is wide enough
        // Out until the cost has risen enough (or a bound stops the parameter), then bisect.
        bool found = false;
        for (int k = 0; k < 12 && !found; ++k) {
          inside = outside;
          outside *= 2.0;
          found = rise(outside) >= level_rise;
          const double ui = best[i] + outside * d(i);
          if (!found && (ui <= lower[i] || ui >= upper[i])) break;
        }
        double endpoint = (side < 0 ? lower[i] : upper[i]) * scale[i];  // never rose enough
        if (found) {
          for (int k = 0; k < 20; ++k) {
            const double mid = 0.5 * (inside + outside);
            (rise(mid) >= level_rise ? outside : inside) = mid;
          }
          endpoint = (best[i] + outside * d(i)) * scale[i];
        }
        out = endpoint;
      }
    }
  }
  u = best;
  SummarizeEstimates(result, options);
  return result;
}

}  // namespace hotlap::ident
