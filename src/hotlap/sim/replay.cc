#include "hotlap/sim/replay.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/sim/sampled_inputs.h"
#include "hotlap/vehicle/vehicle_model.h"

namespace hotlap::sim {

namespace {

void CheckLength(const std::vector<double>& v, size_t n, const std::string& name) {
  if (v.size() != n) {
    throw InputError(
        fmt::format("replay input '{}' has {} samples, expected {}", name, v.size(), n));
  }
  for (size_t i = 0; i < n; ++i) {
    if (!std::isfinite(v[i])) {
      throw InputError(fmt::format("replay input '{}' is not finite at sample {}", name, i));
    }
  }
}

void CheckTemperature(double temp, const char* what, Corner c, double time) {
  if (!(temp > 0.0 && temp < 3000.0)) {
    throw NumericalError(fmt::format(
        "replay diverged: {} temperature of corner {} is {:g} K at t = {:g} s; check the inputs "
        "(forces, speeds) and the parameters",
        what, CornerName(c), temp, time));
  }
}

// The sample count, after checking it (at least two), the times (finite, strictly increasing) and
// the two temperature channels.
size_t CheckTimesAndTemperatures(const ReplayInputs& in) {
  const size_t n = in.time.size();
  if (n < 2) throw InputError("replay needs at least two samples");
  CheckLength(in.time, n, "time_s");
  for (size_t i = 1; i < n; ++i) {
    if (!(in.time[i] > in.time[i - 1])) {
      throw InputError(fmt::format("replay time is not strictly increasing at sample {}", i));
    }
  }
  CheckLength(in.ambient_temp, n, "ambient_temp");
  CheckLength(in.track_temp, n, "track_temp");
  return n;
}

void CheckCornerChannels(const CornerChannels& ch, size_t n, Corner c) {
  const std::string corner(CornerName(c));
  CheckLength(ch.speed, n, "speed_" + corner);
  CheckLength(ch.fx, n, "fx_" + corner);
  CheckLength(ch.fy, n, "fy_" + corner);
  CheckLength(ch.fz, n, "fz_" + corner);
  CheckLength(ch.slip_angle, n, "slip_angle_" + corner);
  CheckLength(ch.slip_ratio, n, "slip_ratio_" + corner);
}

}  // namespace

CornerSamples CornerSamplesOf(const ReplayInputs& in, Corner corner) {
  const CornerChannels& ch = in.corners[CornerIndex(corner)];
  return {in.time,       ch.speed,      ch.fx,           ch.fy,        ch.fz,
          ch.slip_angle, ch.slip_ratio, in.ambient_temp, in.track_temp};
}

CornerSamples BrakeSamplesOf(const ReplayInputs& in, Corner corner) {
  CornerSamples s = CornerSamplesOf(in, corner);
  const CornerChannels& ch = in.corners[CornerIndex(corner)];
  if (ch.brake_fx.empty()) return s;
  if (ch.brake_fx.size() != in.time.size()) {
    throw InputError(fmt::format("the brake force of corner {} has {} samples, time has {}",
                                 CornerName(corner), ch.brake_fx.size(), in.time.size()));
  }
  s.fx = ch.brake_fx;
  return s;
}

ReplayInitialState CarStartState(const vehicle::Car& car) {
  const vehicle::InitialTemperatures& t = car.initial;
  ReplayInitialState s;
  for (int k = 0; k < 4; ++k) {
    s.tyres[k] = {t.tread_temp, t.carcass_temp, 0.0, t.rim_temp};
    s.brakes[k] = {t.disc_temp, t.calliper_temp, t.disc_bulk_temp};
  }
  return s;
}

ReplayInitialState StateAt(const ReplayResult& r, size_t k) {
  ReplayInitialState s;
  for (int c = 0; c < 4; ++c) {
    const CornerHistory& h = r.corners[c];
    s.tyres[c] = {h.tread_temp[k], h.carcass_temp[k], h.wear[k],
                  h.rim_temp.empty() ? 0.0 : h.rim_temp[k]};
    s.brakes[c] = {h.disc_temp[k], h.calliper_temp[k],
                   h.disc_bulk_temp.empty() ? 0.0 : h.disc_bulk_temp[k]};
  }
  return s;
}

ReplayInitialState EndState(const ReplayResult& r) { return StateAt(r, r.time.size() - 1); }

std::span<const std::pair<std::string_view, std::vector<double> CornerHistory::*>> ModelChannels() {
  static const std::array<std::pair<std::string_view, std::vector<double> CornerHistory::*>, 7>
      kChannels = {{{"gas_temp_{}_C", &CornerHistory::gas_temp},
                    {"rim_temp_{}_C", &CornerHistory::rim_temp},
                    {"pressure_{}_kPa", &CornerHistory::pressure},
                    {"rolling_resistance_{}", &CornerHistory::rolling_resistance},
                    {"liner_gas_temp_{}_C", &CornerHistory::liner_gas_temp},
                    {"liner_pressure_{}_kPa", &CornerHistory::liner_pressure},
                    {"disc_bulk_temp_{}_C", &CornerHistory::disc_bulk_temp}}};
  return kChannels;
}

double ModelChannelValue(std::vector<double> CornerHistory::*member, double si) {
  if (member == &CornerHistory::pressure || member == &CornerHistory::liner_pressure) {
    return 1e-3 * si;
  }
  if (member == &CornerHistory::rolling_resistance) return si;
  return KelvinToCelsius(si);
}

namespace {

using TyreParams = tyre::TyreThermalParams<double>;
using BrakeParams = brake::BrakeThermalParams<double>;

// Heat held by the nodes, J (from 0 K: only its changes are used).
double TyreStored(const TyreParams& p, const tyre::TyreState<double>& x) {
  return p.tread_mass * p.tread_heat_capacity * x.tread_temp +
         p.carcass_mass * p.carcass_heat_capacity * x.carcass_temp;
}
double RimStored(const TyreParams& p, const tyre::TyreState<double>& x) {
  return p.HasGasAndRim() ? p.rim_mass * p.rim_heat_capacity * x.rim_temp : 0.0;
}
double BrakeStored(const BrakeParams& p, const brake::BrakeState<double>& x) {
  const double disc = p.disc_mass * p.disc_heat_capacity;
  double e = p.mass_participation * disc * x.disc_temp +
             p.calliper_mass * p.calliper_heat_capacity * x.calliper_temp;
  if (p.HasBulk()) e += (1.0 - p.mass_participation) * disc * x.bulk_temp;
  return e;
}

// The rates of the accumulated energies, W.
void TyreRates(const TyreParams& p, const tyre::TyreHeatFlows<double>& q,
               const tyre::TyreInputTerms<double>& t, double vehicle_rolling, double* d) {
  using std::abs;
  d[kSlidingWork] = t.sliding_power;
  // The gas-and-rim tyre's rolling resistance is the car's; the paper's tyre is rolled by the
  // vehicle model's coefficient (its .tir's QSY1).
  d[kRollingWork] =
      p.HasGasAndRim() ? q.rolling_power : abs(t.input.speed) * vehicle_rolling * abs(t.input.fz);
  d[kTreadHeat] = q.q1;
  d[kCarcassHeat] = q.q2;
  d[kTreadConvection] = q.q3;
  d[kTrackConduction] = q.q4;
  d[kTreadRadiation] = q.q6;
  d[kSidewallRadiation] = q.q7;
  d[kSidewallConvection] = q.sidewall_convection;
  d[kCarcassToGas] = q.carcass_to_gas;
  d[kRimToAir] = q.rim_to_air;
  d[kBrakeToRim] = q.brake_to_rim;
}
void BrakeRates(const brake::BrakeHeatFlows<double>& q, double* d) {
  d[kBrakeWork] = q.q1;
  d[kDiscRadiation] = q.q3;
  d[kDiscConvection] = q.q4;
  d[kCalliperRadiation] = q.q5;
  d[kCalliperConvection] = q.q6;
  d[kVaneConvection] = q.bulk_convection;
  d[kHubToRim] = q.hub_to_rim;
  d[kRadiationToRim] = q.radiation_to_rim;
}

// What a corner's integration leaves at each audit boundary.
struct Boundary {
  TyreEnergies tyre{};
  BrakeEnergies brake{};
  double tyre_stored = 0.0, rim_stored = 0.0, brake_stored = 0.0;
};

// Sample k's position among the boundaries, or -1.
int BoundaryIndex(const std::vector<size_t>& boundaries, size_t k) {
  const auto it = std::lower_bound(boundaries.begin(), boundaries.end(), k);
  return it != boundaries.end() && *it == k ? static_cast<int>(it - boundaries.begin()) : -1;
}

// The first sample, each audit start, the last sample.
std::vector<size_t> AuditBoundaries(const std::vector<size_t>& starts, size_t n) {
  std::vector<size_t> b = {0};
  for (size_t s : starts) {
    if (s <= b.back() || s >= n - 1) {
      throw InputError(fmt::format("replay audit start {} is not inside the run (1 to {}) after {}",
                                   s, n - 2, b.back()));
    }
    b.push_back(s);
  }
  b.push_back(n - 1);
  return b;
}

// Records a tyre state at sample k.
struct TyreRecorder {
  const TyreParams& p;
  const tyre::TyreCompound& compound;
  const CornerSamples& samples;
  const ReplayOptions& options;
  CornerHistory& h;
  Corner corner;

