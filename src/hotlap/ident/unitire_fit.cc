#include "hotlap/ident/unitire_fit.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <string_view>
#include <tuple>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/common/median.h"
#include "hotlap/common/units.h"
#include "hotlap/ident/multi_start_solve.h"
#include "hotlap/ident/rig_fit_common.h"

namespace hotlap::ident {

namespace {

using tyre::kUniTireFieldNames;
using tyre::UniTireParams;

constexpr size_t kFieldCount = kUniTireFieldNames.size();

// Pointers to every field of `p`, in FieldsOf order (kUniTireFieldNames).
template <Scalar T>
std::array<T*, kFieldCount> FieldPointers(UniTireParams<T>& p) {
  return std::apply([](auto&... f) { return std::array<T*, kFieldCount>{&f...}; },
                    UniTireParams<T>::FieldsOf(p));
}

int FieldIndex(std::string_view name) {
  for (size_t i = 0; i < kFieldCount; ++i) {
    if (kUniTireFieldNames[i] == name) return static_cast<int>(i);
  }
  throw std::logic_error("unitire_fit: unknown field " + std::string(name));
}

// A free parameter of the fit: field and bounds.
struct FreeField {
  std::string_view name;
  double lower;
  double upper;
};

using internal::GroupTolerance;
using internal::GroupValues;
using internal::kLoadGroupTolerance;
using internal::ValueGroups;

bool IsFitTemp(double temp, std::span<const double> fit_temps, double tolerance) {
  return std::any_of(fit_temps.begin(), fit_temps.end(),
                     [&](double t) { return std::abs(temp - t) <= tolerance; });
}

// --- Initial guess -------------------------------------------------------------------------------

// One pure-slip curve at one temperature and load: slope at zero slip and peak force.
struct Curve {
  double temp = 0.0;
  double fz = 0.0;
  double stiffness = 0.0;     // -dFy/dx (lateral) or dFx/dx (longitudinal) at x = 0, N
  double moment_slope = 0.0;  // dMz/dx at x = 0, N m (lateral only)
  double peak = 0.0;          // largest |F|, N
};

// Slopes of y(x) and m(x) at x = 0 (ZeroSlipSlope), the force's times `sign`, and the peak |y|.
struct Point {
  double x, y, m;
};

std::optional<Curve> EstimateCurve(const std::vector<Point>& pts, double sign) {
  std::vector<double> x, y, m;
  for (const Point& p : pts) {
    x.push_back(p.x);
    y.push_back(p.y);
    m.push_back(p.m);
  }
  Curve c;
  c.stiffness = sign * internal::ZeroSlipSlope(x, y);
  c.moment_slope = internal::ZeroSlipSlope(x, m);
  for (const Point& p : pts) c.peak = std::max(c.peak, std::abs(p.y));
  if (!(c.stiffness > 0.0) || !(c.peak > 0.0)) return std::nullopt;
  return c;
}

// Pure-slip curves by (temperature group, load group), from the samples at fit temperatures.
std::vector<Curve> PureSlipCurves(std::span<const RigSample> samples,
                                  const UniTireFitOptions& options, bool lateral) {
  std::vector<const RigSample*> chosen;
  for (const RigSample& s : samples) {
    if (!IsFitTemp(s.tread_temp, options.fit_temps, options.temp_tolerance)) continue;
    if (lateral && std::abs(s.slip_ratio) <= 1e-6 && std::abs(s.camber) <= 1e-4) {
      chosen.push_back(&s);
    }
    if (!lateral && s.fx && std::abs(s.slip_angle) <= 1e-6 && std::abs(s.camber) <= 1e-4) {
      chosen.push_back(&s);
    }
  }
  std::vector<double> temps, loads;
  for (const RigSample* s : chosen) {
    temps.push_back(s->tread_temp);
    loads.push_back(s->fz);
  }
  const ValueGroups tg = GroupValues(temps, options.temp_tolerance, GroupTolerance::kAbsolute);
  const ValueGroups lg = GroupValues(loads, kLoadGroupTolerance, GroupTolerance::kRelative);
  std::map<std::pair<int, int>, std::vector<Point>> points;
  for (size_t i = 0; i < chosen.size(); ++i) {
    const RigSample& s = *chosen[i];
    const Point p = lateral ? Point{std::tan(s.slip_angle), s.fy, s.mz}
                            : Point{s.slip_ratio / (1.0 + s.slip_ratio), *s.fx, 0.0};
    if (!lateral && !(1.0 + s.slip_ratio > 0.0)) continue;
    points[{tg.index[i], lg.index[i]}].push_back(p);
  }
  std::vector<Curve> curves;
  for (auto& [key, pts] : points) {
    std::optional<Curve> c = EstimateCurve(pts, lateral ? -1.0 : 1.0);
    if (!c) continue;
    c->temp = tg.mean[key.first];
    c->fz = lg.mean[key.second];
    curves.push_back(*c);
  }
  return curves;
}

// Pooled within-load slope of log(value) against temperature, over loads with >= 2 temperatures:
// the decay b of value ~ exp(-b T) is minus it. Then the value at T_ref for each load.
struct LoadLaw {
  double decay = 0.0;
  std::vector<double> loads;      // N
  std::vector<double> ref_value;  // value at T_ref
};

LoadLaw TemperatureRegression(const std::vector<Curve>& curves, double (*value)(const Curve&),
                              double reference_temp) {
  std::vector<double> loads;
  for (const Curve& c : curves) loads.push_back(c.fz);
  const ValueGroups lg = GroupValues(loads, kLoadGroupTolerance, GroupTolerance::kRelative);
  const size_t n_loads = lg.mean.size();
  std::vector<double> mean_t(n_loads, 0.0), mean_l(n_loads, 0.0);
  std::vector<int> count(n_loads, 0);
  for (size_t i = 0; i < curves.size(); ++i) {
    const int l = lg.index[i];
    mean_t[l] += curves[i].temp;
    mean_l[l] += std::log(value(curves[i]));
    ++count[l];
  }
  for (size_t l = 0; l < n_loads; ++l) {
    mean_t[l] /= count[l];
    mean_l[l] /= count[l];
  }
  double sxy = 0.0, sxx = 0.0;
  for (size_t i = 0; i < curves.size(); ++i) {
    const int l = lg.index[i];
    const double dt = curves[i].temp - mean_t[l];
    sxy += dt * (std::log(value(curves[i])) - mean_l[l]);
    sxx += dt * dt;
  }
  LoadLaw law;
  law.decay = sxx > 0.0 ? -sxy / sxx : 0.0;
  law.loads = lg.mean;
  for (size_t l = 0; l < n_loads; ++l) {
    law.ref_value.push_back(std::exp(mean_l[l] + law.decay * (mean_t[l] - reference_temp)));
  }
  return law;
}

// s11, s12, s13 of K = s11 Fz sech(s12 Fzn^2 + s13 Fzn) through acosh, with s13 >= 0.
std::array<double, 3> SechLoadLaw(const LoadLaw& law, double nominal_load) {
  double max_ratio = 0.0;
  for (size_t l = 0; l < law.loads.size(); ++l) {
    max_ratio = std::max(max_ratio, law.ref_value[l] / law.loads[l]);
  }
  const double s11 = 1.05 * max_ratio;
  // Least squares x_l = s12 u_l^2 + s13 u_l, u = Fzn.
  double a11 = 0.0, a12 = 0.0, a22 = 0.0, b1 = 0.0, b2 = 0.0;
  for (size_t l = 0; l < law.loads.size(); ++l) {
    const double u = law.loads[l] / nominal_load;
    const double x = std::acosh(std::max(1.0, s11 / (law.ref_value[l] / law.loads[l])));
    a11 += u * u * u * u;
    a12 += u * u * u;
    a22 += u * u;
    b1 += u * u * x;
    b2 += u * x;
  }
  double s12 = 0.0, s13 = 0.0;
  const double det = a11 * a22 - a12 * a12;
  if (law.loads.size() >= 2 && std::abs(det) > 1e-12 * a11 * a22) {
    s12 = (b1 * a22 - a12 * b2) / det;
    s13 = (a11 * b2 - a12 * b1) / det;
  }
  if (!(s13 >= 0.0) || law.loads.size() < 2) {
    s12 = 0.0;
    s13 = a22 > 0.0 ? b2 / a22 : 0.0;
  }
  return {s11, std::clamp(s12, -10.0, 10.0), std::clamp(s13, 0.0, 10.0)};
}

std::vector<const RigSample*> FitSamples(std::span<const RigSample> samples,
                                         const UniTireFitOptions& options) {
  if (options.fit_temps.empty()) {
    throw InputError("UniTire fit: options.fit_temps is empty; give at least one temperature");
  }
  std::vector<const RigSample*> out;
  for (const RigSample& s : samples) {
    if (IsFitTemp(s.tread_temp, options.fit_temps, options.temp_tolerance)) out.push_back(&s);
  }
  if (out.empty()) {
    throw InputError(fmt::format("UniTire fit: no sample lies within {:g} K of a fit temperature",
                                 options.temp_tolerance));
  }
  return out;
}

double NominalLoad(const std::vector<const RigSample*>& fit, const UniTireFitOptions& options) {
  if (options.nominal_load) return *options.nominal_load;
  std::vector<double> loads;
  for (const RigSample* s : fit) loads.push_back(s->fz);
  return Median(loads);
}

double ReferenceTemp(const UniTireFitOptions& options) {
  if (options.reference_temp) return *options.reference_temp;
  return std::accumulate(options.fit_temps.begin(), options.fit_temps.end(), 0.0) /
         static_cast<double>(options.fit_temps.size());
}

// --- Fit --------------------------------------------------------------------------------------

struct SampleResidual {
  const UniTireParams<double>* base;
  const std::vector<int>* free;
  RigSample sample;
  double fy_scale, mz_scale, fx_scale;

