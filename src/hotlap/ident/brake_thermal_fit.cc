#include "hotlap/ident/brake_thermal_fit.h"
#include "hotlap/common/special_values.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>

#include <fmt/format.h>

#include <Eigen/Dense>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/ident/bounded_least_squares.h"
#include "hotlap/ident/jet_predictor.h"
#include "hotlap/sim/synth_sensor.h"

namespace hotlap::ident {

namespace {

// Every parameter of the brake model over a log, in fit order.
enum Index : int { kGamma, kXi, kDisc = 2, kCalliper = 8, kDisc0 = 14, kCalliper0, kCount };
enum Channel : int { kDiscTemp, kCalliperTemp };

// The entries of P = L L' in the order of L's: 11, 21, 22, 31, 32, 33.
constexpr std::array<const char*, 6> kPNames = {"P11", "P21", "P22", "P31", "P32", "P33"};
constexpr std::array<bool, 6> kDiagonal = {true, false, true, false, false, true};
// Where the fitted L has a diagonal entry below this fraction of its scale, the P-space statistics
// are taken at L with that entry raised to it (see ReportInP).
constexpr double kMinDiagonal = 1e-3;

template <Scalar T>
void SetCholesky(brake::ConvectionPolynomial<T>& l, std::span<const T> x) {
  l.l11 = x[0];
  l.l21 = x[1];
  l.l22 = x[2];
  l.l31 = x[3];
  l.l32 = x[4];
  l.l33 = x[5];
}

class BrakeLogModel {
 public:
  BrakeLogModel(const brake::BrakeFile& brake, const sim::CornerSamples& samples, double max_step,
                double lag)
      : brake_(brake), samples_(samples), max_step_(max_step), lag_(lag) {}

  size_t num_samples() const { return samples_.time.size(); }
  int num_channels() const { return 2; }

  template <Scalar T, class Emit>
  void Run(std::span<const T> x, Emit&& emit) const {
    brake::BrakeThermalParams<T> p = brake_.params.Cast<T>();
    p.heat_partition = x[kGamma];
    p.mass_participation = x[kXi];
    SetCholesky(p.disc_convection, x.subspan(kDisc, 6));
    SetCholesky(p.calliper_convection, x.subspan(kCalliper, 6));
    sim::FirstOrderLag<T> disc_sensor(lag_), calliper_sensor(lag_);
    const brake::BrakeState<T> start{x[kDisc0], x[kCalliper0]};
    sim::IntegrateBrake<T>(p, samples_, start, max_step_,
                           [&](size_t k, const brake::BrakeState<T>& s) {
                             const double t = samples_.time[k];
                             emit(kDiscTemp, k, disc_sensor.Next(t, s.disc_temp));
                             emit(kCalliperTemp, k, calliper_sensor.Next(t, s.calliper_temp));
                           });
  }

 private:
  const brake::BrakeFile& brake_;
  sim::CornerSamples samples_;
  double max_step_;
  double lag_;
};

// The same model with the convection given by the entries of P (11, 21, 22, 31, 32, 33) instead
// of L: L = chol(P) inside, on the scalar, so the derivatives with respect to P are exact where
// P is positive definite (elsewhere the prediction is NaN).
class BrakeLogModelP {
 public:
  explicit BrakeLogModelP(const BrakeLogModel& model) : model_(model) {}
  size_t num_samples() const { return model_.num_samples(); }
  int num_channels() const { return 2; }

  template <Scalar T, class Emit>
  void Run(std::span<const T> x, Emit&& emit) const {
    std::vector<T> l(x.begin(), x.end());
    for (int base : {kDisc, kCalliper}) Cholesky<T>(x.subspan(base, 6), &l[base]);
    model_.Run<T>(l, emit);
  }

  // P's entries (p11, p21, p22, p31, p32, p33) to its lower-triangular Cholesky factor.
  template <Scalar T>
  static void Cholesky(std::span<const T> p, T* l) {
    using std::sqrt;
    l[0] = sqrt(p[0]);
    l[1] = p[1] / l[0];
    l[2] = sqrt(p[2] - l[1] * l[1]);
    l[3] = p[3] / l[0];
    l[4] = (p[4] - l[3] * l[1]) / l[2];
    l[5] = sqrt(p[5] - l[3] * l[3] - l[4] * l[4]);
  }