  void operator()(size_t k, const tyre::TyreState<double>& x, double brake_to_rim) const {
    CheckTemperature(x.tread_temp, "tread", corner, samples.time[k]);
    CheckTemperature(x.carcass_temp, "carcass", corner, samples.time[k]);
    h.tread_temp[k] = x.tread_temp;
    h.carcass_temp[k] = x.carcass_temp;
    h.wear[k] = x.wear;
    h.grip_factor[k] = compound.GripFactor(x.tread_temp, x.wear);
    if (p.HasGasAndRim()) {
      CheckTemperature(x.rim_temp, "rim", corner, samples.time[k]);
      const tyre::TyreGas<double> gas =
          tyre::CalcTyreGas(p, x.carcass_temp, x.rim_temp, samples.speed[k]);
      h.rim_temp[k] = x.rim_temp;
      h.gas_temp[k] = gas.gas_temp;
      h.pressure[k] = gas.pressure;
      h.rolling_resistance[k] = gas.rolling_resistance;
      if (!h.liner_gas_temp.empty()) {
        h.liner_gas_temp[k] = gas.liner_temp;
        h.liner_pressure[k] = gas.liner_pressure;
      }
    }
    if (options.record_heat_flows) {
      const auto q = tyre::CalcTyreHeatFlows(
          p, x, tyre::CalcTyreInputTerms(p, compound, samples.TyreInputAt<double>(k, 0.0)),
          brake_to_rim);
      const std::array<double, 7> flows = {q.q1, q.q2, q.q3, q.q4, q.q5, q.q6, q.q7};
      for (int i = 0; i < 7; ++i) h.heat_flows[i][k] = flows[i];
    }
  }
};

// Records a brake state at sample k.
void RecordBrake(size_t k, const brake::BrakeState<double>& x, const BrakeParams& p,
                 const CornerSamples& samples, CornerHistory& h, Corner c) {
  CheckTemperature(x.disc_temp, "disc", c, samples.time[k]);
  CheckTemperature(x.calliper_temp, "calliper", c, samples.time[k]);
  h.disc_temp[k] = x.disc_temp;
  h.calliper_temp[k] = x.calliper_temp;
  h.brake_power[k] = brake::CalcBrakePower(samples.speed[k], samples.fx[k]);
  if (p.HasBulk()) {
    CheckTemperature(x.bulk_temp, "disc bulk", c, samples.time[k]);
    h.disc_bulk_temp[k] = x.bulk_temp;
  }
}

// The vehicle model's free-rolling resistance coefficient of each corner (0 for a thermal-only
// car): what the car spends rolling a paper-model tyre.
std::array<double, 4> VehicleRollingCoefficients(const vehicle::Car& car) {
  std::array<double, 4> c{};
  if (!car.vehicle) return c;
  for (Corner corner : kAllCorners) {
    c[CornerIndex(corner)] = vehicle::CalcFreeRollingCoefficient(car.vehicle->corner(corner),
                                                                 0.25 * car.vehicle->Weight());
  }
  return c;
}

// The histories a corner's models fill, sized for n samples.
void SizeHistory(CornerHistory& h, size_t n, const TyreParams& tp, const BrakeParams& bp,
                 bool heat_flows) {
  for (auto* v : {&h.tread_temp, &h.carcass_temp, &h.wear, &h.grip_factor, &h.disc_temp,
                  &h.calliper_temp, &h.brake_power}) {
    v->resize(n);
  }
  if (tp.HasGasAndRim()) {
    for (auto* v : {&h.rim_temp, &h.gas_temp, &h.pressure, &h.rolling_resistance}) v->resize(n);
    if (tp.gas_liner_conductance > 0.0) {
      h.liner_gas_temp.resize(n);
      h.liner_pressure.resize(n);
    }
  }
  if (bp.HasBulk()) h.disc_bulk_temp.resize(n);
  if (heat_flows) {
    for (auto& q : h.heat_flows) q.resize(n);
  }
}

// The states only some models have need a start of their own (CarStartState gives the car's).
void CheckModelStarts(const TyreParams& tp, const BrakeParams& bp, const tyre::TyreState<double>& t,
                      const brake::BrakeState<double>& b, Corner c) {
  if (tp.HasGasAndRim() && !(t.rim_temp > 0.0)) {
    throw InputError(
        fmt::format("replay: the starting rim temperature of corner {} is {:g} K; "
                    "its gas-and-rim tyre needs one (sim::CarStartState gives the car's)",
                    CornerName(c), t.rim_temp));
  }
  if (bp.HasBulk() && !(b.bulk_temp > 0.0)) {
    throw InputError(fmt::format(
        "replay: the starting disc bulk temperature of corner {} is "
        "{:g} K; its surface-and-bulk disc needs one (sim::CarStartState gives the car's)",
        CornerName(c), b.bulk_temp));
  }
}

// One corner's replay: its models over its samples, the histories and, at each audit boundary,
// the accumulated energies and the heat the nodes hold.
class CornerReplay {
 public:
  CornerReplay(const vehicle::Car& car, const ReplayInputs& in, Corner c,
               const ReplayOptions& options, const std::vector<size_t>& boundaries,
               double vehicle_rolling, CornerHistory& h)
      : c_(c),
        tp_(car.tyre(c).params),
        bp_(car.brake(c).params),
        compound_(*car.tyre(c).compound),
        samples_(CornerSamplesOf(in, c)),
        brake_samples_(BrakeSamplesOf(in, c)),
        options_(options),
        boundaries_(boundaries),
        vehicle_rolling_(vehicle_rolling),
        h_(h),
        record_tyre_{tp_, compound_, samples_, options_, h_, c_},
        tyre_constants_(tyre::CalcTyreConstants(tp_)),
        brake_constants_(brake::CalcBrakeConstants(bp_)),
        at_(boundaries.size()) {}

