// The race plan with right-side stops among the services: a dynamic programme over the left and
// right tyres' ages and the fuel, the tyre sets priced by a Lagrange multiplier (docs/race.md).

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/common/special_values.h"
#include "hotlap/race/race_plan.h"

namespace hotlap::race {

namespace {

enum Choice : uint8_t { kStay = 0, kFuel = 1, kFour = 2, kRight = 3 };

// The ages as a pair (left, right), right <= left <= max: a triangle, indexed row by row.
size_t Pair(int left, int right) {
  return static_cast<size_t>(left) * static_cast<size_t>(left + 1) / 2 + static_cast<size_t>(right);
}

// Two bits a state: the decisions of one lap.
struct LapChoices {
  std::vector<uint8_t> bits;
  void Resize(size_t states) { bits.assign((states + 3) / 4, 0); }
  void Set(size_t i, Choice c) {
    bits[i / 4] = static_cast<uint8_t>(bits[i / 4] | (c << (2 * (i % 4))));
  }
  Choice Get(size_t i) const { return static_cast<Choice>((bits[i / 4] >> (2 * (i % 4))) & 3); }
};

struct Programme {
  const RaceRules& r;
  int max_age, window;
  std::vector<double> lap_s;        // [Pair(left, right)]: the lap at the reference fuel
  std::vector<double> fuel_s;       // [laps of fuel left]: the fuel's weight on the lap
  std::vector<LapChoices> choices;  // [lap]: after it, the decision per state
  double value = kInf;              // the race's time with the sets' price, from the green flag

  Programme(const RaceRules& rules, const FallOff& f, int max_tyre_age)
      : r(rules), max_age(max_tyre_age), window(rules.FuelWindow()) {
    lap_s.resize(Pair(max_age, max_age) + 1);
    for (int a = 0; a <= max_age; ++a) {
      for (int b = 0; b <= a; ++b) lap_s[Pair(a, b)] = f.LapTime(a, b, f.reference_fuel_kg);
    }
    for (int u = 0; u <= window; ++u) {
      fuel_s.push_back(f.fuel_s_per_kg * (r.FuelAboard(u) - f.reference_fuel_kg));
    }
  }

  size_t State(int left, int right, int fuel) const {
    return Pair(left, right) * static_cast<size_t>(window + 1) + static_cast<size_t>(fuel);
  }

  // The backward sweep with `price` seconds charged for every new set of right sides.
  void Solve(double price) {
    const int n = r.laps;
    const size_t states = State(max_age, max_age, window) + 1;
    std::vector<double> next(states, 0.0), now(states, kInf);
    choices.assign(static_cast<size_t>(n) + 1, {});
    for (int l = n; l >= 1; --l) {
      const int top = std::min(l, max_age);
      LapChoices& choice = choices[static_cast<size_t>(l)];
      choice.Resize(State(top, top, window) + 1);
      std::fill(now.begin(), now.end(), kInf);
      for (int a = 1; a <= top; ++a) {
        for (int b = 1; b <= a; ++b) {
          for (int u = 0; u <= window; ++u) {
            const size_t i = State(a, b, u);
            if (l == n) {
              now[i] = 0.0;
              continue;
            }
            double best = kInf;
            Choice pick = kStay;
            // The next lap on tyres (left, right) with `fuel` laps of fuel after a stop of `stop`.
            const auto run_on = [&](int left, int right, int fuel, double stop, Choice c) {
              if (fuel < 1 || left + 1 > max_age) return;
              const double v = stop + lap_s[Pair(left, right)] + fuel_s[fuel] +
                               next[State(left + 1, right + 1, fuel - 1)];
              if (v < best) {
                best = v;
                pick = c;
              }
            };
            const double fill = (window - u) * r.fuel_per_lap_kg;
            run_on(a, b, u, 0.0, kStay);
            run_on(a, b, window, StopTime(r, l, Service::kFuelOnly, fill), kFuel);
            run_on(0, 0, window, StopTime(r, l, Service::kFourTyresAndFuel, fill) + price, kFour);
            run_on(a, 0, window, StopTime(r, l, Service::kRightTyresAndFuel, fill) + price, kRight);
            now[i] = best;
            choice.Set(i, pick);
          }
        }
      }
      std::swap(now, next);
    }
    value = kInf;
    if (n == 1 || next[State(1, 1, window - 1)] < kInf) {
      value = lap_s[Pair(0, 0)] + fuel_s[window] + (n == 1 ? 0.0 : next[State(1, 1, window - 1)]);
    }
  }

