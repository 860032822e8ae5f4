#include "hotlap/race/plan_runs.h"

#include <algorithm>

namespace hotlap::race {

namespace {

bool IsLeft(size_t corner) { return corner == 0 || corner == 2; }  // fl, rl

// Corner k's state at `age` laps on its tyre.
void TakeCorner(const FallOff& f, size_t k, int age, SetLap& out) {
  const int n = static_cast<int>(f.set_laps.size());
  const SetLap& at = f.set_laps[std::clamp(age, 0, n - 1)];
  out.tread_temp[k] = at.tread_temp[k];
  out.carcass_temp[k] = at.carcass_temp[k];
  out.disc_peak_temp[k] = at.disc_peak_temp[k];
  out.pressure[k] = at.pressure[k];
  out.wear_mm[k] = at.wear_mm[k];
  if (age >= n) {
    // The wear carried on at the last ten laps' rate.
    const int span = std::min(10, n - 1);
    const double rate =
        span > 0 ? (f.set_laps[n - 1].wear_mm[k] - f.set_laps[n - 1 - span].wear_mm[k]) / span
                 : 0.0;
    out.wear_mm[k] += rate * (age - (n - 1));
  }
}

}  // namespace

std::vector<SetLap> PlanLapStates(const RacePlan& plan, const FallOff& f) {
  std::vector<SetLap> laps;
  if (f.set_laps.empty()) return laps;
  int left = 0, right = 0;
  size_t next = 0;
  for (size_t lap = 1; lap <= plan.lap_time_s.size(); ++lap) {
    SetLap s;
    for (size_t k = 0; k < 4; ++k) TakeCorner(f, k, IsLeft(k) ? left : right, s);
    laps.push_back(s);
    ++left;
    ++right;
    if (next < plan.stops.size() && plan.stops[next].lap == static_cast<int>(lap)) {
      const Service service = plan.stops[next++].service;
      if (service != Service::kFuelOnly) right = 0;
      if (service == Service::kFourTyresAndFuel) left = 0;
    }
  }
  return laps;
}

std::vector<PlanRun> PlanRuns(const RacePlan& plan, const std::vector<SetLap>& laps) {
  std::vector<PlanRun> runs;
  if (laps.empty()) return runs;
  PlanRun run;
  run.first_lap = 1;
  const auto close = [&](int last) {
    run.last_lap = last;
    const SetLap& end = laps[static_cast<size_t>(last - 1)];
    run.wear_mm = end.wear_mm;
    run.end_pressure = end.pressure;
    for (int l = run.first_lap; l <= last; ++l) {
      const SetLap& s = laps[static_cast<size_t>(l - 1)];
      for (size_t k = 0; k < 4; ++k) {
        run.peak_tread_temp[k] = std::max(run.peak_tread_temp[k], s.tread_temp[k]);
        run.peak_carcass_temp[k] = std::max(run.peak_carcass_temp[k], s.carcass_temp[k]);
        run.peak_disc_temp[k] = std::max(run.peak_disc_temp[k], s.disc_peak_temp[k]);
      }
    }
    runs.push_back(run);
  };
  for (const PitStop& stop : plan.stops) {
    if (stop.service == Service::kFuelOnly) continue;
    close(stop.lap);
    run = PlanRun{};
    run.first_lap = stop.lap + 1;
    run.fitted = stop.service;
  }
  close(static_cast<int>(laps.size()));
  return runs;
}

}  // namespace hotlap::race