  // Integrates from the corner's start; returns what each boundary holds.
  std::vector<Boundary> Run(const tyre::TyreState<double>& tyre,
                            const brake::BrakeState<double>& brake) {
    CheckModelStarts(tp_, bp_, tyre, brake, c_);
    SizeHistory(h_, samples_.time.size(), tp_, bp_, options_.record_heat_flows);
    if (tp_.HasGasAndRim()) {
      RunTogether(tyre, brake);
    } else {
      RunApart(tyre, brake);
    }
    return std::move(at_);
  }

 private:
  tyre::TyreInputTerms<double> TyreTerms(size_t k, double f,
                                         const tyre::TyreInputTerms<double>* near) const {
    return tyre::CalcTyreInputTerms(tp_, tyre_constants_, compound_,
                                    samples_.TyreInputAt<double>(k, f), near);
  }
  brake::BrakeInputTerms<double> BrakeTerms(size_t k, double f) const {
    return brake::CalcBrakeInputTerms(bp_, brake_constants_,
                                      brake_samples_.BrakeInputAt<double>(k, f));
  }

  // The gas-and-rim tyre and its brake together: the rim takes the brake's heat.
  void RunTogether(const tyre::TyreState<double>& tyre, const brake::BrakeState<double>& brake) {
    constexpr size_t kN = size_t{kTyreEnergyCount} + size_t{kBrakeEnergyCount};
    using State = WithEnergies<WheelState<double>, kN>;
    using Terms = std::pair<tyre::TyreInputTerms<double>, brake::BrakeInputTerms<double>>;
    IntegrateOverSamples(
        samples_, State{{tyre, brake}, {}}, options_.max_step_s,
        [&](size_t k, double f, const Terms* near) {
          return Terms{TyreTerms(k, f, near ? &near->first : nullptr), BrakeTerms(k, f)};
        },
        [&](const State& s, const Terms& t) {
          State d;
          brake::BrakeHeatFlows<double> bq;
          d.x.brake = brake::CalcBrakeDerivatives(bp_, s.x.brake, t.second, &bq, s.x.tyre.rim_temp);
          tyre::TyreHeatFlows<double> tq;
          d.x.tyre = tyre::CalcTyreDerivatives(tp_, compound_, s.x.tyre, t.first, &tq, bq.ToRim());
          TyreRates(tp_, tq, t.first, vehicle_rolling_, d.e.data());
          BrakeRates(bq, d.e.data() + kTyreEnergyCount);
          return d;
        },
        [&](size_t k, const State& s) {
          const double to_rim =
              options_.record_heat_flows
                  ? brake::CalcBrakeHeatFlows(bp_, s.x.brake, BrakeTerms(k, 0.0), s.x.tyre.rim_temp)
                        .ToRim()
                  : 0.0;
          record_tyre_(k, s.x.tyre, to_rim);
          RecordBrake(k, s.x.brake, bp_, brake_samples_, h_, c_);
          if (const int b = BoundaryIndex(boundaries_, k); b >= 0) {
            std::copy_n(s.e.begin(), kTyreEnergyCount, at_[b].tyre.begin());
            std::copy_n(s.e.begin() + kTyreEnergyCount, kBrakeEnergyCount, at_[b].brake.begin());
            at_[b].tyre_stored = TyreStored(tp_, s.x.tyre);
            at_[b].rim_stored = RimStored(tp_, s.x.tyre);
            at_[b].brake_stored = BrakeStored(bp_, s.x.brake);
          }
        },
        &brake_samples_);
  }