 private:
  const BrakeLogModel& model_;
};

FitParameter BrakeParameter(int index, const brake::BrakeThermalParams<double>& car) {
  if (index == kDisc0) return InitialTemperatureParameter("initial_disc_temp_C", "T_disc(0)");
  if (index == kCalliper0) {
    return InitialTemperatureParameter("initial_calliper_temp_C", "T_calliper(0)");
  }
  const brake::BrakeThermalField& f = *BrakeFitFields()[index];
  return FitParameterOf(f.Path(), *f.fit, f.Of(car));
}

std::vector<double> Cumulative(std::span<const double> time, const std::vector<double>& f) {
  std::vector<double> out(f.size(), 0.0);
  for (size_t k = 1; k < f.size(); ++k) {
    out[k] = out[k - 1] + 0.5 * (f[k] + f[k - 1]) * (time[k] - time[k - 1]);
  }
  return out;
}

// P (symmetric, from its lower triangle 11, 21, 22, 31, 32, 33) projected onto the positive
// semi-definite matrices (eigenvalues clipped at a small positive floor), then factored P = L L'.
std::array<double, 6> CholeskyOfProjected(const Eigen::VectorXd& p6) {
  Eigen::Matrix3d p;
  p << p6(0), p6(1), p6(3), p6(1), p6(2), p6(4), p6(3), p6(4), p6(5);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(p);
  const double floor = 1e-3 * std::max(eig.eigenvalues().maxCoeff(), 1e-3);
  const Eigen::Vector3d clipped = eig.eigenvalues().cwiseMax(floor);
  const Eigen::Matrix3d psd =
      eig.eigenvectors() * clipped.asDiagonal() * eig.eigenvectors().transpose();
  const Eigen::Matrix3d l = psd.llt().matrixL();
  return {l(0, 0), l(1, 0), l(1, 1), l(2, 0), l(2, 1), l(2, 2)};
}

// The equation-error guess: both heat balances (000:24-25) integrated from the first sample are
// linear in gamma, xi and the entries of P_disc and P_calliper once the measured (smoothed)
// temperatures stand in for the states.
std::optional<std::vector<double>> EquationErrorGuess(const brake::BrakeFile& brake,
                                                      const BrakeCornerData& d) {
  if (!d.disc.usable || !d.calliper.usable) return std::nullopt;
  const std::span<const double> time = d.samples.time;
  const size_t n = time.size();
  const brake::BrakeThermalParams<double>& b = brake.params;
  const std::vector<double> td = SmoothedForGuess(d.disc.values);
  const std::vector<double> tk = SmoothedForGuess(d.calliper.values);
  const brake::BrakeConstants<double> k = brake::CalcBrakeConstants(b);
  std::vector<double> q1(n), q2(n), q3(n), q5(n);
  std::array<std::vector<double>, 6> zd, zk;  // c_ij z_i z_j (T - T0) per P entry
  for (auto* v : {&zd, &zk}) {
    for (auto& x : *v) x.resize(n);
  }
  constexpr std::array<std::array<int, 2>, 6> kIj = {
      {{0, 0}, {1, 0}, {1, 1}, {2, 0}, {2, 1}, {2, 2}}};
  for (size_t i = 0; i < n; ++i) {
    const brake::BrakeInput<double> in = d.samples.BrakeInputAt<double>(i, 0.0);
    const double t0 = in.cooling_air_temp, t04 = t0 * t0 * t0 * t0;
    q1[i] = brake::CalcBrakePower(in.speed, in.fx);
    q2[i] = k.pad_conductance * (td[i] - tk[i]);
    q3[i] = k.disc_radiation * (td[i] * td[i] * td[i] * td[i] - t04);
    q5[i] = k.calliper_radiation * (tk[i] * tk[i] * tk[i] * tk[i] - t04);
    const double z2 = std::abs(in.speed) / 100.0;
    const std::array<double, 3> z_d = {1.0, z2, (td[i] - kZeroCelsius) / 1000.0};
    const std::array<double, 3> z_k = {1.0, z2, (tk[i] - kZeroCelsius) / 1000.0};
    for (int e = 0; e < 6; ++e) {
      const auto [a, c] = kIj[e];
      const double mult = a == c ? 1.0 : 2.0;
      zd[e][i] = mult * z_d[a] * z_d[c] * (td[i] - t0);
      zk[e][i] = mult * z_k[a] * z_k[c] * (tk[i] - t0);
    }
  }
  const auto i1 = Cumulative(time, q1), i2 = Cumulative(time, q2), i3 = Cumulative(time, q3),
             i5 = Cumulative(time, q5);
  const double cd = b.disc_mass * b.disc_heat_capacity;  // whole disc; xi is fitted
  const double ck = b.calliper_mass * b.calliper_heat_capacity;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(2 * n, 14);
  Eigen::VectorXd rhs(2 * n);
  std::array<std::vector<double>, 6> izd, izk;
  for (int e = 0; e < 6; ++e) {
    izd[e] = Cumulative(time, zd[e]);
    izk[e] = Cumulative(time, zk[e]);
  }
  // Rows in kelvin of a tenth of the disc and of the calliper.
  for (size_t i = 0; i < n; ++i) {
    const double sd = 1.0 / (0.1 * cd), sk = 1.0 / ck;
    a(i, kGamma) = i1[i] * sd;
    a(i, kXi) = -cd * (td[i] - td[0]) * sd;
    for (int e = 0; e < 6; ++e) a(i, kDisc + e) = -izd[e][i] * sd;
    rhs(i) = (i2[i] + i3[i]) * sd;
    a(n + i, kGamma) = -i1[i] * sk;
    for (int e = 0; e < 6; ++e) a(n + i, kCalliper + e) = -izk[e][i] * sk;
    rhs(n + i) = (ck * (tk[i] - tk[0]) - i1[i] - i2[i] + i5[i]) * sk;
  }
  Eigen::VectorXd lower(14), upper(14), start(14);
  lower(kGamma) = 0.0;
  upper(kGamma) = 1.0;
  start(kGamma) = b.heat_partition;
  lower(kXi) = 0.005;
  upper(kXi) = 1.0;
  start(kXi) = b.mass_participation;
  for (int base : {kDisc, kCalliper}) {
    for (int e = 0; e < 6; ++e) {
      const bool diag = kIj[e][0] == kIj[e][1];
      lower(base + e) = diag ? 0.0 : -1e4;
      upper(base + e) = 1e4;
      start(base + e) = diag ? 1.0 : 0.0;
    }
  }
  const Eigen::VectorXd x = SolveBoundedLeastSquares(a, rhs, lower, upper, start);
  std::vector<double> out = {x(kGamma), x(kXi)};
  for (int base : {kDisc, kCalliper}) {
    const std::array<double, 6> l = CholeskyOfProjected(x.segment(base, 6));
    out.insert(out.end(), l.begin(), l.end());
  }
  return out;
}

// The entries 11, 21, 22, 31, 32, 33 of P = L L' from L's (same order).
std::array<double, 6> PEntries(const double* l) {
  return {l[0] * l[0],
          l[1] * l[0],
          l[1] * l[1] + l[2] * l[2],
          l[3] * l[0],
          l[3] * l[1] + l[4] * l[2],
          l[3] * l[3] + l[4] * l[4] + l[5] * l[5]};
}

// The fit, solved for L, reported for the entries of P (the paper's twelve parameters): the model
// is linear in them, so a valley of equally good fits is straight in P and its linearised
// intervals hold, where in L it curves and they do not. The statistics (noise levels, Ceres
// covariance, undetermined directions) are computed again at the solution in P coordinates
// (FitOptions::solve = false). Where a diagonal entry of L sits at 0 (P on the edge of the
// positive semi-definite matrices) the map L -> P is singular and the covariance would be
// conditioned on the edge; the entry is raised to kMinDiagonal of its scale first (P moves by
// a millionth of a scale squared), so the covariance is the unconstrained one.
FitResult ReportInP(const BrakeLogModel& model, const std::vector<double>& all,
                    const std::vector<int>& free, const FitResult& lfit,
                    std::span<const MeasuredChannel> channels, std::span<const double> time,
                    const FitOptions& options) {
  std::vector<double> p_all = all;
  std::vector<FitParameter> params = lfit.parameters;
  for (int base : {kDisc, kCalliper}) {
    // The raised diagonal must also survive the way back: P's Cholesky factor subtracts the
    // squares of the off-diagonal entries, and a diagonal entry a million times smaller than
    // its row's (an undetermined convection, e.g. a dead calliper sensor's) rounds away there
    // (a zero pivot, then NaN). Raised tenfold until L -> P -> L gives L back.
    double l[6];
    std::array<double, 6> p{};
    for (double raise = kMinDiagonal; raise <= 1.0; raise *= 10.0) {
      for (int e = 0; e < 6; ++e) {
        l[e] = all[base + e];
        if (kDiagonal[e]) l[e] = std::max(l[e], raise * lfit.parameters[base + e].scale);
      }
      p = PEntries(l);
      double back[6];
      BrakeLogModelP::Cholesky<double>(std::span<const double>(p.data(), 6), back);
      bool same = true;
      for (int e = 0; e < 6; ++e) {
        same =
            same && std::isfinite(back[e]) &&
            std::abs(back[e] - l[e]) <= 1e-6 * (std::abs(l[e]) + lfit.parameters[base + e].scale);
      }
      if (same) break;
    }
    for (int e = 0; e < 6; ++e) {
      p_all[base + e] = p[e];
      params[base + e] = {ConvectionMatrixKeys()[base - kDisc + e],
                          fmt::format("{} {}", base == kDisc ? "disc" : "cal", kPNames[e]),
                          "W/K",
                          kDiagonal[e] ? 0.0 : -kInf,
                          kInf,
                          std::max(std::abs(p[e]), 0.1)};
    }
  }
  std::vector<double> start;
  for (int i : free) start.push_back(p_all[i]);
  const BrakeLogModelP model_p(model);
  const JetPredictor<BrakeLogModelP> predictor(model_p, p_all, free, {kDiscTemp, kCalliperTemp});
  FitOptions report = options;
  report.solve = false;
  const std::vector<std::vector<double>> starts = {start};
  FitResult out = FitChannels(predictor, params, channels, starts, time, report);
  // Where the solution came from, and what the solver said, stay those of the L fit.
  for (size_t i = 0; i < free.size(); ++i) {
    if (free[i] >= kDisc && free[i] < kDisc0) {
      const int base = free[i] < kCalliper ? kDisc : kCalliper;
      double l0[6];
      for (int e = 0; e < 6; ++e) l0[e] = lfit.estimates[base + e].start;
      out.estimates[i].start = PEntries(l0)[free[i] - base];
    } else {
      out.estimates[i].start = lfit.estimates[i].start;
    }
  }
  out.converged = lfit.converged;
  out.iterations = lfit.iterations;
  out.starts_scored = lfit.starts_scored;
  out.starts_solved = lfit.starts_solved;
  for (const std::string& w : lfit.warnings) {
    if (w.find("solver stopped") != std::string::npos) out.warnings.push_back(w);
  }
  return out;
}

}  // namespace

std::array<double, 6> ConvectionMatrixEntries(const brake::ConvectionPolynomial<double>& l) {
  const double entries[6] = {l.l11, l.l21, l.l22, l.l31, l.l32, l.l33};
  return PEntries(entries);
}

const std::vector<const brake::BrakeThermalField*>& BrakeFitFields() {
  static const std::vector<const brake::BrakeThermalField*> fields =
      brake::FittedBrakeThermalFields();
  return fields;
}

const std::vector<std::string>& BrakeParameterKeys() {
  static const std::vector<std::string> keys = [] {
    std::vector<std::string> k;
    for (const brake::BrakeThermalField* f : BrakeFitFields()) k.push_back(f->Path());
    return k;
  }();
  return keys;
}

const std::vector<std::string>& ConvectionMatrixKeys() {
  static const std::vector<std::string> keys = [] {
    std::vector<std::string> k;
    for (const char* part : {"disc", "calliper"}) {
      for (const char* e : kPNames) k.push_back(fmt::format("{}_convection_{}_W_per_K", part, e));
    }
    return k;
  }();
  return keys;
}

BrakeFitResult FitBrakeCorner(const brake::BrakeFile& any_brake, const BrakeCornerData& d,
                              const LogFitOptions& options) {
  // The fit identifies the paper's lumped disc (docs/fitting.md): a bulk disc is fitted as it.
  brake::BrakeFile brake = any_brake;
  brake.params.disc_model = brake::DiscModel::kLumped;
  const std::span<const double> time = d.samples.time;
  if (time.empty()) throw InputError("the log has no samples");
  BrakeFitResult r;
  r.params = brake.params;
  const BrakeLogModel model(brake, d.samples, options.max_step_s, options.sensor_lag_s);
  const brake::BrakeThermalParams<double>& car = brake.params;
  std::vector<double> all(kCount);
  for (int i = 0; i < kDisc0; ++i) all[i] = BrakeFitFields()[i]->Of(car);
  all[kDisc0] = StartingTemperature(d.disc, time, options.initial_state, d.fallback_disc_temp);
  all[kCalliper0] =
      StartingTemperature(d.calliper, time, options.initial_state, d.fallback_calliper_temp);
  for (const LoggedChannel* ch : {&d.disc, &d.calliper}) {
    if (const std::string s = DescribeChannelProblems(*ch); !s.empty()) r.warnings.push_back(s);
  }
  std::vector<int> free;
  for (int i = 0; i < kDisc0; ++i) free.push_back(i);
  if (options.initial_state == InitialStateMode::kFitted) {
    free.push_back(kDisc0);
    free.push_back(kCalliper0);
  }
  if (d.disc.usable || d.calliper.usable) {
    std::vector<FitParameter> params;
    for (int i : free) params.push_back(BrakeParameter(i, car));
    const std::vector<MeasuredChannel> channels = {TemperatureChannel(d.disc, d.weights),
                                                   TemperatureChannel(d.calliper, d.weights)};
    std::vector<std::vector<double>> starts;
    const auto with_states = [&](std::vector<double> s) {
      for (size_t i = kDisc0; i < free.size(); ++i) s.push_back(all[free[i]]);
      return s;
    };
    starts.push_back(with_states(std::vector<double>(all.begin(), all.begin() + kDisc0)));
    if (auto guess = EquationErrorGuess(brake, d)) starts.push_back(with_states(*guess));
    std::mt19937_64 rng(options.seed);
    for (int i = 0; i < options.random_starts; ++i) {
      std::vector<double> s = {0.5 + 0.5 * static_cast<double>(rng() >> 11) * 0x1.0p-53,
                               LogUniform(rng, 0.02, 0.5)};
      // Scaled entries; the off-diagonal ones also flip sign half the time, since a coupling of
      // the other sign is a separate basin that scaling alone never reaches.
      for (int j = kDisc; j < kDisc0; ++j) {
        const int e = (j - kDisc) % 6;  // l11, l21, l22, l31, l32, l33
        const bool off_diagonal = e == 1 || e == 3 || e == 4;
        const double sign = off_diagonal && (rng() & 1) ? -1.0 : 1.0;
        s.push_back(sign * all[j] * LogUniform(rng, 0.3, 3.0));
      }
      starts.push_back(with_states(s));
    }
    const JetPredictor<BrakeLogModel> predictor(model, all, free, {kDiscTemp, kCalliperTemp});
    r.cholesky_fit = FitChannels(predictor, params, channels, starts, time, options.solver);
    for (size_t i = 0; i < free.size(); ++i) all[free[i]] = r.cholesky_fit->estimates[i].value;
    r.fit = ReportInP(model, all, free, *r.cholesky_fit, channels, time, options.solver);
    AddLagWarnings(*r.cholesky_fit, options.sensor_lag_s, &r.warnings);
    AddMisfitWarnings(*r.cholesky_fit, &r.warnings);
  } else {
    r.warnings.push_back(
        "no usable disc or calliper temperature: the brake parameters are kept from the car file");
  }
  for (int i = 0; i < kDisc0; ++i) BrakeFitFields()[i]->Of(r.params) = all[i];
  r.disc_model.resize(time.size());
  r.calliper_model.resize(time.size());
  model.Run<double>(all, [&](int c, size_t k, double v) {
    (c == kDiscTemp ? r.disc_model : r.calliper_model)[k] = v;
  });
  return r;
}

}  // namespace hotlap::ident
