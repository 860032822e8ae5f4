#include "hotlap/ident/mf_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string_view>
#include <utility>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/common/median.h"
#include "hotlap/common/units.h"
#include "hotlap/ident/multi_start_solve.h"
#include "hotlap/ident/rig_fit_common.h"
#include "hotlap/tyre/magic_formula.h"

namespace hotlap::ident {

namespace {

using tyre::MagicFormulaParams;

// The coefficients this fit can free, by `.tir` name.
#define HOTLAP_MF_FITTABLE(X)                                                                     \
  X(PCY1)                                                                                         \
  X(PDY1)                                                                                         \
  X(PDY2) X(PDY3) X(PEY1) X(PEY2) X(PEY3) X(PKY1) X(PKY2) X(PKY4) X(PKY6) X(PKY7) X(PHY1) X(PHY2) \
      X(PVY1) X(PVY2) X(PVY3) X(PVY4) X(PCX1) X(PDX1) X(PDX2) X(PDX3) X(PEX1) X(PEX2) X(PEX3)     \
          X(PEX4) X(PKX1) X(PKX2) X(PKX3) X(PHX1) X(PHX2) X(PVX1) X(PVX2)

enum class Coef {
#define HOTLAP_ENUM(name) name,
  HOTLAP_MF_FITTABLE(HOTLAP_ENUM)
#undef HOTLAP_ENUM
};

std::string_view CoefName(Coef c) {
  switch (c) {
#define HOTLAP_NAME(name) \
  case Coef::name:        \
    return #name;
    HOTLAP_MF_FITTABLE(HOTLAP_NAME)
#undef HOTLAP_NAME
  }
  return "?";
}

template <Scalar T>
T& Field(MagicFormulaParams<T>& p, Coef c) {
  switch (c) {
#define HOTLAP_FIELD(name) \
  case Coef::name:         \
    return p.name;
    HOTLAP_MF_FITTABLE(HOTLAP_FIELD)
#undef HOTLAP_FIELD
  }
  throw std::logic_error("mf_fit: unknown coefficient");
}

// A free coefficient and its bounds.
struct Free {
  Coef coef;
  double lower;
  double upper;
};

enum class Channel { kLateral, kLongitudinal };

bool IsLateral(const RigSample& s) { return std::abs(s.slip_ratio) <= 1e-6; }
bool IsLongitudinal(const RigSample& s) { return s.fx && std::abs(s.slip_angle) <= 1e-6; }
double Measured(const RigSample& s, Channel c) { return c == Channel::kLateral ? s.fy : *s.fx; }
double Slip(const RigSample& s, Channel c) {
  return c == Channel::kLateral ? s.slip_angle : s.slip_ratio;
}

// Load groups: sorted loads no more than 2% apart.
internal::ValueGroups GroupLoads(const std::vector<const RigSample*>& samples) {
  std::vector<double> loads;
  for (const RigSample* s : samples) loads.push_back(s->fz);
  return internal::GroupValues(loads, internal::kLoadGroupTolerance,
                               internal::GroupTolerance::kRelative);
}

// Per load group of zero-camber samples: slope of F against slip at zero slip (secant through
// the two smallest slips, extrapolated to zero) and the peak |F|.
struct CurveEstimate {
  double fz = 0.0;
  double slope = 0.0;  // dF/dslip at 0, N (per rad or per unit slip ratio)
  double peak = 0.0;
};

std::vector<CurveEstimate> EstimateCurves(const std::vector<const RigSample*>& samples,
                                          Channel channel) {
  std::vector<const RigSample*> flat;
  for (const RigSample* s : samples) {
    if (std::abs(s->camber) <= 1e-4) flat.push_back(s);
  }
  const internal::ValueGroups groups = GroupLoads(flat);
  std::vector<CurveEstimate> out;
  for (size_t g = 0; g < groups.mean.size(); ++g) {
    std::vector<double> slip, force;
    double peak = 0.0;
    for (size_t i = 0; i < flat.size(); ++i) {
      if (groups.index[i] != static_cast<int>(g)) continue;
      slip.push_back(Slip(*flat[i], channel));
      force.push_back(Measured(*flat[i], channel));
      peak = std::max(peak, std::abs(force.back()));
    }
    if (!(peak > 0.0)) continue;
    const double slope = internal::ZeroSlipSlope(slip, force);
    if (slope == 0.0 || !std::isfinite(slope)) continue;
    out.push_back({groups.mean[g], slope, peak});
  }
  return out;
}

// The sign of dF/dslip from all the data: the least-squares slope of F on slip over every load
// group together, each group's mean slip and force removed (its offset), zero-camber samples
// only where there are any. `fallback` where the data give no slope.
double PooledSlopeSign(const std::vector<const RigSample*>& samples, Channel channel,
                       double fallback) {
  std::vector<const RigSample*> flat;
  for (const RigSample* s : samples) {
    if (std::abs(s->camber) <= 1e-4) flat.push_back(s);
  }
  if (flat.empty()) flat = samples;
  const internal::ValueGroups groups = GroupLoads(flat);
  const size_t n = groups.mean.size();
  std::vector<double> mean_x(n, 0.0), mean_y(n, 0.0), count(n, 0.0);
  for (size_t i = 0; i < flat.size(); ++i) {
    const size_t g = static_cast<size_t>(groups.index[i]);
    mean_x[g] += Slip(*flat[i], channel);
    mean_y[g] += Measured(*flat[i], channel);
    count[g] += 1.0;
  }
  double sxy = 0.0, sxx = 0.0;
  for (size_t i = 0; i < flat.size(); ++i) {
    const size_t g = static_cast<size_t>(groups.index[i]);
    const double dx = Slip(*flat[i], channel) - mean_x[g] / count[g];
    sxy += dx * (Measured(*flat[i], channel) - mean_y[g] / count[g]);
    sxx += dx * dx;
  }
  if (!(sxx > 0.0) || sxy == 0.0 || !std::isfinite(sxy)) return fallback;
  return sxy < 0.0 ? -1.0 : 1.0;
}

// Starting lateral coefficients from the curves: friction line in dfz, cornering stiffness law
// K = PKY1 Fz0 sin(2 atan(Fz / (PKY2 Fz0))), i.e. Fz/K linear in Fz^2.
// Where the non-estimated coefficients start.
enum class Start {
  kGeneric,   // shape 1.3 / 1.65, curvatures, shifts and camber terms 0, PKY4 = 2
  kFromBase,  // as the base file has them: only friction and stiffness come from the data
};

void GuessLateral(const std::vector<CurveEstimate>& curves, double sign, Start start,
                  MagicFormulaParams<double>& p) {
  if (curves.empty()) return;
  const double fz0 = p.FNOMIN * p.LFZO;
  std::vector<double> dfz, mu, fz2, fz_over_k;
  for (const CurveEstimate& c : curves) {
    dfz.push_back((c.fz - fz0) / fz0);
    mu.push_back(c.peak / c.fz);
    fz2.push_back(c.fz * c.fz);
    fz_over_k.push_back(c.fz / std::abs(c.slope));
  }
  const auto [mu0, mu1] = internal::LineFit(dfz, mu);
  p.PDY1 = std::clamp(mu0, 0.2, 3.5);
  p.PDY2 = curves.size() >= 2 ? std::clamp(mu1 / 1.0, -0.9, 0.9) : p.PDY2;
  if (start == Start::kGeneric) p.PKY4 = 2.0;  // sign: PooledSlopeSign, ISO negative
  const auto [a, b] = internal::LineFit(fz2, fz_over_k);
  if (start == Start::kGeneric && curves.size() >= 2 && a > 0.0 && b > 0.0) {
    const double pky1 = 1.0 / (2.0 * fz0 * std::sqrt(a * b));
    p.PKY1 = sign * std::clamp(pky1, 1.0, 250.0);
    p.PKY2 = std::clamp(2.0 * pky1 * a, 0.1, 9.0);
  } else {
    // One load, a stiffness still rising linearly, or a base's load law: keep PKY2 and PKY4,
    // scale PKY1 to the slopes.
    double k = 0.0, shape = 0.0;
    for (const CurveEstimate& c : curves) {
      const double x = c.fz / (std::max(p.PKY2, 0.1) * fz0);
      k += std::abs(c.slope);
      shape += fz0 * std::sin(p.PKY4 * std::atan(x));
    }
    if (shape > 0.0) p.PKY1 = sign * std::clamp(k / shape, 1.0, 250.0);
  }
  if (start == Start::kFromBase) return;
  p.PCY1 = 1.3;
  p.PEY1 = 0.0;
  p.PEY2 = 0.0;
  p.PEY3 = 0.0;
  for (double* shift :
       {&p.PHY1, &p.PHY2, &p.PVY1, &p.PVY2, &p.PDY3, &p.PKY6, &p.PKY7, &p.PVY3, &p.PVY4}) {
    *shift = 0.0;
  }
}

// Starting longitudinal coefficients: friction line in dfz, K/Fz = PKX1 + PKX2 dfz.
void GuessLongitudinal(const std::vector<CurveEstimate>& curves, Start start,
                       MagicFormulaParams<double>& p) {
  if (curves.empty()) return;
  const double fz0 = p.FNOMIN * p.LFZO;
  std::vector<double> dfz, mu, k;
  for (const CurveEstimate& c : curves) {
    dfz.push_back((c.fz - fz0) / fz0);
    mu.push_back(c.peak / c.fz);
    k.push_back(c.slope / c.fz);
  }
  const auto [mu0, mu1] = internal::LineFit(dfz, mu);
  const auto [k0, k1] = internal::LineFit(dfz, k);
  p.PDX1 = std::clamp(mu0, 0.2, 3.5);
  p.PDX2 = curves.size() >= 2 ? std::clamp(mu1, -0.9, 0.9) : p.PDX2;
  p.PKX1 = std::clamp(k0, 1.0, 250.0);
  p.PKX2 = curves.size() >= 2 ? std::clamp(k1, -9.0, 9.0) : p.PKX2;
  if (start == Start::kFromBase) return;
  p.PKX3 = 0.0;
  p.PCX1 = 1.65;
  for (double* c :
       {&p.PEX1, &p.PEX2, &p.PEX3, &p.PEX4, &p.PHX1, &p.PHX2, &p.PVX1, &p.PVX2, &p.PDX3}) {
    *c = 0.0;
  }
}

// Largest value of PKY4 atan(Fz / (PKY2 Fz0)) the bounds allow for Fz up to 2 FNOMIN.
constexpr double kMaxStiffnessAngle = kPi - 0.05;
constexpr double kPky4Max = 2.9;

// Lower bound of PKY2 that keeps PKY4 atan(2 FNOMIN / (PKY2 FNOMIN LFZO)) <= kMaxStiffnessAngle
// for every PKY4 up to `pky4_max` (atan < pi/2, so none is needed when pky4_max <= 2 or so).
double Pky2Lower(double pky4_max, double lfzo) {
  const double atan_max = kMaxStiffnessAngle / pky4_max;
  if (atan_max >= 0.5 * kPi) return 0.05;
  return std::clamp(2.0 / (lfzo * std::tan(atan_max)), 0.05, 9.0);
}

// The free coefficients of one channel, by what the samples can identify; `p` gives PKY4 and
// LFZO for PKY2's bound where PKY4 is not free.
std::vector<Free> FreeSet(Channel channel, size_t loads, bool camber, bool both_signs,
                          double stiffness_sign, const MagicFormulaParams<double>& p) {
  std::vector<Free> f;
  if (channel == Channel::kLateral) {
    const double lo = stiffness_sign < 0.0 ? -300.0 : 0.5;
    const double hi = stiffness_sign < 0.0 ? -0.5 : 300.0;
    f = {{Coef::PCY1, 1.0, 2.5}, {Coef::PDY1, 0.05, 5.0}, {Coef::PEY1, -20.0, 1.0},
         {Coef::PKY1, lo, hi},   {Coef::PHY1, -0.1, 0.1}, {Coef::PVY1, -0.5, 0.5}};
    if (loads >= 2) {
      f.insert(f.end(), {{Coef::PDY2, -1.0, 1.0},
                         {Coef::PEY2, -20.0, 20.0},
                         {Coef::PKY2, Pky2Lower(loads >= 3 ? kPky4Max : p.PKY4, p.LFZO), 10.0},
                         {Coef::PHY2, -0.1, 0.1},
                         {Coef::PVY2, -0.5, 0.5}});
    }
    if (loads >= 3) f.push_back({Coef::PKY4, 1.0, kPky4Max});
    if (both_signs) f.push_back({Coef::PEY3, -1.0, 1.0});
    if (camber) {
      f.insert(f.end(),
               {{Coef::PDY3, -50.0, 50.0}, {Coef::PKY6, -10.0, 10.0}, {Coef::PVY3, -5.0, 5.0}});
      if (loads >= 2) f.insert(f.end(), {{Coef::PKY7, -10.0, 10.0}, {Coef::PVY4, -5.0, 5.0}});
    }
  } else {
    f = {{Coef::PCX1, 1.0, 2.5},   {Coef::PDX1, 0.05, 5.0}, {Coef::PEX1, -20.0, 1.0},
         {Coef::PKX1, 0.5, 300.0}, {Coef::PHX1, -0.1, 0.1}, {Coef::PVX1, -0.5, 0.5}};
    if (loads >= 2) {
      f.insert(f.end(), {{Coef::PDX2, -1.0, 1.0},
                         {Coef::PEX2, -20.0, 20.0},
                         {Coef::PKX2, -10.0, 10.0},
                         {Coef::PHX2, -0.1, 0.1},
                         {Coef::PVX2, -0.5, 0.5}});
    }
    if (loads >= 3) f.insert(f.end(), {{Coef::PEX3, -20.0, 20.0}, {Coef::PKX3, -5.0, 5.0}});
    if (both_signs) f.push_back({Coef::PEX4, -1.0, 1.0});
    if (camber) f.push_back({Coef::PDX3, -50.0, 50.0});
  }
  return f;
}

struct Residual {
  const MagicFormulaParams<double>* base;
  const std::vector<Free>* free;
  RigSample sample;
  Channel channel;
  double scale;

