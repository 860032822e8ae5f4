// The fitting engine on problems with known answers: a straight line (the covariance is
// sigma^2 (X'X)^-1 exactly), the coverage of the 95% intervals over many noisy realisations of a
// nonlinear decay, a rank-deficient model, outliers under each loss, and the multi-start.

#include "hotlap/ident/channel_fit.h"

#include <cmath>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "hotlap/common/error.h"
#include "hotlap/ident/jet_predictor.h"
#include "hotlap/sim/synth_sensor.h"
#include "test_util.h"

namespace hotlap::ident {
namespace {

// y(t) = a + b t (+ c t for the rank-deficient variant: b and c only appear as b + c).
struct LineModel {
  std::vector<double> t;
  bool twin = false;
  size_t num_samples() const { return t.size(); }
  int num_channels() const { return 1; }
  template <Scalar T, class Emit>
  void Run(std::span<const T> x, Emit&& emit) const {
    for (size_t k = 0; k < t.size(); ++k) {
      emit(0, k, x[0] + (twin ? x[1] + x[2] : x[1]) * t[k]);
    }
  }
};

// y(t) = A exp(-t / tau).
struct DecayModel {
  std::vector<double> t;
  size_t num_samples() const { return t.size(); }
  int num_channels() const { return 1; }
  template <Scalar T, class Emit>
  void Run(std::span<const T> x, Emit&& emit) const {
    using std::exp;
    for (size_t k = 0; k < t.size(); ++k) emit(0, k, x[0] * exp(-t[k] / x[1]));
  }
};

std::vector<double> Grid(int n, double dt) {
  std::vector<double> t(n);
  for (int k = 0; k < n; ++k) t[k] = k * dt;
  return t;
}

MeasuredChannel Noisy(const std::vector<double>& truth, double sigma, uint64_t seed) {
  sim::GaussianNoise noise(seed);
  MeasuredChannel ch{.name = "y", .values = truth, .prior_sigma = sigma};
  for (double& v : ch.values) v += sigma * noise.Next();
  return ch;
}

TEST(ChannelFitTest, StraightLineCovarianceIsSigmaSquaredInverseXtX) {
  const LineModel model{Grid(50, 0.1)};
  std::vector<double> truth;
  for (double t : model.t) truth.push_back(2.0 + 3.0 * t);
  MeasuredChannel ch = Noisy(truth, 0.1, 7);
  ch.fixed_sigma = true;  // the known noise level: the covariance is then exact
  const std::vector<FitParameter> params = {{"a", "a", "", -100, 100, 1.0},
                                            {"b", "b", "", -100, 100, 1.0}};
  const JetPredictor<LineModel> predictor(model, {0.0, 0.0}, {0, 1}, {0});
  FitOptions options;
  options.loss = LossKind::kNone;
  const FitResult r = FitChannels(predictor, params, std::vector{ch},
                                  std::vector<std::vector<double>>{{0.0, 0.0}}, {}, options);
  Eigen::MatrixXd x(50, 2);
  Eigen::VectorXd y(50);
  for (int k = 0; k < 50; ++k) {
    x(k, 0) = 1.0;
    x(k, 1) = model.t[k];
    y(k) = ch.values[k];
  }
  const Eigen::Vector2d ls = x.colPivHouseholderQr().solve(y);
  const Eigen::Matrix2d cov = 0.01 * (x.transpose() * x).inverse();
  // To the solver's tolerance: a thousandth of a standard error.
  EXPECT_NEAR(r.estimates[0].value, ls(0), 1e-3 * std::sqrt(cov(0, 0)));
  EXPECT_NEAR(r.estimates[1].value, ls(1), 1e-3 * std::sqrt(cov(1, 1)));
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) EXPECT_NEAR(r.covariance(i, j), cov(i, j), 1e-9 * cov(0, 0));
  }
  EXPECT_NEAR(r.estimates[1].std_error, std::sqrt(cov(1, 1)), 1e-9);
  EXPECT_NEAR(r.estimates[1].ci_high - r.estimates[1].value, 1.959964 * std::sqrt(cov(1, 1)), 1e-6);
  EXPECT_NEAR(r.correlation(0, 1), cov(0, 1) / std::sqrt(cov(0, 0) * cov(1, 1)), 1e-9);
  EXPECT_TRUE(r.estimates[0].well_determined && r.estimates[1].well_determined);
  EXPECT_TRUE(r.AllWarnings().empty());
  // A family of one: the joint interval is the 95% one.
  EXPECT_EQ(r.estimates[1].joint_high, r.estimates[1].ci_high);
  EXPECT_EQ(r.estimates[1].joint_low, r.estimates[1].ci_low);

