#include "hotlap/race/cautions.h"

#include <cmath>
#include <random>
#include <utility>

#include <fmt/format.h>

#include "hotlap/common/error.h"

namespace hotlap::race {

CautionModel CautionModel::Off() {
  CautionModel m;
  m.rate_per_lap = 0.0;
  m.stage_cautions = false;
  return m;
}

CautionModel SouthernFiveHundredCautions() {
  CautionModel m;
  m.rate_per_lap = 6.0 / 316.0;
  m.length_laps = 6;
  return m;
}

double RaceUnderCautions(const RaceRules& r, const FallOff& f, const std::vector<PitStop>& stops,
                         const CautionModel& m, uint64_t stream, std::vector<int>* caution_starts) {
  std::mt19937_64 draw(m.seed * 0x9E3779B97F4A7C15ull + stream);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  double fuel = r.fuel_capacity_kg, time = 0.0;
  int left_age = 0, right_age = 0, caution_left = 0;
  std::vector<int> starts;
  bool first_caution_lap = false;
  bool restart = false;  // the last lap was a caution's
  size_t next = 0;
  int pending = -1;          // a stop put off from the lap pit road was closed
  int last_green_stop = -1;  // the lap a green stop was made on (none yet)
  for (int lap = 1; lap <= r.laps; ++lap) {
    // A caution comes out at random on a green lap.
    if (caution_left == 0 && m.rate_per_lap > 0.0 && uniform(draw) < m.rate_per_lap) {
      caution_left = m.length_laps;
      first_caution_lap = true;
      starts.push_back(lap);
      // A green stop made on the lap before is caught a lap down by the field.
      if (last_green_stop == lap - 1) time += f.LapTime(left_age, right_age, fuel);
    }
    const bool under_caution = caution_left > 0;
    if (under_caution) {
      time += m.lap_time_s;
      fuel -= m.fuel_share * r.fuel_per_lap_kg;
      --caution_left;
    } else {
      // The tyres and brakes a caution cooled: the laps after it, booked on the first.
      time += f.LapTime(left_age, right_age, fuel) + (restart ? f.restart_penalty_s : 0.0);
      fuel -= r.fuel_per_lap_kg;
      ++left_age;
      ++right_age;
    }
    restart = under_caution;
    const bool pit_closed = under_caution && first_caution_lap;
    first_caution_lap = false;
    const bool due = (next < stops.size() && stops[next].lap == lap) || pending >= 0;
    if (due && lap < r.laps) {
      if (pit_closed) {
        if (pending < 0) pending = static_cast<int>(next++);
      } else {
        const PitStop& stop = pending >= 0 ? stops[static_cast<size_t>(pending)] : stops[next++];
        pending = -1;
        const double added = r.fuel_capacity_kg - fuel;
        const bool cheap = under_caution || r.EndsStage(lap);
        time += (cheap ? r.caution_pit_loss_s : r.pit_loss_s) + ServiceTime(r, stop.service, added);
        if (!cheap) last_green_stop = lap;
        fuel = r.fuel_capacity_kg;
        if (stop.service != Service::kFuelOnly) right_age = 0;
        if (stop.service == Service::kFourTyresAndFuel) left_age = 0;
      }
    }
    // The stage ends: a scheduled caution from the next lap.
    if (m.stage_cautions && r.EndsStage(lap) && caution_left == 0) {
      caution_left = m.length_laps;
      first_caution_lap = false;  // the field pits on the stage's last lap's caution
      starts.push_back(lap + 1);
    }
  }
  if (caution_starts != nullptr) *caution_starts = std::move(starts);
  return time;
}

namespace {

// Welford's running mean and squares: identical values give their value and zero spread exactly.
struct RunningMean {
  int n = 0;
  double mean = 0.0, m2 = 0.0;
  void Add(double x) {
    ++n;
    const double delta = x - mean;
    mean += delta / n;
    m2 += delta * (x - mean);
  }
  double StandardError() const { return n > 1 ? std::sqrt(m2 / (n - 1) / n) : 0.0; }
};

}  // namespace

MonteCarloResult SimulatePlan(const RaceRules& r, const FallOff& f,
                              const std::vector<PitStop>& stops, const CautionModel& m, int races,
                              std::vector<double>* times) {
  CheckRaceRules(r);
  if (races < 1) throw InputError(fmt::format("Monte Carlo: {} races; at least 1", races));
  if (!(m.rate_per_lap >= 0.0 && m.rate_per_lap <= 1.0)) {
    throw InputError(fmt::format("caution rate {:g} per lap must be in [0, 1]", m.rate_per_lap));
  }
  MonteCarloResult out;
  out.races = races;
  RunningMean time;
  double caution_sum = 0.0;
  std::vector<int> starts;
  if (times != nullptr) times->clear();
  for (int i = 0; i < races; ++i) {
    const double t = RaceUnderCautions(r, f, stops, m, static_cast<uint64_t>(i), &starts);
    time.Add(t);
    if (times != nullptr) times->push_back(t);
    caution_sum += static_cast<double>(starts.size());
    if (out.caution_histogram.size() <= starts.size()) {
      out.caution_histogram.resize(starts.size() + 1);
    }
    ++out.caution_histogram[starts.size()];
  }
  out.mean_time_s = time.mean;
  out.standard_error_s = time.StandardError();
  out.mean_cautions = caution_sum / races;
  return out;
}

MonteCarloResult GainOver(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size() || a.empty()) {
    throw InputError(
        fmt::format("a paired gain needs the same races: {} and {}", a.size(), b.size()));
  }
  RunningMean gain;
  for (size_t i = 0; i < a.size(); ++i) gain.Add(b[i] - a[i]);
  MonteCarloResult out;
  out.races = static_cast<int>(a.size());
  out.mean_time_s = gain.mean;
  out.standard_error_s = gain.StandardError();
  return out;
}

}  // namespace hotlap::race