  template <typename T>
  bool operator()(T const* const* x, T* r) const {
    MagicFormulaParams<T> p = base->Cast<T>();
    for (size_t i = 0; i < free->size(); ++i) Field(p, (*free)[i].coef) = x[0][i];
    const tyre::TyreForces<T> f =
        tyre::CalcMagicFormula(p, internal::RigOperatingPoint<T>(sample), {});
    r[0] = ((channel == Channel::kLateral ? f.fy : f.fx) - Measured(sample, channel)) / scale;
    return true;
  }
};

struct ChannelFit {
  bool converged = true;
  int iterations = 0;
};

// Fits the channel's free coefficients of `params` (updated in place) to `samples`, from several
// starting curvatures, keeping the lowest cost.
ChannelFit FitChannel(const std::vector<const RigSample*>& samples, Channel channel,
                      const std::vector<Free>& free, int max_iterations,
                      MagicFormulaParams<double>& params) {
  double scale = 0.0;
  for (const RigSample* s : samples) scale = std::max(scale, std::abs(Measured(*s, channel)));
  if (!(scale > 0.0)) scale = 1.0;
  const int n = static_cast<int>(free.size());
  const Coef curvature = channel == Channel::kLateral ? Coef::PEY1 : Coef::PEX1;
  std::vector<double> x0;
  std::vector<internal::ParameterBounds> bounds;
  internal::MultiStartOptions solve;
  solve.max_iterations = max_iterations;
  for (int i = 0; i < n; ++i) {
    bounds.push_back({free[i].lower, free[i].upper});
    x0.push_back(internal::StartInsideBounds(Field(params, free[i].coef), bounds.back()));
    if (free[i].coef == curvature) solve.start_indices.push_back(i);
  }
  const MagicFormulaParams<double> base = params;
  // The starting curvature as given (the base's, or 0 for a generic start), then others.
  solve.start_values = {Field(params, curvature)};
  for (double e : {0.0, -1.0, 0.5, -3.0}) {
    if (std::find(solve.start_values.begin(), solve.start_values.end(), e) ==
        solve.start_values.end()) {
      solve.start_values.push_back(e);
    }
  }
  const internal::MultiStartResult best = internal::SolveMultiStart(
      x0, bounds,
      [&](ceres::Problem& problem, double* x) {
        for (const RigSample* s : samples) {
          internal::AddDynamicAutoDiffResidual(
              problem, new Residual{&base, &free, *s, channel, scale}, n, 1, x);
        }
      },
      solve);
  for (int i = 0; i < n; ++i) Field(params, free[i].coef) = best.x[i];
  return {best.converged, best.iterations};
}

std::vector<MagicFormulaFitMetrics> Metrics(const MagicFormulaParams<double>& params,
                                            const std::vector<const RigSample*>& samples,
                                            Channel channel) {
  const internal::ValueGroups groups = GroupLoads(samples);
  std::vector<MagicFormulaFitMetrics> rows(groups.mean.size());
  std::vector<double> sum2(rows.size(), 0.0);
  for (size_t i = 0; i < samples.size(); ++i) {
    const RigSample& s = *samples[i];
    const tyre::TyreForces<double> f =
        tyre::CalcMagicFormula(params, internal::RigOperatingPoint<double>(s), {});
    const double model = channel == Channel::kLateral ? f.fy : f.fx;
    const double measured = Measured(s, channel);
    MagicFormulaFitMetrics& m = rows[groups.index[i]];
    sum2[groups.index[i]] += (model - measured) * (model - measured);
    m.peak_N = std::max(m.peak_N, std::abs(measured));
    ++m.samples;
  }
  for (size_t g = 0; g < rows.size(); ++g) {
    rows[g].channel = channel == Channel::kLateral ? "fy" : "fx";
    rows[g].fz_N = groups.mean[g];
    rows[g].rms_N = std::sqrt(sum2[g] / rows[g].samples);
    rows[g].rms_rel_peak = rows[g].peak_N > 0.0 ? rows[g].rms_N / rows[g].peak_N : 0.0;
  }
  return rows;
}

// "NAME = value at its lower/upper bound" for each free coefficient within a millionth of the
// bounds' span of one of them.
void AddAtBounds(const std::vector<Free>& free, MagicFormulaParams<double>& p,
                 std::vector<std::string>& out) {
  for (const Free& f : free) {
    const double value = Field(p, f.coef);
    const double tol = 1e-6 * (f.upper - f.lower);
    if (std::abs(value - f.lower) <= tol || std::abs(value - f.upper) <= tol) {
      const bool lower = std::abs(value - f.lower) <= tol;
      out.push_back(fmt::format("{} = {:.6g} at its {} bound", CoefName(f.coef), value,
                                lower ? "lower" : "upper"));
    }
  }
}

double LargestSlip(const std::vector<const RigSample*>& samples, Channel channel) {
  double largest = 0.0;
  for (const RigSample* s : samples) largest = std::max(largest, std::abs(Slip(*s, channel)));
  return largest;
}

// The plausibility check of the fitted coefficients over the data's slip ranges.
void CheckFit(const std::vector<const RigSample*>& lateral,
              const std::vector<const RigSample*>& longitudinal, MagicFormulaFitResult& result) {
  const double sign = result.plausibility.lateral_sign;
  std::vector<std::string> at_bounds = std::move(result.plausibility.at_bounds);
  result.plausibility =
      CheckMagicFormulaPlausibility(result.params, LargestSlip(lateral, Channel::kLateral),
                                    LargestSlip(longitudinal, Channel::kLongitudinal), sign);
  result.plausibility.at_bounds = std::move(at_bounds);
}

tyre::TyreOperatingPoint<double> CheckPoint(const MagicFormulaParams<double>& p, double fz,
                                            double alpha, double kappa) {
  tyre::TyreOperatingPoint<double> op;
  op.fz = fz;
  op.slip_angle = alpha;
  op.slip_ratio = kappa;
  op.speed = std::max(p.LONGVL, 1.0);
  return op;
}

// Fy (lateral) or Fx at one load and slip.
double CheckForce(const MagicFormulaParams<double>& p, double fz, double slip, Channel channel) {
  const bool lateral = channel == Channel::kLateral;
  const tyre::TyreForces<double> f =
      tyre::CalcMagicFormula(p, CheckPoint(p, fz, lateral ? slip : 0.0, lateral ? 0.0 : slip), {});
  return lateral ? f.fy : f.fx;
}

// One channel to check: which, over which slips, and the sign F must have for positive slip.
struct ChannelCheck {
  Channel channel;
  double slip_max;
  double sign;  // expected sign of F for positive slip
};

// The largest |F|/Fz over +-slip_max (NaN if any force is not finite).
double PeakMu(const MagicFormulaParams<double>& p, double fz, const ChannelCheck& c) {
  double peak = 0.0;
  constexpr int kSteps = 40;
  for (int i = 0; i <= kSteps; ++i) {
    const double slip = c.slip_max * (2.0 * i / kSteps - 1.0);
    const double f = CheckForce(p, fz, slip, c.channel);
    if (!std::isfinite(f)) return std::nan("");
    peak = std::max(peak, std::abs(f) / fz);
  }
  return peak;
}

// The failure at one load, or "" when that load passes.
std::string CheckLoad(const MagicFormulaParams<double>& p, double fz, const ChannelCheck& c,
                      double& peak_mu) {
  const bool lateral = c.channel == Channel::kLateral;
  const char* force = lateral ? "Fy" : "Fx";
  const char* sign = c.sign < 0.0 ? "negative" : "positive";
  const double fz0 = p.FNOMIN * p.LFZO;
  if (lateral && p.PKY2 != 0.0) {
    const double angle = p.PKY4 * std::atan(fz / (p.PKY2 * fz0));
    if (!(angle > 0.0 && angle < kPi)) {
      return fmt::format(
          "PKY4 atan(Fz / (PKY2 Fz0)) = {:.4g} at Fz = {:.0f} N is outside (0, pi): the cornering "
          "stiffness changes sign (PKY4 = {:.4g}, PKY2 = {:.4g})",
          angle, fz, p.PKY4, p.PKY2);
    }
  }
  constexpr double h = 1e-4;
  const double stiffness =
      (CheckForce(p, fz, h, c.channel) - CheckForce(p, fz, -h, c.channel)) / (2.0 * h);
  if (!(stiffness * c.sign > 0.0)) {
    return fmt::format("{} stiffness {:.4g} N/{} at Fz = {:.0f} N is not {} as the data's", force,
                       stiffness, lateral ? "rad" : "unit slip", fz, sign);
  }
  const double small = std::min(lateral ? DegToRad(1.0) : 0.01, c.slip_max);
  const double f = CheckForce(p, fz, small, c.channel);
  if (!(f * c.sign > 0.0)) {
    return fmt::format("{} = {:.4g} N at Fz = {:.0f} N and {} = +{:.3g}{} is not {} as the data's",
                       force, f, fz, lateral ? "alpha" : "kappa",
                       lateral ? small * 180.0 / kPi : small, lateral ? " deg" : "", sign);
  }
  peak_mu = PeakMu(p, fz, c);
  if (!(std::isfinite(peak_mu) && peak_mu > 0.0)) {
    return fmt::format("peak |{}|/Fz = {} at Fz = {:.0f} N is not finite and positive", force,
                       peak_mu, fz);
  }
  return {};
}

}  // namespace

MagicFormulaPlausibility CheckMagicFormulaPlausibility(const MagicFormulaParams<double>& params,
                                                       double slip_angle_max, double slip_ratio_max,
                                                       double lateral_sign) {
  MagicFormulaPlausibility out;
  out.fz_min_N = 0.1 * params.FNOMIN;
  out.fz_max_N = 2.0 * params.FNOMIN;
  out.slip_angle_max_rad = slip_angle_max;
  out.slip_ratio_max = slip_ratio_max;
  out.lateral_sign = lateral_sign;
  std::vector<ChannelCheck> checks;
  if (slip_angle_max > 0.0) checks.push_back({Channel::kLateral, slip_angle_max, lateral_sign});
  if (slip_ratio_max > 0.0) checks.push_back({Channel::kLongitudinal, slip_ratio_max, 1.0});
  out.peak_mu_y_min = std::numeric_limits<double>::infinity();
  constexpr int kLoads = 20;
  for (const ChannelCheck& c : checks) {
    for (int i = 0; i < kLoads; ++i) {
      const double fz = out.fz_min_N + (out.fz_max_N - out.fz_min_N) * i / (kLoads - 1);
      double peak_mu = 0.0;
      const std::string failure = CheckLoad(params, fz, c, peak_mu);
      if (!failure.empty()) {
        out.failures.push_back(failure);
        break;  // the lightest failing load of each channel says why
      }
      if (c.channel == Channel::kLateral) {
        out.peak_mu_y_min = std::min(out.peak_mu_y_min, peak_mu);
        out.peak_mu_y_max = std::max(out.peak_mu_y_max, peak_mu);
      }
    }
  }
  if (!std::isfinite(out.peak_mu_y_min)) out.peak_mu_y_min = 0.0;
  out.passed = out.failures.empty();
  return out;
}

MagicFormulaFitResult FitMagicFormula(std::span<const RigSample> samples,
                                      const MagicFormulaFitOptions& options) {
  internal::CheckRigSamples(samples);
  MagicFormulaFitResult result;
  std::vector<const RigSample*> lateral, longitudinal;
  int combined = 0;
  double t_min = std::numeric_limits<double>::infinity(), t_max = -t_min;
  std::vector<double> loads, speeds;
  for (const RigSample& s : samples) {
    if (IsLateral(s)) lateral.push_back(&s);
    if (IsLongitudinal(s)) longitudinal.push_back(&s);
    if (!IsLateral(s) && !IsLongitudinal(s)) ++combined;
    t_min = std::min(t_min, s.tread_temp);
    t_max = std::max(t_max, s.tread_temp);
    loads.push_back(s.fz);
    speeds.push_back(s.speed);
  }
  if (lateral.empty() && longitudinal.empty()) {
    throw InputError(
        "Magic Formula fit: the data hold no pure-slip curve (rows with slip_ratio 0 for Fy, or "
        "slip_angle 0 with fx measured for Fx)");
  }
  if (t_max - t_min > 3.0) {
    result.warnings.push_back(fmt::format(
        "tread temperatures span {:.1f} K; the Magic Formula has no temperature, so they are "
        "fitted as one tyre (fit `--model unitire` for temperature effects)",
        t_max - t_min));
  }
  if (combined > 0) {
    result.warnings.push_back(
        fmt::format("{} combined-slip samples are not used (pure-slip fit)", combined));
  }

  MagicFormulaParams<double> p;
  const Start start = options.base ? Start::kFromBase : Start::kGeneric;
  if (options.base) {
    p = *options.base;
  } else {
    p = tyre::MagicFormulaDefaults();
    p.FNOMIN = Median(loads);
    p.LONGVL = std::max(Median(speeds), 1.0);
    p.FZMIN = 0.0;
    p.FZMAX = 3.0 * *std::max_element(loads.begin(), loads.end());
  }
  const double fz_max = *std::max_element(loads.begin(), loads.end());
  if (fz_max > p.FZMAX) {
    result.warnings.push_back(fmt::format(
        "loads up to {:.0f} N exceed the base file's FZMAX {:.0f} N; FZMAX raised to cover them",
        fz_max, p.FZMAX));
    p.FZMAX = 1.2 * fz_max;
  }

  const auto fit_channel = [&](const std::vector<const RigSample*>& chosen, Channel channel) {
    if (chosen.empty()) {
      result.warnings.push_back(
          fmt::format("no pure {} samples: the {} coefficients are kept from the base",
                      channel == Channel::kLateral ? "side-slip" : "longitudinal-slip (with fx)",
                      channel == Channel::kLateral ? "lateral" : "longitudinal"));
      return;
    }
    const std::vector<CurveEstimate> curves = EstimateCurves(chosen, channel);
    const double sign = PooledSlopeSign(chosen, channel, channel == Channel::kLateral ? -1.0 : 1.0);
    if (channel == Channel::kLateral) {
      result.plausibility.lateral_sign = sign;
      GuessLateral(curves, sign, start, p);
    } else {
      GuessLongitudinal(curves, start, p);
    }
    bool camber = false, negative = false, positive = false;
    for (const RigSample* s : chosen) {
      camber = camber || std::abs(s->camber) > 1e-4;
      negative = negative || Slip(*s, channel) < 0.0;
      positive = positive || Slip(*s, channel) > 0.0;
    }
    const std::vector<Free> free =
        FreeSet(channel, GroupLoads(chosen).mean.size(), camber, negative && positive, sign, p);
    for (const Free& f : free) result.fitted_coefficients.emplace_back(CoefName(f.coef));
    const ChannelFit fit = FitChannel(chosen, channel, free, options.max_iterations, p);
    AddAtBounds(free, p, result.plausibility.at_bounds);
    result.converged = result.converged && fit.converged;
    result.iterations += fit.iterations;
  };
  result.converged = true;
  // The initial guess is the base with both channels' data estimates (recorded before fitting).
  {
    MagicFormulaParams<double> guess = p;
    GuessLateral(EstimateCurves(lateral, Channel::kLateral),
                 PooledSlopeSign(lateral, Channel::kLateral, -1.0), start, guess);
    GuessLongitudinal(EstimateCurves(longitudinal, Channel::kLongitudinal), start, guess);
    result.initial_guess = guess;
  }
  fit_channel(lateral, Channel::kLateral);
  fit_channel(longitudinal, Channel::kLongitudinal);
  result.params = p;
  CheckFit(lateral, longitudinal, result);
  result.lateral_samples = static_cast<int>(lateral.size());
  result.longitudinal_samples = static_cast<int>(longitudinal.size());
  for (auto [chosen, channel] :
       {std::pair{&lateral, Channel::kLateral}, std::pair{&longitudinal, Channel::kLongitudinal}}) {
    if (chosen->empty()) continue;
    const auto rows = Metrics(p, *chosen, channel);
    result.metrics.insert(result.metrics.end(), rows.begin(), rows.end());
  }
  return result;
}

}  // namespace hotlap::ident