  // A family of ten (Bonferroni, 0.5% per interval): Phi^-1(0.9975) = 2.807034 std errors (a
  // linear model: its cost is exactly quadratic, so no widening).
  options.joint_family_size = 10;
  const FitResult r10 = FitChannels(predictor, params, std::vector{ch},
                                    std::vector<std::vector<double>>{{0.0, 0.0}}, {}, options);
  EXPECT_NEAR(r10.estimates[1].joint_high - r10.estimates[1].value, 2.807034 * std::sqrt(cov(1, 1)),
              1e-6);
  EXPECT_NEAR(r10.estimates[1].value - r10.estimates[1].joint_low, 2.807034 * std::sqrt(cov(1, 1)),
              1e-6);
  EXPECT_NEAR(r10.estimates[1].ci_high - r10.estimates[1].value, 1.959964 * std::sqrt(cov(1, 1)),
              1e-6);
  options.joint_family_size = 0;
  EXPECT_THROW(FitChannels(predictor, params, std::vector{ch},
                           std::vector<std::vector<double>>{{0.0, 0.0}}, {}, options),
               std::invalid_argument);
}

// Table values of the standard normal quantile.
TEST(ChannelFitTest, NormalQuantileMatchesTables) {
  EXPECT_NEAR(NormalQuantile(0.5), 0.0, 1e-14);
  EXPECT_NEAR(NormalQuantile(0.975), 1.959963984540054, 1e-12);
  EXPECT_NEAR(NormalQuantile(0.995), 2.575829303548901, 1e-12);
  EXPECT_NEAR(NormalQuantile(0.999), 3.090232306167814, 1e-12);
  EXPECT_NEAR(NormalQuantile(0.001), -3.090232306167814, 1e-12);
  EXPECT_NEAR(NormalQuantile(1e-9), -5.997807015007686, 1e-10);
  EXPECT_NEAR(JointNormalQuantile(1), 1.959963984540054, 1e-12);
  EXPECT_NEAR(JointNormalQuantile(2), 2.241402727604947, 1e-12);   // Phi^-1(0.9875)
  EXPECT_NEAR(JointNormalQuantile(10), 2.807033768343811, 1e-12);  // Phi^-1(0.9975)
  EXPECT_THROW(NormalQuantile(0.0), std::invalid_argument);
  EXPECT_THROW(NormalQuantile(1.0), std::invalid_argument);
  EXPECT_THROW(JointNormalQuantile(0), std::invalid_argument);
}

// Over 200 noisy realisations, each 95% interval holds the truth about 95% of the time (the
// binomial standard deviation is 1.5%), with the noise level estimated from the residuals; the
// joint intervals of the two parameters hold both at once at least about 95% of the time
// (Bonferroni is conservative: 95% to 97.5% by the correlation), where the two 95% intervals
// together hold both only about 90 to 95% of the time.
TEST(ChannelFitTest, NinetyFivePercentIntervalsCoverNinetyFivePercent) {
  const DecayModel model{Grid(80, 0.05)};
  std::vector<double> truth;
  for (double t : model.t) truth.push_back(5.0 * std::exp(-t / 1.5));
  const std::vector<FitParameter> params = {{"A", "A", "", 0.0, 100.0, 5.0},
                                            {"tau", "tau", "s", 0.01, 100.0, 1.0}};
  const JetPredictor<DecayModel> predictor(model, {1.0, 1.0}, {0, 1}, {0});
  int covered[2] = {0, 0}, both_covered = 0, jointly_covered = 0;
  constexpr int kRuns = 200;
  FitOptions options;
  options.joint_family_size = 2;
  for (int seed = 1; seed <= kRuns; ++seed) {
    const FitResult r =
        FitChannels(predictor, params, std::vector{Noisy(truth, 0.05, seed)},
                    std::vector<std::vector<double>>{{1.0, 1.0}, {10.0, 0.2}}, {}, options);
    const double t[2] = {5.0, 1.5};
    bool both = true, joint = true;
    for (int i = 0; i < 2; ++i) {
      const ParameterEstimate& e = r.estimates[i];
      const bool in = t[i] >= e.ci_low && t[i] <= e.ci_high;
      covered[i] += in;
      both = both && in;
      joint = joint && t[i] >= e.joint_low && t[i] <= e.joint_high;
      EXPECT_TRUE(e.joint_low <= e.ci_low && e.joint_high >= e.ci_high) << seed;
    }
    both_covered += both;
    jointly_covered += joint;
  }
  for (int i = 0; i < 2; ++i) {
    EXPECT_GE(covered[i], 0.91 * kRuns) << i;
    EXPECT_LE(covered[i], 0.99 * kRuns) << i;
  }
  EXPECT_GE(jointly_covered, 0.92 * kRuns);
  EXPECT_GT(jointly_covered, both_covered);
}