  // The paper's tyre has no rim: tyre and brake run apart, as published.
  void RunApart(const tyre::TyreState<double>& tyre, const brake::BrakeState<double>& brake) {
    using TyreRun = WithEnergies<tyre::TyreState<double>, kTyreEnergyCount>;
    IntegrateOverSamples(
        samples_, TyreRun{tyre, {}}, options_.max_step_s,
        [&](size_t k, double f, const tyre::TyreInputTerms<double>* near) {
          return TyreTerms(k, f, near);
        },
        [&](const TyreRun& s, const tyre::TyreInputTerms<double>& t) {
          TyreRun d;
          tyre::TyreHeatFlows<double> q;
          d.x = tyre::CalcTyreDerivatives(tp_, compound_, s.x, t, &q);
          TyreRates(tp_, q, t, vehicle_rolling_, d.e.data());
          return d;
        },
        [&](size_t k, const TyreRun& s) {
          record_tyre_(k, s.x, 0.0);
          if (const int b = BoundaryIndex(boundaries_, k); b >= 0) {
            at_[b].tyre = s.e;
            at_[b].tyre_stored = TyreStored(tp_, s.x);
          }
        });
    using BrakeRun = WithEnergies<brake::BrakeState<double>, kBrakeEnergyCount>;
    IntegrateOverSamples(
        brake_samples_, BrakeRun{brake, {}}, options_.max_step_s,
        [&](size_t k, double f, const brake::BrakeInputTerms<double>*) { return BrakeTerms(k, f); },
        [&](const BrakeRun& s, const brake::BrakeInputTerms<double>& t) {
          BrakeRun d;
          brake::BrakeHeatFlows<double> q;
          // Without a rim the bulk disc's hub and rim shares are zero (vehicle::LoadCar).
          d.x = brake::CalcBrakeDerivatives(bp_, s.x, t, &q, t.input.cooling_air_temp);
          BrakeRates(q, d.e.data());
          return d;
        },
        [&](size_t k, const BrakeRun& s) {
          RecordBrake(k, s.x, bp_, brake_samples_, h_, c_);
          if (const int b = BoundaryIndex(boundaries_, k); b >= 0) {
            at_[b].brake = s.e;
            at_[b].brake_stored = BrakeStored(bp_, s.x);
          }
        });
  }