  // The stops the last Solve chose, from the green flag.
  std::vector<PitStop> Stops() const {
    std::vector<PitStop> stops;
    int left = 1, right = 1, fuel = window - 1;
    for (int l = 1; l < r.laps; ++l) {
      const Choice c = choices[static_cast<size_t>(l)].Get(State(left, right, fuel));
      if (c == kFuel) stops.push_back({l, Service::kFuelOnly, 0.0});
      if (c == kFour) stops.push_back({l, Service::kFourTyresAndFuel, 0.0});
      if (c == kRight) stops.push_back({l, Service::kRightTyresAndFuel, 0.0});
      if (c != kStay) fuel = window;
      if (c == kFour) left = 0;
      if (c == kFour || c == kRight) right = 0;
      ++left;
      ++right;
      --fuel;
    }
    return stops;
  }
};

int SetsOf(const std::vector<PitStop>& stops) {
  int sets = 1;
  for (const PitStop& s : stops) sets += s.service != Service::kFuelOnly;
  return sets;
}

}  // namespace

RacePlan OptimalPlanWithRightSideStops(const RaceRules& r, const FallOff& f, int max_tyre_age) {
  CheckRaceRules(r);
  if (!f.HasSides()) {
    throw InputError("race plan with right-side stops: the fall-off has no left-wear laps");
  }
  const int window = r.FuelWindow();
  const int max_age = max_tyre_age > 0 ? max_tyre_age : std::min(r.laps, 2 * window);
  if (max_age < 1 || max_age > 400) {
    throw InputError(fmt::format("race plan: tyre age cap {} must be in [1, 400]", max_age));
  }
  Programme p(r, f, max_age);
  // Any plan within the sets takes at least value(price) - price (sets - 1) for every price >= 0
  // (the Lagrangian bound); at price 0 it is the least time with the sets free.
  double bound = -kInf;
  const auto solve = [&](double price) {
    p.Solve(price);
    if (!(p.value < kInf)) throw InputError("race plan: no plan meets the rules (fuel)");
    bound = std::max(bound, p.value - price * (r.tyre_sets - 1));
    return p.Stops();
  };
  std::vector<PitStop> stops = solve(0.0);
  const bool binding = SetsOf(stops) > r.tyre_sets;
  if (binding) {
    // The sets bind: the least price per set at which the plan keeps to them, bisected.
    double low = 0.0, high = 1.0;
    for (stops = solve(high); SetsOf(stops) > r.tyre_sets; stops = solve(high)) {
      low = high;
      high *= 2.0;
      if (high > 1e6) throw InputError("race plan: no plan meets the rules (tyre sets)");
    }
    for (int k = 0; k < 12; ++k) {
      const double mid = 0.5 * (low + high);
      std::vector<PitStop> s = solve(mid);
      if (SetsOf(s) <= r.tyre_sets) {
        high = mid;
        stops = std::move(s);
      } else {
        low = mid;
      }
    }
  }
  RacePlan plan = EvaluatePlan(r, f, stops, "optimal");
  // Free sets: exact (the gap only round-off).
  plan.optimality_gap_s = binding ? std::max(0.0, plan.race_time_s - bound) : 0.0;
  return plan;
}

}  // namespace hotlap::race
