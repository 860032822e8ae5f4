#include "hotlap/race/race_plan.h"
#include "hotlap/common/special_values.h"

#include <algorithm>
#include <cstdint>
#include <limits>

#include <fmt/format.h>

#include "hotlap/common/enum_names.h"
#include "hotlap/common/error.h"

namespace hotlap::race {

namespace {

double FuelMass(const RaceRules& r, int laps_left) { return r.FuelAboard(laps_left); }

}  // namespace

namespace {

constexpr EnumNames<Service, 3> kServiceNames{
    {{{Service::kFourTyresAndFuel, "four tyres and fuel"},
      {Service::kRightTyresAndFuel, "right-side tyres and fuel"},
      {Service::kFuelOnly, "fuel only"}}}};
constexpr EnumNames<Service, 3> kServiceMarks{{{{Service::kFourTyresAndFuel, ""},
                                                {Service::kRightTyresAndFuel, "r"},
                                                {Service::kFuelOnly, "f"}}}};

}  // namespace

const char* ServiceName(Service service) { return kServiceNames.Name(service); }

const char* ServiceMark(Service service) { return kServiceMarks.Name(service); }

double ServiceTime(const RaceRules& r, Service service, double fuel_added_kg) {
  const double fuel = fuel_added_kg / r.fuel_rate_kg_per_s;
  switch (service) {
    case Service::kFourTyresAndFuel:
      return std::max(r.tyre_service_s, fuel);
    case Service::kRightTyresAndFuel:
      return std::max(r.right_tyre_service_s, fuel);
    case Service::kFuelOnly:
      break;
  }
  return fuel;
}

double StopTime(const RaceRules& r, int lap, Service service, double fuel_added_kg) {
  return (r.EndsStage(lap) ? r.caution_pit_loss_s : r.pit_loss_s) +
         ServiceTime(r, service, fuel_added_kg);
}

RacePlan EvaluatePlan(const RaceRules& r, const FallOff& f, const std::vector<PitStop>& stops,
                      std::string name) {
  CheckRaceRules(r);
  const int window = r.FuelWindow();
  RacePlan plan;
  plan.name = std::move(name);
  plan.tyre_sets_used = 1;
  int left_age = 0, right_age = 0, fuel = window;
  size_t next = 0;
  for (int lap = 1; lap <= r.laps; ++lap) {
    if (fuel < 1) {
      throw InputError(fmt::format("plan '{}': the fuel runs out on lap {}", plan.name, lap));
    }
    const double t = f.LapTime(left_age, right_age, FuelMass(r, fuel));
    plan.lap_time_s.push_back(t);
    plan.race_time_s += t;
    ++left_age;
    ++right_age;
    --fuel;
    if (next < stops.size() && stops[next].lap == lap) {
      if (lap >= r.laps)
        throw InputError(fmt::format("plan '{}': a stop after the race", plan.name));
      PitStop stop = stops[next++];
      if (stop.service == Service::kRightTyresAndFuel && !r.right_side_stops) {
        throw InputError(
            fmt::format("plan '{}': a right-side stop after lap {}; the rules change four tyres",
                        plan.name, lap));
      }
      stop.time_lost_s = StopTime(r, lap, stop.service, (window - fuel) * r.fuel_per_lap_kg);
      plan.race_time_s += stop.time_lost_s;
      fuel = window;
      if (stop.service != Service::kFuelOnly) {
        right_age = 0;
        if (stop.service == Service::kFourTyresAndFuel) left_age = 0;
        ++plan.tyre_sets_used;
      }
      plan.stops.push_back(stop);
    }
  }
  if (next != stops.size()) {
    throw InputError(
        fmt::format("plan '{}': stops out of lap order or outside the race", plan.name));
  }
  if (plan.tyre_sets_used > r.tyre_sets) {
    throw InputError(fmt::format("plan '{}' uses {} tyre sets; the rules allow {}", plan.name,
                                 plan.tyre_sets_used, r.tyre_sets));
  }
  return plan;
}

RacePlan OptimalPlan(const RaceRules& r, const FallOff& f) {
  CheckRaceRules(r);
  if (r.right_side_stops) return OptimalPlanWithRightSideStops(r, f);
  const int n = r.laps, window = r.FuelWindow(), sets = r.tyre_sets;
  // State after lap l, before the decision: age a in [1, l] (laps on the set), fuel f in
  // [0, window] (laps of it left), sets used s in [1, sets]. value[a][f][s]: the least time of
  // the stops and laps still to come.
  const size_t na = static_cast<size_t>(n) + 1, nf = static_cast<size_t>(window) + 1,
               ns = static_cast<size_t>(sets) + 1;
  const auto index = [&](int a, int fu, int s) {
    return (static_cast<size_t>(a) * nf + static_cast<size_t>(fu)) * ns + static_cast<size_t>(s);
  };
  std::vector<double> next_value(na * nf * ns, 0.0), value(na * nf * ns, kInf);
  // decision[l]: 0 stay, 1 fuel only, 2 four tyres and fuel; 255 none possible.
  std::vector<std::vector<uint8_t>> decision(static_cast<size_t>(n) + 1);
  const auto lap_time = [&](int age, int fuel) { return f.LapTime(age, FuelMass(r, fuel)); };
  for (int l = n; l >= 1; --l) {
    std::fill(value.begin(), value.end(), kInf);
    std::vector<uint8_t>& choice = decision[static_cast<size_t>(l)];
    choice.assign(static_cast<size_t>(l + 1) * nf * ns, 255);  // ages 0 to l
    for (int a = 1; a <= l; ++a) {
      for (int fu = 0; fu <= window; ++fu) {
        for (int s = 1; s <= sets; ++s) {
          const size_t i = index(a, fu, s);
          if (l == n) {
            value[i] = 0.0;
            choice[i] = 0;
            continue;
          }
          double best = kInf;
          uint8_t pick = 255;
          // Run the next lap from (age, fuel, sets) after a stop costing `stop`.
          const auto run_on = [&](int age, int fuel, int used, double stop, uint8_t d) {
            if (fuel < 1 || used > sets) return;
            const double v =
                stop + lap_time(age, fuel) + next_value[index(age + 1, fuel - 1, used)];
            if (v < best) {
              best = v;
              pick = d;
            }
          };
          const double fill = (window - fu) * r.fuel_per_lap_kg;
          run_on(a, fu, s, 0.0, 0);
          run_on(a, window, s, StopTime(r, l, Service::kFuelOnly, fill), 1);
          run_on(0, window, s + 1, StopTime(r, l, Service::kFourTyresAndFuel, fill), 2);
          value[i] = best;
          choice[i] = pick;
        }
      }
    }
    std::swap(value, next_value);
  }
  // Forward: lap 1 on the starting set, a full cell; then the decisions.
  std::vector<PitStop> stops;
  int age = 1, fuel = window - 1, used = 1;
  for (int l = 1; l < n; ++l) {
    const uint8_t d = decision[static_cast<size_t>(l)][index(age, fuel, used)];
    if (d == 255) throw InputError("race plan: no plan meets the rules (fuel or tyre sets)");
    if (d == 1) {
      stops.push_back({l, Service::kFuelOnly, 0.0});
      fuel = window;
    } else if (d == 2) {
      stops.push_back({l, Service::kFourTyresAndFuel, 0.0});
      fuel = window;
      age = 0;
      ++used;
    }
    ++age;
    --fuel;
  }
  return EvaluatePlan(r, f, stops, "optimal");
}

std::vector<RacePlan> FixedPlans(const RaceRules& r, const FallOff& f) {
  CheckRaceRules(r);
  const int window = r.FuelWindow();
  std::vector<RacePlan> plans;
  const auto add = [&](const std::vector<PitStop>& stops, const char* name) {
    try {
      plans.push_back(EvaluatePlan(r, f, stops, name));
    } catch (const InputError&) {
      // Not within the rules (too many tyre sets): not a plan to compare with.
    }
  };
  // Four tyres and fuel as late as the fuel allows.
  std::vector<PitStop> late;
  for (int lap = window; lap < r.laps; lap += window)
    late.push_back({lap, Service::kFourTyresAndFuel, 0.0});
  add(late, "fuel windows");
  if (r.right_side_stops) {
    std::vector<PitStop> alternate = late;
    for (size_t i = 0; i < alternate.size(); i += 2)
      alternate[i].service = Service::kRightTyresAndFuel;
    add(alternate, "rights between");
  }
  // A stop at each stage end (its cheap caution), and between them, and after the last, the
  // fewest stops the fuel allows, evenly spaced.
  std::vector<PitStop> stages;
  std::vector<int> bounds = {0};
  for (int end : r.stage_ends) bounds.push_back(end);
  bounds.push_back(r.laps);
  for (size_t i = 0; i + 1 < bounds.size(); ++i) {
    const int from = bounds[i], length = bounds[i + 1] - bounds[i];
    const int runs = (length + window - 1) / window;  // runs of at most a window each
    for (int k = 1; k < runs; ++k) {
      stages.push_back({from + (k * length + runs - 1) / runs, Service::kFourTyresAndFuel, 0.0});
    }
    if (i + 1 < bounds.size() - 1)
      stages.push_back({bounds[i + 1], Service::kFourTyresAndFuel, 0.0});
  }
  add(stages, "stage ends");
  return plans;
}

}  // namespace hotlap::race