  Corner c_;
  const TyreParams& tp_;
  const BrakeParams& bp_;
  const tyre::TyreCompound& compound_;
  const CornerSamples samples_, brake_samples_;
  const ReplayOptions& options_;
  const std::vector<size_t>& boundaries_;
  double vehicle_rolling_;
  CornerHistory& h_;
  const TyreRecorder record_tyre_;
  const tyre::TyreConstants<double> tyre_constants_;
  const brake::BrakeConstants<double> brake_constants_;
  std::vector<Boundary> at_;
};

}  // namespace

ReplayResult RunReplay(const vehicle::Car& car, const ReplayInputs& in,
                       const ReplayInitialState& initial, const ReplayOptions& options) {
  const size_t n = CheckTimesAndTemperatures(in);
  if (!(options.max_step_s > 0.0)) throw InputError("replay max step must be > 0 s");
  const std::vector<size_t> boundaries = AuditBoundaries(options.audit_starts, n);
  const std::array<double, 4> vehicle_rolling = VehicleRollingCoefficients(car);

  ReplayResult result;
  result.time = in.time;
  result.audits.resize(boundaries.size() - 1);
  for (Corner c : kAllCorners) {
    const int ci = CornerIndex(c);
    const CornerChannels& ch = in.corners[ci];
    CheckCornerChannels(ch, n, c);
    if (!ch.brake_fx.empty()) CheckLength(ch.brake_fx, n, "brake_fx_" + std::string(CornerName(c)));
    const std::vector<Boundary> at =
        CornerReplay(car, in, c, options, boundaries, vehicle_rolling[ci], result.corners[ci])
            .Run(initial.tyres[ci], initial.brakes[ci]);
    for (size_t b = 0; b + 1 < boundaries.size(); ++b) {
      result.audits[b][ci] = AuditBetween(
          at[b].tyre, at[b + 1].tyre, at[b].brake, at[b + 1].brake,
          at[b + 1].tyre_stored - at[b].tyre_stored, at[b + 1].rim_stored - at[b].rim_stored,
          at[b + 1].brake_stored - at[b].brake_stored,
          in.time[boundaries[b + 1]] - in.time[boundaries[b]], car.tyre(c).params.HasGasAndRim());
    }
  }
  return result;
}

ReplayInputs ResampleReplayInputs(const ReplayInputs& in, double rate_hz, int laps) {
  if (!(rate_hz > 0.0 && std::isfinite(rate_hz))) {
    throw InputError(fmt::format("resampling rate must be finite and > 0 Hz, got {:g}", rate_hz));
  }
  if (laps < 1) throw InputError(fmt::format("resampling needs at least one lap, got {}", laps));
  const size_t n = CheckTimesAndTemperatures(in);
  for (Corner c : kAllCorners) CheckCornerChannels(in.corners[CornerIndex(c)], n, c);

  const double t0 = in.time.front(), t1 = in.time.back();
  const double period = t1 - t0 + (in.time[1] - in.time[0]);
  // One lap alone covers [t0, t1]; repeated laps fill the whole period each.
  const double per_lap_count =
      laps == 1 ? std::floor((t1 - t0) * rate_hz) + 1.0 : std::floor(period * rate_hz);
  const double total_count = per_lap_count * laps;
  if (total_count < 2.0) {
    throw InputError(fmt::format(
        "resampling at {:g} Hz leaves fewer than two samples of a {:g} s log", rate_hz, t1 - t0));
  }
  if (total_count > static_cast<double>(std::numeric_limits<int>::max())) {
    throw InputError(
        fmt::format("resampling at {:g} Hz over {} laps gives too many samples", rate_hz, laps));
  }
  const size_t per_lap = static_cast<size_t>(per_lap_count);

  // Interval and weight of every grid time within a lap, found by one forward scan: interval j
  // holds time[j] <= t < time[j + 1] (the last interval also takes any t past the end, weight 1).
  std::vector<size_t> interval(per_lap);
  std::vector<double> weight(per_lap);
  size_t j = 0;
  for (size_t k = 0; k < per_lap; ++k) {
    const double t = t0 + k / rate_hz;
    while (j + 2 < n && in.time[j + 1] <= t) ++j;
    interval[k] = j;
    weight[k] = std::clamp((t - in.time[j]) / (in.time[j + 1] - in.time[j]), 0.0, 1.0);
  }
  const auto resample = [&](const std::vector<double>& v) {
    std::vector<double> r(per_lap * laps);
    for (size_t k = 0; k < per_lap; ++k) {
      const size_t i = interval[k];
      r[k] = v[i] + weight[k] * (v[i + 1] - v[i]);
    }
    for (int l = 1; l < laps; ++l) std::copy_n(r.begin(), per_lap, r.begin() + l * per_lap);
    return r;
  };

  ReplayInputs out;
  out.time.reserve(per_lap * laps);
  for (int l = 0; l < laps; ++l) {
    const double start = t0 + l * period;
    for (size_t k = 0; k < per_lap; ++k) out.time.push_back(start + k / rate_hz);
  }
  for (int c = 0; c < 4; ++c) {
    const CornerChannels& a = in.corners[c];
    CornerChannels& b = out.corners[c];
    b.speed = resample(a.speed);
    b.fx = resample(a.fx);
    b.fy = resample(a.fy);
    b.fz = resample(a.fz);
    b.slip_angle = resample(a.slip_angle);
    b.slip_ratio = resample(a.slip_ratio);
    if (!a.brake_fx.empty()) {
      CheckLength(a.brake_fx, n, "brake_fx_" + std::string(CornerName(static_cast<Corner>(c))));
      b.brake_fx = resample(a.brake_fx);
    }
  }
  out.ambient_temp = resample(in.ambient_temp);
  out.track_temp = resample(in.track_temp);
  return out;
}

HistoryStats CalcHistoryStats(const std::vector<double>& time, const std::vector<double>& values) {
  HistoryStats s;
  if (values.empty()) return s;
  s.peak = *std::max_element(values.begin(), values.end());
  s.final = values.back();
  const double span = time.back() - time.front();
  if (values.size() < 2 || span <= 0.0) {
    s.mean = values.front();
    return s;
  }
  double integral = 0.0;
  for (size_t i = 1; i < values.size(); ++i) {
    integral += 0.5 * (values[i] + values[i - 1]) * (time[i] - time[i - 1]);
  }
  s.mean = integral / span;
  return s;
}

std::array<CornerReplaySummary, 4> SummarizeReplay(const ReplayResult& result) {
  std::array<CornerReplaySummary, 4> out;
  const std::vector<double>& t = result.time;
  for (int c = 0; c < 4; ++c) {
    const CornerHistory& h = result.corners[c];
    CornerReplaySummary& s = out[c];
    s.tread = CalcHistoryStats(t, h.tread_temp);
    s.carcass = CalcHistoryStats(t, h.carcass_temp);
    s.disc = CalcHistoryStats(t, h.disc_temp);
    s.calliper = CalcHistoryStats(t, h.calliper_temp);
    if (!h.gas_temp.empty()) {
      s.gas = CalcHistoryStats(t, h.gas_temp);
      s.rim = CalcHistoryStats(t, h.rim_temp);
      s.pressure = CalcHistoryStats(t, h.pressure);
    }
    if (!h.disc_bulk_temp.empty()) s.disc_bulk = CalcHistoryStats(t, h.disc_bulk_temp);
    s.final_wear_mm = h.wear.empty() ? 0.0 : h.wear.back();
    s.min_grip_factor =
        h.grip_factor.empty() ? 0.0 : *std::min_element(h.grip_factor.begin(), h.grip_factor.end());
    for (size_t i = 1; i < t.size() && i < h.brake_power.size(); ++i) {
      s.brake_energy_J += 0.5 * (h.brake_power[i] + h.brake_power[i - 1]) * (t[i] - t[i - 1]);
    }
  }
  return out;
}

}  // namespace hotlap::sim
