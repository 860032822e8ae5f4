#include "hotlap/observe/synth_check.h"

#include <cmath>
#include <limits>
#include <string>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/logs/telemetry.h"
#include "hotlap/sim/synth_sensor.h"

namespace hotlap::observe {

namespace {

const std::vector<double>& Column(const sim::SynthLog& log, const std::string& name) {
  for (size_t i = 0; i < log.columns.size(); ++i) {
    if (log.columns[i] == name) return log.values[i];
  }
  throw InputError("synthetic log has no column '" + name + "'");
}

}  // namespace

SynthCheck CheckObserverOnSynth(const vehicle::Car& car, const sim::SynthLog& log,
                                const ObserverConfig& config, const SynthCheckOptions& o) {
  const sim::ReplayInputs& in = log.inputs;
  const size_t n = in.time.size();
  std::array<const std::vector<double>*, 4> tread{}, disc{}, calliper{};
  for (Corner c : kAllCorners) {
    const std::string name(CornerName(c));
    tread[CornerIndex(c)] = &Column(log, "tread_temp_" + name + "_C");
    disc[CornerIndex(c)] = &Column(log, "disc_temp_" + name + "_C");
    calliper[CornerIndex(c)] = &Column(log, "calliper_temp_" + name + "_C");
  }
  ObserverStart start;
  // One starting carcass temperature for the car (the log's are all the car file's).
  start.carcass_temp = log.truth.corners[0].carcass_temp[0] + o.carcass_offset_K;
  CarObserver observer(car, config, start);

  // Dropouts: a two-state chain per corner with the requested stationary fraction.
  sim::GaussianNoise random(o.seed);
  const auto uniform = [&] { return 0.5 * (1.0 + std::erf(random.Next() / std::sqrt(2.0))); };
  std::array<bool, 4> out{};
  long withheld = 0, disc_total = 0;

  std::array<std::array<double, 5>, 4> truth{};  // tread, carcass, wear, disc, calliper
  SynthCheck r;
  double sum_carcass2 = 0.0;
  std::array<double, 4> corner_carcass2{};
  long inside[5] = {0, 0, 0, 0, 0};
  double nees[5] = {0, 0, 0, 0, 0};
  for (size_t k = 0; k < n; ++k) {
    ObserverSample s;
    s.time = in.time[k];
    s.ambient_temp = in.ambient_temp[k];
    s.track_temp = in.track_temp[k];
    const double dt = k > 0 ? in.time[k] - in.time[k - 1] : 0.0;
    const double leave = dt / o.dropout_mean_s;  // P(out -> in) per sample
    const double enter = leave * o.disc_dropout_fraction / (1.0 - o.disc_dropout_fraction);
    for (int i = 0; i < 4; ++i) {
      const sim::CornerHistory& h = log.truth.corners[i];
      truth[i] = {h.tread_temp[k], h.carcass_temp[k], h.wear[k], h.disc_temp[k],
                  h.calliper_temp[k]};
    }
    for (int i = 0; i < 4; ++i) {
      const sim::CornerChannels& ch = in.corners[i];
      s.inputs[i] = {ch.speed[k], ch.fx[k], ch.fy[k], ch.fz[k], ch.slip_angle[k], ch.slip_ratio[k]};
      if (!ch.brake_fx.empty()) s.inputs[i].brake_fx = ch.brake_fx[k];
      if (k > 0) out[i] = out[i] ? uniform() >= leave : uniform() < enter;
      // Readings: the log's columns.
      s.readings[i].tread_temp = CelsiusToKelvin((*tread[i])[k]);
      ++disc_total;
      const double disc_reading = CelsiusToKelvin((*disc[i])[k]);
      if (out[i] && k > 0) {
        ++withheld;
      } else {
        s.readings[i].disc_temp = disc_reading;
      }
      if (o.read_calliper) s.readings[i].calliper_temp = CelsiusToKelvin((*calliper[i])[k]);
    }
    r.warnings += static_cast<long>(observer.Step(s).size());
    if (in.time[k] - in.time[0] < o.score_from_s) continue;
    ++r.scored;
    for (Corner c : kAllCorners) {
      const int i = CornerIndex(c);
      const std::array<double, 5>& x = truth[i];
      const CornerEstimate e = observer.Estimate(c);
      const double de = e.carcass_temp - x[1];
      sum_carcass2 += de * de;
      corner_carcass2[i] += de * de;
      const double err[5] = {e.tread_temp - x[0], de, e.wear - x[2], e.disc_temp - x[3],
                             e.calliper_temp - x[4]};
      const double sd[5] = {e.tread_temp_sd, e.carcass_temp_sd, e.wear_sd, e.disc_temp_sd,
                            e.calliper_temp_sd};
      for (int j = 0; j < 5; ++j) {
        inside[j] += std::abs(err[j]) <= sd[j] ? 1 : 0;
        nees[j] += err[j] * err[j] / std::max(sd[j] * sd[j], 1e-300);
      }
    }
  }
  r.samples = static_cast<long>(n);
  const double count = 4.0 * static_cast<double>(r.scored);
  if (r.scored > 0) {
    r.carcass_rms_all_K = std::sqrt(sum_carcass2 / count);
    for (int i = 0; i < 4; ++i) {
      r.carcass_rms_K[i] = std::sqrt(corner_carcass2[i] / static_cast<double>(r.scored));
    }
    r.coverage = {inside[0] / count, inside[1] / count, inside[2] / count, inside[3] / count,
                  inside[4] / count};
    r.nees = {nees[0] / count, nees[1] / count, nees[2] / count, nees[3] / count, nees[4] / count};
  }
  r.disc_missing_fraction = static_cast<double>(withheld) / static_cast<double>(disc_total);
  double nis_sum = 0.0;
  long nis_count = 0;
  for (Corner c : kAllCorners) {
    const int i = CornerIndex(c);
    const CornerEstimate e = observer.Estimate(c);
    r.wear_truth_mm[i] = truth[i][2];
    r.wear_estimate_mm[i] = e.wear;
    r.wear_sd_mm[i] = e.wear_sd;
    if (r.wear_truth_mm[i] > 0.0) {
      r.max_wear_rel_error = std::max(r.max_wear_rel_error,
                                      std::abs(e.wear - r.wear_truth_mm[i]) / r.wear_truth_mm[i]);
    }
    for (Sensor s : kAllSensors) {
      const SensorMonitor& m = observer.monitor(c, s);
      r.mean_nis[i][static_cast<int>(s)] = m.MeanNis();
      r.nis_consistent = r.nis_consistent && m.Consistent();
      if (m.used > 0) {
        ++r.sensors;
        r.sensors_consistent += m.Consistent() ? 1 : 0;
        nis_sum += m.nis_sum;
        nis_count += m.used;
      }
      r.rejected += m.rejected;
    }
  }
  r.pooled_mean_nis = nis_count > 0 ? nis_sum / static_cast<double>(nis_count) : 0.0;
  r.nis_used = nis_count;
  r.pooled_nis_bounds95 = MeanNisBounds95(nis_count);
  return r;
}

}  // namespace hotlap::observe