TEST(ChannelFitTest, RankDeficientModelReportsTheUndeterminedCombination) {
  const LineModel model{Grid(40, 0.1), true};
  std::vector<double> truth;
  for (double t : model.t) truth.push_back(1.0 + 2.0 * t);
  const std::vector<FitParameter> params = {
      {"a", "a", "", -10, 10, 1.0}, {"b", "b", "", -10, 10, 1.0}, {"c", "c", "", -10, 10, 1.0}};
  const JetPredictor<LineModel> predictor(model, {0.0, 0.0, 0.0}, {0, 1, 2}, {0});
  const FitResult r =
      FitChannels(predictor, params, std::vector{Noisy(truth, 0.01, 3)},
                  std::vector<std::vector<double>>{{0.0, 0.5, 0.5}}, {}, FitOptions{});
  EXPECT_FALSE(r.estimates[0].undetermined);
  EXPECT_TRUE(r.estimates[0].well_determined);
  for (int i : {1, 2}) {
    EXPECT_TRUE(r.estimates[i].undetermined);
    EXPECT_FALSE(r.estimates[i].well_determined);
    EXPECT_TRUE(std::isinf(r.estimates[i].std_error));
    EXPECT_EQ(r.estimates[i].ci_low, -10.0);  // the interval is the bounds
    EXPECT_EQ(r.estimates[i].ci_high, 10.0);
  }
  EXPECT_NEAR(r.estimates[1].value + r.estimates[2].value, 2.0, 0.01);
  ASSERT_EQ(r.null_directions.cols(), 1);
  bool named = false;
  for (const std::string& w : r.AllWarnings()) {
    named |= w.find("combination") != std::string::npos && w.find(" b") != std::string::npos &&
             w.find(" c") != std::string::npos;
  }
  EXPECT_TRUE(named) << ::testing::PrintToString(r.AllWarnings());
}

// 3% of the samples (6 of 200) 40 noise levels off: the robust losses shrug them off, plain least
// squares does not, and the warning counts them.
TEST(ChannelFitTest, RobustLossesResistOutliers) {
  const LineModel model{Grid(200, 0.05)};
  std::vector<double> truth;
  for (double t : model.t) truth.push_back(1.0 + 0.5 * t);
  MeasuredChannel ch = Noisy(truth, 0.1, 11);
  for (size_t k = 5; k < ch.values.size(); k += 33) ch.values[k] += 4.0;
  const std::vector<FitParameter> params = {{"a", "a", "", -10, 10, 1.0},
                                            {"b", "b", "", -10, 10, 1.0}};
  const JetPredictor<LineModel> predictor(model, {0.0, 0.0}, {0, 1}, {0});
  for (LossKind loss : {LossKind::kHuber, LossKind::kCauchy, LossKind::kNone}) {
    FitOptions options;
    options.loss = loss;
    const FitResult r = FitChannels(predictor, params, std::vector{ch},
                                    std::vector<std::vector<double>>{{0.0, 0.0}}, {}, options);
    const double error = std::abs(r.estimates[0].value - 1.0);
    if (loss == LossKind::kNone) {
      EXPECT_GT(error, 0.08) << "least squares is pulled by the outliers";
    } else {
      EXPECT_LT(error, 0.05) << LossKindName(loss);
      EXPECT_NEAR(r.channels[0].sigma, 0.1, 0.02) << LossKindName(loss);
    }
    EXPECT_EQ(r.channels[0].outliers, 6) << LossKindName(loss);
    bool warned = false;
    for (const std::string& w : r.AllWarnings()) warned |= w.find("outliers") != std::string::npos;
    EXPECT_TRUE(warned) << LossKindName(loss);
  }
}

// A decay started from a time constant 100 times too small is found by the other start.
TEST(ChannelFitTest, MultiStartFindsTheBetterMinimum) {
  const DecayModel model{Grid(80, 0.05)};
  std::vector<double> truth;
  for (double t : model.t) truth.push_back(5.0 * std::exp(-t / 1.5));
  const std::vector<FitParameter> params = {{"A", "A", "", 0.0, 100.0, 5.0},
                                            {"tau", "tau", "s", 0.01, 100.0, 1.0}};
  const JetPredictor<DecayModel> predictor(model, {1.0, 1.0}, {0, 1}, {0});
  const FitResult r = FitChannels(
      predictor, params, std::vector{Noisy(truth, 0.05, 5)},
      std::vector<std::vector<double>>{{0.01, 0.011}, {90.0, 0.02}, {3.0, 3.0}}, {}, FitOptions{});
  EXPECT_NEAR(r.estimates[0].value, 5.0, 0.1);
  EXPECT_NEAR(r.estimates[1].value, 1.5, 0.05);
  EXPECT_GE(r.starts_solved, 2);
  EXPECT_EQ(r.starts_scored, 3);
}

TEST(ChannelFitTest, ParsesLosses) {
  EXPECT_EQ(ParseLossKind("huber"), LossKind::kHuber);
  EXPECT_EQ(ParseLossKind("cauchy"), LossKind::kCauchy);
  EXPECT_EQ(ParseLossKind("none"), LossKind::kNone);
  EXPECT_THROW(ParseLossKind("l1"), InputError);
}

}  // namespace
}  // namespace hotlap::ident
