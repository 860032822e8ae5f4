#include "hotlap/common/special_values.h"
#include "hotlap/ident/channel_fit.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include <Eigen/Dense>

#include "hotlap/common/error.h"
#include "hotlap/ident/channel_fit_internal.h"

// The parts of channel_fit.h that turn a solution into what is reported: standard errors,
// intervals, verdicts, the sensor-lag diagnostic and the warnings in words.

namespace hotlap::ident {

namespace {

std::string Describe(const FitParameter& p, double value) {
  return fmt::format("{:.4g}{}{}", value + p.display_offset, p.unit.empty() ? "" : " ", p.unit);
}

}  // namespace

std::vector<std::string> NullSpaceWarnings(std::span<const FitParameter> parameters,
                                           const Eigen::MatrixXd& directions) {
  std::vector<std::string> out;
  for (Eigen::Index j = 0; j < directions.cols(); ++j) {
    // In units of the parameters' scales, normalised; name the components that matter.
    Eigen::VectorXd d(directions.rows());
    for (Eigen::Index i = 0; i < d.size(); ++i) d(i) = directions(i, j) / parameters[i].scale;
    if (!(d.norm() > 0.0)) continue;
    d /= d.norm();
    Eigen::Index big = 0;
    d.cwiseAbs().maxCoeff(&big);
    if (d(big) < 0.0) d = -d;
    std::string combination;
    int terms = 0;
    for (Eigen::Index i = 0; i < d.size(); ++i) {
      if (std::abs(d(i)) < 0.1) continue;
      combination +=
          fmt::format("{}{:+.2f} {}", combination.empty() ? "" : " ", d(i), parameters[i].label);
      ++terms;
    }
    if (terms == 1) {
      out.push_back(fmt::format(
          "{} is undetermined: changing it leaves every prediction unchanged (to first order)",
          parameters[big].label));
    } else {
      out.push_back(fmt::format(
          "the data cannot determine the combination ({}) (in units of the parameters' scales): "
          "changing the parameters along it leaves every prediction unchanged (to first order); "
          "each one is reported as undetermined",
          combination));
    }
  }
  return out;
}

double NormalQuantile(double p) {
  if (!(p > 0.0 && p < 1.0)) throw std::invalid_argument("NormalQuantile: p outside (0, 1)");
  // Bisection on Phi(z) = erfc(-z / sqrt 2) / 2, then Newton steps polish it.
  double lo = -40.0, hi = 40.0;
  for (int k = 0; k < 60; ++k) {
    const double mid = 0.5 * (lo + hi);
    (0.5 * std::erfc(-mid / std::sqrt(2.0)) < p ? lo : hi) = mid;
  }
  double z = 0.5 * (lo + hi);
  for (int k = 0; k < 3; ++k) {
    const double pdf = std::exp(-0.5 * z * z) / std::sqrt(2.0 * std::numbers::pi);
    if (!(pdf > 0.0)) break;
    z -= (0.5 * std::erfc(-z / std::sqrt(2.0)) - p) / pdf;
  }
  return z;
}

double JointNormalQuantile(int family_size) {
  if (family_size < 1) throw std::invalid_argument("JointNormalQuantile: family_size < 1");
  return NormalQuantile(1.0 - 0.025 / family_size);
}

LossKind ParseLossKind(const std::string& text) {
  if (text == "none") return LossKind::kNone;
  if (text == "huber") return LossKind::kHuber;
  if (text == "cauchy") return LossKind::kCauchy;
  throw InputError(fmt::format("loss '{}': expected none, huber or cauchy", text));
}

const char* LossKindName(LossKind kind) {
  switch (kind) {
    case LossKind::kHuber:
      return "huber";
    case LossKind::kCauchy:
      return "cauchy";
    case LossKind::kNone:
      break;
  }
  return "none";
}

void SummarizeEstimates(FitResult& result, const FitOptions& options) {
  const size_t n = result.parameters.size();
  const double z_joint = JointNormalQuantile(options.joint_family_size);
  result.correlation = Eigen::MatrixXd::Constant(n, n, kNaN);
  std::vector<std::string>& warnings = result.estimate_warnings;
  warnings.clear();
  for (size_t i = 0; i < n; ++i) {
    const FitParameter& p = result.parameters[i];
    ParameterEstimate& e = result.estimates[i];
    const double var = result.covariance(i, i);
    if (!std::isfinite(var)) e.undetermined = true;
    e.std_error = e.undetermined ? kInf : std::sqrt(std::max(var, 0.0));
    e.ci_low = e.undetermined ? p.lower : std::max(p.lower, e.value - internal::kZ95 * e.std_error);
    e.ci_high =
        e.undetermined ? p.upper : std::min(p.upper, e.value + internal::kZ95 * e.std_error);
    e.joint_low = e.undetermined ? p.lower : std::max(p.lower, e.value - z_joint * e.std_error);
    e.joint_high = e.undetermined ? p.upper : std::min(p.upper, e.value + z_joint * e.std_error);
    if (!e.undetermined && std::isfinite(e.std_error)) {
      if (e.likelihood_low < e.ci_low) e.ci_low = std::max(p.lower, e.likelihood_low);
      if (e.likelihood_high > e.ci_high) e.ci_high = std::min(p.upper, e.likelihood_high);
      if (e.joint_likelihood_low < e.joint_low) {
        e.joint_low = std::max(p.lower, e.joint_likelihood_low);
      }
      if (e.joint_likelihood_high > e.joint_high) {
        e.joint_high = std::min(p.upper, e.joint_likelihood_high);
      }
    }
    // A joint interval is never narrower than the 95% one (a widened 95% edge may reach past it).
    e.joint_low = std::min(e.joint_low, e.ci_low);
    e.joint_high = std::max(e.joint_high, e.ci_high);
    const double range = p.upper - p.lower;
    const double tol = std::min(std::isfinite(range) ? 1e-6 * range : kInf, 1e-4 * p.scale);
    e.at_bound = e.value - p.lower <= tol || p.upper - e.value <= tol;
    const double half_width =
        std::max({internal::kZ95 * e.std_error, e.value - e.ci_low, e.ci_high - e.value});
    const bool narrow = p.role == ParameterRole::kModel
                            ? half_width <= options.max_relative_ci * std::abs(e.value)
                            : half_width <= options.max_nuisance_ci;
    e.well_determined = !e.undetermined && !e.at_bound && narrow;
    if (p.role != ParameterRole::kModel || e.undetermined) continue;
    if (e.at_bound) {
      warnings.push_back(fmt::format(
          "{} is at its {} bound {}: the data would move it further, so its interval is one-sided "
          "and not reliable",
          p.label, e.value - p.lower <= tol ? "lower" : "upper",
          Describe(p, e.value - p.lower <= tol ? p.lower : p.upper)));
    } else if (!narrow) {
      warnings.push_back(fmt::format(
          "{} is poorly determined: {} with 95% interval [{:.4g}, {:.4g}] (+/-{:.0f}% of its "
          "value)",
          p.label, Describe(p, e.value), e.ci_low + p.display_offset, e.ci_high + p.display_offset,
          e.value != 0.0 ? 100.0 * half_width / std::abs(e.value) : kInf));
    }
  }
  for (size_t i = 0; i < n; ++i) {
    for (size_t j = 0; j < n; ++j) {
      const double s = result.estimates[i].std_error * result.estimates[j].std_error;
      if (std::isfinite(s) && s > 0.0) result.correlation(i, j) = result.covariance(i, j) / s;
    }
  }
  for (size_t i = 0; i < n; ++i) {
    for (size_t j = i + 1; j < n; ++j) {
      const double r = result.correlation(i, j);
      const auto& a = result.estimates[i];
      const auto& b = result.estimates[j];
      if (std::abs(r) > 0.99 && (!a.well_determined || !b.well_determined) &&
          result.parameters[i].role == ParameterRole::kModel &&
          result.parameters[j].role == ParameterRole::kModel) {
        warnings.push_back(fmt::format(
            "{} and {} are nearly interchangeable (correlation {:.3f}): the data fix mainly a "
            "combination of the two",
            result.parameters[i].label, result.parameters[j].label, r));
      }
    }
  }
}

namespace internal {

// The sensor-lag diagnostic: if a channel's sensor lags by tau, measured ~ model(t - tau) ~
// model - tau dmodel/dt. One Gauss-Newton step of the fit with a lag per channel added (the
// parameters free to move with it, so what they absorbed of the lag is given back), over the
// inlier samples, estimates each tau and its standard error.
void EstimateApparentLags(const Predictions& at_best, std::span<const double> scale,
                          std::span<const MeasuredChannel> channels, std::span<const double> time,
                          FitResult* result) {
  const Predictions* p = &at_best;
  const size_t n = time.size();
  const int n_par = static_cast<int>(scale.size());
  const int n_ch = static_cast<int>(channels.size());
  std::vector<std::array<double, 3>> rows;  // (channel, sample, weight) of the inliers
  for (int c = 0; c < n_ch; ++c) {
    const double sigma = result->channels[c].sigma;
    for (size_t k = 0; k < n; ++k) {
      const double w = channels[c].weights.empty() ? 1.0 : channels[c].weights[k];
      const double m = channels[c].values[k];
      if (!std::isfinite(m) || !(w > 0.0)) continue;
      if (std::abs(p->value[c][k] - m) > 3.0 * sigma) continue;
      rows.push_back({double(c), double(k), std::sqrt(w) / sigma});
    }
  }
  if (rows.size() < static_cast<size_t>(n_par + n_ch + 1)) return;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(rows.size(), n_par + n_ch);
  Eigen::VectorXd b(rows.size());
  for (size_t i = 0; i < rows.size(); ++i) {
    const int c = static_cast<int>(rows[i][0]);
    const size_t k = static_cast<size_t>(rows[i][1]);
    const double f = rows[i][2];
    for (int j = 0; j < n_par; ++j) a(i, j) = f * p->jacobian[c][k * n_par + j] * scale[j];
    const size_t lo = k == 0 ? 0 : k - 1, hi = std::min(k + 1, n - 1);
    const double rate = (p->value[c][hi] - p->value[c][lo]) / (time[hi] - time[lo]);
    a(i, n_par + c) = -f * rate;
    b(i) = -f * (p->value[c][k] - channels[c].values[k]);
  }
  const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(a);
  const Eigen::VectorXd x = cod.solve(b);
  const Eigen::MatrixXd cov = (a.transpose() * a).completeOrthogonalDecomposition().pseudoInverse();
  for (int c = 0; c < n_ch; ++c) {
    if (result->channels[c].samples < 3) continue;
    const double var = cov(n_par + c, n_par + c);
    if (!(var > 0.0)) continue;
    result->channels[c].apparent_lag = x(n_par + c);
    result->channels[c].apparent_lag_std_error = std::sqrt(var);
  }
}

}  // namespace internal

}  // namespace hotlap::ident