  template <typename T>
  bool operator()(T const* const* x, T* r) const {
    UniTireParams<T> p = base->Cast<T>();
    const auto fields = FieldPointers(p);
    for (size_t i = 0; i < free->size(); ++i) *fields[(*free)[i]] = x[0][i];
    const tyre::TyreForces<T> f =
        tyre::CalcUniTireForces(p, internal::RigOperatingPoint<T>(sample));
    r[0] = (f.fy - sample.fy) / fy_scale;
    r[1] = (f.mz - sample.mz) / mz_scale;
    if (sample.fx) r[2] = (f.fx - *sample.fx) / fx_scale;
    return true;
  }
};

}  // namespace

tyre::UniTireParams<double> CalcUniTireInitialGuess(std::span<const RigSample> samples,
                                                    const UniTireFitOptions& options) {
  internal::CheckRigSamples(samples);
  const std::vector<const RigSample*> fit = FitSamples(samples, options);
  const double nominal_load = NominalLoad(fit, options);
  const double reference_temp = ReferenceTemp(options);

  const std::vector<Curve> lateral = PureSlipCurves(samples, options, /*lateral=*/true);
  if (lateral.empty()) {
    throw InputError(
        "UniTire fit: no curve of pure side slip (zero slip ratio and camber, at least one "
        "non-zero "
        "slip angle) at the fit temperatures");
  }
  UniTireParams<double> p;
  p.nominal_load = nominal_load;
  for (tyre::TemperatureFactor<double>* f :
       {&p.stiffness_temperature, &p.trail_temperature, &p.friction_temperature}) {
    *f = {1.0, 0.0, reference_temp};
  }
  // Cornering stiffness: temperature decay, then the load law at T_ref.
  const LoadLaw k_law = TemperatureRegression(
      lateral, [](const Curve& c) { return c.stiffness; }, reference_temp);
  p.stiffness_temperature.decay = std::clamp(k_law.decay, -0.2, 0.2);
  const auto [s11, s12, s13] = SechLoadLaw(k_law, nominal_load);
  p.cornering_stiffness_per_load = s11;
  p.cornering_stiffness_load_quad = s12;
  p.cornering_stiffness_load_lin = s13;
  p.cornering_stiffness_camber = 0.0;

  // Friction from the peaks: log(mu) linear in (Fzn - 1).
  {
    std::vector<double> x, y;
    for (const Curve& c : lateral) {
      x.push_back(c.fz / nominal_load - 1.0);
      y.push_back(std::log(c.peak / c.fz));
    }
    const auto [c0, c1] = internal::LineFit(x, y);
    p.friction_y = std::clamp(std::exp(c0), 0.1, 4.0);
    p.friction_load_decay = std::clamp(-c1, -1.0, 1.0);
  }
  p.curvature_y = 0.0;

  // Trail at zero slip: temperature decay, then a power law in the load.
  std::vector<Curve> trails;
  for (const Curve& c : lateral) {
    if (c.moment_slope > 0.0) trails.push_back(c);
  }
  p.trail = 0.02;
  p.trail_load_exponent = 0.5;
  if (!trails.empty()) {
    const LoadLaw t_law = TemperatureRegression(
        trails, [](const Curve& c) { return c.moment_slope / c.stiffness; }, reference_temp);
    p.trail_temperature.decay = std::clamp(t_law.decay, -0.2, 0.2);
    std::vector<double> x, y;
    for (size_t l = 0; l < t_law.loads.size(); ++l) {
      x.push_back(std::log(t_law.loads[l] / nominal_load));
      y.push_back(std::log(t_law.ref_value[l]));
    }
    const auto [c0, c1] = internal::LineFit(x, y);
    p.trail_load_exponent = t_law.loads.size() >= 2 ? std::clamp(c1, 0.0, 2.0) : 0.5;
    p.trail = std::clamp(std::exp(c0), 1e-4, 0.5);
  }
  p.trail_offset = 0.2 * p.trail;
  p.trail_decay_lin = 1.0;
  p.trail_decay_quad = 0.0;

  // Sliding-speed friction law: no effect (one rig speed cannot identify it).
  p.friction_sliding_ratio = 1.0;
  p.friction_peak_speed = 1.0;
  p.friction_speed_shape = 1.0;

  // Longitudinal: from pure longitudinal-slip curves if measured, else as the lateral.
  p.slip_stiffness_per_load = s11;
  p.slip_stiffness_load_quad = s12;
  p.slip_stiffness_load_lin = s13;
  p.friction_x = p.friction_y;
  p.curvature_x = 0.0;
  const std::vector<Curve> longitudinal = PureSlipCurves(samples, options, /*lateral=*/false);
  if (!longitudinal.empty()) {
    const double b = p.stiffness_temperature.decay;
    std::vector<Curve> at_ref = longitudinal;
    LoadLaw law;
    {
      std::vector<double> loads;
      for (const Curve& c : at_ref) loads.push_back(c.fz);
      const ValueGroups lg = GroupValues(loads, kLoadGroupTolerance, GroupTolerance::kRelative);
      law.loads = lg.mean;
      law.ref_value.assign(lg.mean.size(), 0.0);
      std::vector<int> count(lg.mean.size(), 0);
      for (size_t i = 0; i < at_ref.size(); ++i) {
        law.ref_value[lg.index[i]] +=
            std::log(at_ref[i].stiffness) + b * (at_ref[i].temp - reference_temp);
        ++count[lg.index[i]];
      }
      for (size_t l = 0; l < law.loads.size(); ++l) {
        law.ref_value[l] = std::exp(law.ref_value[l] / count[l]);
      }
    }
    const auto [x1, x2, x3] = SechLoadLaw(law, nominal_load);
    p.slip_stiffness_per_load = x1;
    p.slip_stiffness_load_quad = x2;
    p.slip_stiffness_load_lin = x3;
    double mu = 0.0;
    for (const Curve& c : longitudinal) {
      mu += c.peak / c.fz * std::exp(p.friction_load_decay * (c.fz / nominal_load - 1.0));
    }
    p.friction_x = std::clamp(mu / static_cast<double>(longitudinal.size()), 0.1, 4.0);
  }
  return p;
}

std::vector<UniTireTempMetrics> EvaluateUniTire(const tyre::UniTireParams<double>& params,
                                                std::span<const RigSample> samples,
                                                std::span<const double> fit_temps,
                                                double temp_tolerance) {
  std::vector<double> temps;
  for (const RigSample& s : samples) temps.push_back(s.tread_temp);
  const ValueGroups tg = GroupValues(temps, temp_tolerance, GroupTolerance::kAbsolute);
  std::vector<UniTireTempMetrics> rows(tg.mean.size());
  std::vector<double> fy2(rows.size(), 0.0), mz2(rows.size(), 0.0), fx2(rows.size(), 0.0);
  std::vector<int> fx_count(rows.size(), 0);
  for (size_t i = 0; i < samples.size(); ++i) {
    const RigSample& s = samples[i];
    const int g = tg.index[i];
    const tyre::TyreForces<double> f =
        tyre::CalcUniTireForces(params, internal::RigOperatingPoint<double>(s));
    fy2[g] += (f.fy - s.fy) * (f.fy - s.fy);
    mz2[g] += (f.mz - s.mz) * (f.mz - s.mz);
    if (s.fx) {
      fx2[g] += (f.fx - *s.fx) * (f.fx - *s.fx);
      ++fx_count[g];
    }
    rows[g].fy_peak_N = std::max(rows[g].fy_peak_N, std::abs(s.fy));
    ++rows[g].samples;
  }
  for (size_t g = 0; g < rows.size(); ++g) {
    UniTireTempMetrics& m = rows[g];
    m.temp = tg.mean[g];
    m.fitted = IsFitTemp(m.temp, fit_temps, temp_tolerance);
    m.fy_rms_N = std::sqrt(fy2[g] / m.samples);
    m.mz_rms_Nm = std::sqrt(mz2[g] / m.samples);
    m.fy_rms_rel_peak = m.fy_peak_N > 0.0 ? m.fy_rms_N / m.fy_peak_N : 0.0;
    if (fx_count[g] > 0) m.fx_rms_N = std::sqrt(fx2[g] / fx_count[g]);
  }
  return rows;
}

UniTireFitResult FitUniTire(std::span<const RigSample> samples, const UniTireFitOptions& options) {
  internal::CheckRigSamples(samples);
  const std::vector<const RigSample*> fit = FitSamples(samples, options);
  UniTireFitResult result;
  result.initial_guess =
      options.initial_guess ? *options.initial_guess : CalcUniTireInitialGuess(samples, options);

  // What the data can identify.
  std::vector<double> loads, temps;
  bool camber = false, longitudinal = false;
  double fy_scale = 0.0, mz_scale = 0.0, fx_scale = 0.0;
  for (const RigSample* s : fit) {
    loads.push_back(s->fz);
    temps.push_back(s->tread_temp);
    camber = camber || std::abs(s->camber) > 1e-4;
    longitudinal = longitudinal || (s->fx && std::abs(s->slip_ratio) > 1e-6);
    fy_scale = std::max(fy_scale, std::abs(s->fy));
    mz_scale = std::max(mz_scale, std::abs(s->mz));
    if (s->fx) fx_scale = std::max(fx_scale, std::abs(*s->fx));
  }
  const bool several_loads =
      GroupValues(loads, kLoadGroupTolerance, GroupTolerance::kRelative).mean.size() >= 2;
  const bool several_temps =
      GroupValues(temps, options.temp_tolerance, GroupTolerance::kAbsolute).mean.size() >= 2;
  if (!(fy_scale > 0.0)) fy_scale = 1.0;
  if (!(mz_scale > 0.0)) mz_scale = 1.0;
  if (!(fx_scale > 0.0)) fx_scale = 1.0;
  mz_scale /= options.mz_weight > 0.0 ? options.mz_weight : 1.0;

  std::vector<FreeField> free = {
      {"cornering_stiffness_per_load", 1e-3, 1e3},
      {"cornering_stiffness_load_quad", -10.0, 10.0},
      {"cornering_stiffness_load_lin", 0.0, 10.0},
      {"friction_y", 0.05, 5.0},
      {"curvature_y", -5.0, 5.0},
      {"trail", 0.0, 1.0},
      {"trail_offset", -0.5, 0.5},
      {"trail_decay_lin", 0.0, 100.0},
      {"trail_decay_quad", 0.0, 100.0},
  };
  if (several_loads) {
    free.push_back({"friction_load_decay", -2.0, 2.0});
    free.push_back({"trail_load_exponent", 0.0, 3.0});
  }
  if (several_temps) {
    free.push_back({"stiffness_temperature.decay", -0.5, 0.5});
    free.push_back({"trail_temperature.decay", -0.5, 0.5});
    if (options.friction_temperature == FrictionTemperatureFit::kFitted) {
      free.push_back({"friction_temperature.decay", -0.5, 0.5});
    }
  }
  if (camber) free.push_back({"cornering_stiffness_camber", 0.0, 100.0});
  if (longitudinal) {
    free.push_back({"slip_stiffness_per_load", 1e-3, 1e3});
    free.push_back({"slip_stiffness_load_quad", -10.0, 10.0});
    free.push_back({"slip_stiffness_load_lin", 0.0, 10.0});
    free.push_back({"friction_x", 0.05, 5.0});
    free.push_back({"curvature_x", -5.0, 5.0});
  }

  UniTireParams<double> base = result.initial_guess;
  std::vector<int> free_index;
  std::vector<double> x0;
  std::vector<internal::ParameterBounds> bounds;
  internal::MultiStartOptions solve;
  solve.max_iterations = options.max_iterations;
  {
    const auto fields = FieldPointers(base);
    for (const FreeField& f : free) {
      // Start inside the bounds, away from them so the first step can go either way.
      free_index.push_back(FieldIndex(f.name));
      bounds.push_back({f.lower, f.upper});
      x0.push_back(internal::StartInsideBounds(*fields[free_index.back()], bounds.back()));
      result.fitted_fields.emplace_back(f.name);
      // The curvature E shapes Fbar's knee and can sit in a local minimum far from its start:
      // start it at 0, -1, 1 and -2 and keep the best solution.
      if (f.name == "curvature_y" || f.name == "curvature_x") {
        solve.start_indices.push_back(static_cast<int>(x0.size()) - 1);
      }
    }
  }
  solve.start_values = {0.0, -1.0, 1.0, -2.0};
  const int n_free = static_cast<int>(x0.size());
  const internal::MultiStartResult best = internal::SolveMultiStart(
      x0, bounds,
      [&](ceres::Problem& problem, double* x) {
        for (const RigSample* s : fit) {
          internal::AddDynamicAutoDiffResidual(
              problem, new SampleResidual{&base, &free_index, *s, fy_scale, mz_scale, fx_scale},
              n_free, s->fx ? 3 : 2, x);
        }
      },
      solve);

  result.params = base;
  {
    const auto fields = FieldPointers(result.params);
    for (int i = 0; i < n_free; ++i) *fields[free_index[i]] = best.x[i];
  }
  result.converged = best.converged;
  result.iterations = best.iterations;
  result.final_cost = best.final_cost;
  result.report = best.brief_report;
  result.metrics =
      EvaluateUniTire(result.params, samples, options.fit_temps, options.temp_tolerance);
  return result;
}

void RequireFitAndPredictTemps(std::span<const RigSample> samples, const UniTireFitOptions& options,
                               const std::vector<double>& predict_temps,
                               const std::string& source) {
  const double tol = options.temp_tolerance;
  const auto present = [&](double temp) {
    return std::any_of(samples.begin(), samples.end(),
                       [&](const RigSample& s) { return std::abs(s.tread_temp - temp) <= tol; });
  };
  for (const auto* list : {&options.fit_temps, &predict_temps}) {
    for (double t : *list) {
      if (!present(t)) {
        throw InputError(fmt::format("{}: no rig sample within {:g} K of {:g} degC", source, tol,
                                     KelvinToCelsius(t)));
      }
    }
  }
  for (double p : predict_temps) {
    for (double f : options.fit_temps) {
      if (std::abs(p - f) <= tol) {
        throw InputError(
            fmt::format("{:g} degC is both a fit and a predict temperature", KelvinToCelsius(p)));
      }
    }
  }
}

}  // namespace hotlap::ident
