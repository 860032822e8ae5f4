#include "hotlap/race/race_policy.h"
#include "hotlap/common/special_values.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include <fmt/format.h>

#include "hotlap/common/error.h"

namespace hotlap::race {

namespace {

// The states (age, fuel units, sets used) of one lap as a flat array.
struct StateGrid {
  int ages = 0, fuels = 0, sets = 0;
  size_t size() const { return static_cast<size_t>(ages) * fuels * sets; }
  size_t operator()(int a, int f, int s) const {
    return (static_cast<size_t>(a) * fuels + static_cast<size_t>(f)) * sets +
           static_cast<size_t>(s - 1);
  }
};

// The programme's tables and the costs every lap shares.
class PolicySolver {
 public:
  PolicySolver(const RaceRules& r, const FallOff& f, const CautionModel& m, RacePolicy& p)
      : r_(r), m_(m), p_(p), restart_penalty_(f.restart_penalty_s) {
    grid_ = {p.max_age + 1, p.fuel_units + 1, r.tyre_sets};
    lap_time_.resize(static_cast<size_t>(grid_.ages) * grid_.fuels);
    for (int a = 0; a < grid_.ages; ++a) {
      for (int u = 0; u < grid_.fuels; ++u) LapTimeAt(a, u) = f.LapTime(a, p.FuelMass(u));
    }
    ring_.assign(static_cast<size_t>(m.length_laps) + 1, std::vector<double>(grid_.size(), 0.0));
    green_value_.assign(grid_.size(), 0.0);
    caution_value_.assign(grid_.size(), 0.0);
  }

  double Solve() {
    const int n = r_.laps;
    for (int l = n; l >= 0; --l) {
      if (l < n) CautionFrom(l + 1);
      EnterLap(l);
      if (l >= 1) GreenDecisions(l);
    }
    return Enter(0)[grid_(0, p_.fuel_units, 1)];
  }

 private:
  double& LapTimeAt(int a, int u) { return lap_time_[static_cast<size_t>(a) * grid_.fuels + u]; }
  double LapTime(int a, int u) const { return lap_time_[static_cast<size_t>(a) * grid_.fuels + u]; }
  std::vector<double>& Enter(int l) { return ring_[static_cast<size_t>(l) % ring_.size()]; }
  double FuelService(int units) const {
    return (p_.fuel_units - units) * r_.fuel_per_lap_kg / p_.green_burn / r_.fuel_rate_kg_per_s;
  }
  double TyreService(int units) const { return std::max(r_.tyre_service_s, FuelService(units)); }
  bool Scheduled(int l) const { return m_.stage_cautions && l >= 1 && r_.EndsStage(l); }

  // caution_value_: the expected time from the start of a caution on lap m (m <= laps), its
  // laps, the decision on its first open lap (m + 1) and what follows its last lap.
  void CautionFrom(int m) {
    const int n = r_.laps, e = std::min(m + m_.length_laps - 1, n), laps = e - m + 1;
    // The laps, and the cooled tyres' restart where a green lap follows (not at the finish, nor
    // before a stage end's caution).
    const double restart =
        e < n && !Scheduled(e) ? (1.0 - m_.rate_per_lap) * restart_penalty_ : 0.0;
    const double time = laps * m_.lap_time_s + restart;
    const int c = p_.caution_burn;
    const std::vector<double>& after = Enter(e);
    const bool decides = m + 1 <= e && m + 1 < n;
    const int rest = decides ? e - m - 1 : 0;  // caution laps after the decision
    const double loss = r_.caution_pit_loss_s;
    for (int a = 0; a < grid_.ages; ++a) {
      for (int f = 0; f < grid_.fuels; ++f) {
        for (int s = 1; s <= grid_.sets; ++s) {
          const size_t i = grid_(a, f, s);
          if (!decides) {
            const int left = f - laps * c;
            caution_value_[i] = left < 0 ? kInf : time + (e == n ? 0.0 : after[grid_(a, left, s)]);
            continue;
          }
          const int f1 = f - 2 * c;  // the laps m and m + 1; the decision is kept by it
          if (f1 < 0) {
            caution_value_[i] = kInf;
            continue;
          }
          const auto tail = [&](int age, int fuel, int sets) {
            const int left = fuel - rest * c;
            if (left < 0) return kInf;
            return e == n ? 0.0 : after[grid_(age, left, sets)];
          };
          double best = tail(a, f1, s);
          Decision pick = std::isfinite(best) ? Decision::kStayOut : Decision::kNone;
          const double fuel_only = loss + FuelService(f1) + tail(a, p_.fuel_units, s);
          if (fuel_only < best) best = fuel_only, pick = Decision::kFuelOnly;
          if (s < grid_.sets) {
            const double four = loss + TyreService(f1) + tail(0, p_.fuel_units, s + 1);
            if (four < best) best = four, pick = Decision::kFourTyresAndFuel;
          }
          caution_value_[i] = time + best;
          p_.caution.Set(m, a, f1, s, pick);
        }
      }
    }
  }

  // Enter(l): the expected time of laps l + 1 on from the state after lap l's decision (no green
  // stop on lap l; the caught stop's lap is added where one was made).
  void EnterLap(int l) {
    std::vector<double>& out = Enter(l);
    if (l == r_.laps) {
      std::fill(out.begin(), out.end(), 0.0);
      return;
    }
    const double p = m_.rate_per_lap;
    const bool scheduled = Scheduled(l);
    const int g = p_.green_burn;
    for (int a = 0; a < grid_.ages; ++a) {
      for (int f = 0; f < grid_.fuels; ++f) {
        for (int s = 1; s <= grid_.sets; ++s) {
          const size_t i = grid_(a, f, s);
          if (scheduled) {
            out[i] = caution_value_[i];
            continue;
          }
          double v = 0.0;
          if (p < 1.0) {
            const bool runs = f >= g && a + 1 < grid_.ages;
            const double green =
                runs ? LapTime(a, f) +
                           (l + 1 == r_.laps ? 0.0 : green_value_[grid_(a + 1, f - g, s)])
                     : kInf;
            v += (1.0 - p) * green;
          }
          if (p > 0.0) v += p * caution_value_[i];
          out[i] = v;
        }
      }
    }
  }

  // green_value_ at lap l: the best of staying out, fuel only and four tyres at its end.
  void GreenDecisions(int l) {
    const std::vector<double>& enter = Enter(l);
    const int n = r_.laps;
    if (l == n) {
      std::fill(green_value_.begin(), green_value_.end(), 0.0);
      return;
    }
    const bool cheap = r_.EndsStage(l);
    const double loss = cheap ? r_.caution_pit_loss_s : r_.pit_loss_s;
    // A green stop that the next lap's caution catches runs that lap again.
    const double caught = cheap ? 0.0 : m_.rate_per_lap;
    const int full = p_.fuel_units;
    for (int a = 0; a < grid_.ages; ++a) {
      for (int f = 0; f < grid_.fuels; ++f) {
        for (int s = 1; s <= grid_.sets; ++s) {
          const size_t i = grid_(a, f, s);
          double best = enter[i];
          Decision pick = std::isfinite(best) ? Decision::kStayOut : Decision::kNone;
          const double fuel_only = loss + FuelService(f) + enter[grid_(a, full, s)] +
                                   (caught > 0.0 ? caught * LapTime(a, full) : 0.0);
          if (fuel_only < best) best = fuel_only, pick = Decision::kFuelOnly;
          if (s < grid_.sets) {
            const double four = loss + TyreService(f) + enter[grid_(0, full, s + 1)] +
                                (caught > 0.0 ? caught * LapTime(0, full) : 0.0);
            if (four < best) best = four, pick = Decision::kFourTyresAndFuel;
          }
          green_value_[i] = best;
          p_.green.Set(l, a, f, s, pick);
        }
      }
    }
  }

  const RaceRules& r_;
  const CautionModel& m_;
  RacePolicy& p_;
  double restart_penalty_;
  StateGrid grid_;
  std::vector<double> lap_time_;
  std::vector<std::vector<double>> ring_;  // Enter(l) for the caution's length ahead
  std::vector<double> green_value_;        // at the lap after the one being computed
  std::vector<double> caution_value_;      // a caution from the lap after
};

}  // namespace

DecisionTable::DecisionTable(int laps, int ages, int fuels, int sets)
    : ages_(ages), fuels_(fuels), sets_(sets) {
  const size_t states = static_cast<size_t>(laps + 1) * ages * fuels * sets;
  bits_.assign((states + 3) / 4, 0xFF);  // kNone everywhere
}

size_t DecisionTable::Index(int lap, int age, int fuel, int sets_used) const {
  return ((static_cast<size_t>(lap) * ages_ + static_cast<size_t>(age)) * fuels_ +
          static_cast<size_t>(fuel)) *
             sets_ +
         static_cast<size_t>(sets_used - 1);
}

Decision DecisionTable::At(int lap, int age, int fuel, int sets_used) const {
  if (age < 0 || age >= ages_ || fuel < 0 || fuel >= fuels_ || sets_used < 1 || sets_used > sets_) {
    return Decision::kNone;
  }
  const size_t i = Index(lap, age, fuel, sets_used);
  if (i / 4 >= bits_.size()) return Decision::kNone;
  return static_cast<Decision>((bits_[i / 4] >> (2 * (i % 4))) & 3u);
}

void DecisionTable::Set(int lap, int age, int fuel, int sets_used, Decision d) {
  const size_t i = Index(lap, age, fuel, sets_used);
  const int shift = static_cast<int>(2 * (i % 4));
  bits_[i / 4] =
      static_cast<uint8_t>((bits_[i / 4] & ~(3u << shift)) | (static_cast<unsigned>(d) << shift));
}

double RacePolicy::FuelMass(int units) const {
  return rules.fuel_capacity_kg - (fuel_units - units) * rules.fuel_per_lap_kg / green_burn;
}

void CheckPolicyOptions(const PolicyOptions& o) {
  if (o.fuel_units_per_lap < 1 || o.fuel_units_per_lap > 10) {
    throw InputError(
        fmt::format("race policy: {} fuel units a lap must be in [1, 10]", o.fuel_units_per_lap));
  }
  if (o.max_tyre_age < 0) {
    throw InputError(fmt::format("race policy: tyre age cap {} must be >= 0", o.max_tyre_age));
  }
}

RacePolicy SolvePolicy(const RaceRules& r, const FallOff& f, const CautionModel& m,
                       const PolicyOptions& o) {
  CheckRaceRules(r);
  CheckPolicyOptions(o);
  if (!(m.rate_per_lap >= 0.0 && m.rate_per_lap <= 1.0) || m.length_laps < 1 ||
      !(m.fuel_share >= 0.0 && m.fuel_share <= 1.0) || !(m.lap_time_s > 0.0)) {
    throw InputError(fmt::format(
        "race policy: cautions need a rate in [0, 1], at least one lap, a fuel share in [0, 1] "
        "and a lap time > 0 (rate {:g}, {} laps, share {:g}, {:g} s)",
        m.rate_per_lap, m.length_laps, m.fuel_share, m.lap_time_s));
  }
  RacePolicy p;
  p.rules = r;
  p.cautions = m;
  p.options = o;
  p.green_burn = o.fuel_units_per_lap;
  p.caution_burn = static_cast<int>(std::ceil(m.fuel_share * o.fuel_units_per_lap - 1e-9));
  p.fuel_units =
      static_cast<int>(std::floor(r.fuel_capacity_kg / r.fuel_per_lap_kg * p.green_burn + 1e-9));
  p.max_age = o.max_tyre_age > 0 ? o.max_tyre_age : std::min(r.laps, 2 * r.FuelWindow());
  p.green = DecisionTable(r.laps, p.max_age + 1, p.fuel_units + 1, r.tyre_sets);
  p.caution = DecisionTable(r.laps, p.max_age + 1, p.fuel_units + 1, r.tyre_sets);
  PolicySolver solver(r, f, m, p);
  p.expected_time_s = solver.Solve();
  if (!std::isfinite(p.expected_time_s)) {
    throw InputError("race policy: no policy keeps to the fuel and the tyre sets");
  }
  return p;
}

PolicyRace RaceWithPolicy(const RacePolicy& p, const FallOff& f, uint64_t stream) {
  const RaceRules& r = p.rules;
  const CautionModel& m = p.cautions;
  std::mt19937_64 draw(m.seed * 0x9E3779B97F4A7C15ull + stream);  // as RaceUnderCautions
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  PolicyRace race;
  int age = 0, fuel = p.fuel_units, caution_left = 0, caution_start = -1, last_green_stop = -1;
  bool restart = false;  // the last lap was a caution's
  const auto lap_time = [&](int a, int u) { return f.LapTime(a, p.FuelMass(u)); };
  for (int lap = 1; lap <= r.laps; ++lap) {
    if (caution_left == 0 && m.rate_per_lap > 0.0 && uniform(draw) < m.rate_per_lap) {
      caution_left = m.length_laps;
      caution_start = lap;
      race.caution_starts.push_back(lap);
      if (last_green_stop == lap - 1) race.time_s += lap_time(age, fuel);
    }
    const bool under = caution_left > 0;
    if (under) {
      race.time_s += m.lap_time_s;
      fuel -= p.caution_burn;
      --caution_left;
    } else {
      race.time_s += lap_time(age, fuel) + (restart ? f.restart_penalty_s : 0.0);
      fuel -= p.green_burn;
      ++age;
      race.longest_set_laps = std::max(race.longest_set_laps, age);
    }
    restart = under;
    if (fuel < 0 || age > p.max_age) {  // the programme's states keep to both: a bug if not
      throw std::logic_error(
          fmt::format("race policy: lap {} left fuel {} units, age {}", lap, fuel, age));
    }
    if (lap < r.laps && (!under || lap == caution_start + 1)) {
      const Decision d = under ? p.caution.At(caution_start, age, fuel, race.tyre_sets_used)
                               : p.green.At(lap, age, fuel, race.tyre_sets_used);
      if (d == Decision::kNone) {
        throw InputError(
            fmt::format("race policy: no decision for lap {} (age {}, fuel {})", lap, age, fuel));
      }
      if (d != Decision::kStayOut) {
        const bool cheap = under || r.EndsStage(lap);
        const double fill = (p.fuel_units - fuel) * r.fuel_per_lap_kg / p.green_burn;
        const double fuel_s = fill / r.fuel_rate_kg_per_s;
        race.time_s +=
            (cheap ? r.caution_pit_loss_s : r.pit_loss_s) +
            (d == Decision::kFourTyresAndFuel ? std::max(r.tyre_service_s, fuel_s) : fuel_s);
        if (!cheap) last_green_stop = lap;
        fuel = p.fuel_units;
        ++race.stops;
        if (d == Decision::kFourTyresAndFuel) {
          age = 0;
          ++race.tyre_sets_used;
        }
      }
    }
    if (m.stage_cautions && r.EndsStage(lap) && caution_left == 0) {
      caution_left = m.length_laps;
      caution_start = lap + 1;
      race.caution_starts.push_back(lap + 1);
    }
  }
  return race;
}

MonteCarloResult SimulatePolicy(const RacePolicy& p, const FallOff& f, int races,
                                std::vector<double>* times, PolicyRaceStats* stats) {
  if (races < 1) throw InputError(fmt::format("Monte Carlo: {} races; at least 1", races));
  std::vector<double> all;
  all.reserve(static_cast<size_t>(races));
  MonteCarloResult out;
  out.races = races;
  double cautions = 0.0, stops = 0.0;
  PolicyRaceStats found;
  for (int i = 0; i < races; ++i) {
    const PolicyRace race = RaceWithPolicy(p, f, static_cast<uint64_t>(i));
    all.push_back(race.time_s);
    stops += race.stops;
    found.longest_set_laps = std::max(found.longest_set_laps, race.longest_set_laps);
    found.most_tyre_sets = std::max(found.most_tyre_sets, race.tyre_sets_used);
    cautions += static_cast<double>(race.caution_starts.size());
    if (out.caution_histogram.size() <= race.caution_starts.size()) {
      out.caution_histogram.resize(race.caution_starts.size() + 1);
    }
    ++out.caution_histogram[race.caution_starts.size()];
  }
  // The mean and its standard error of the times, as GainOver makes them against zero.
  const MonteCarloResult mean = GainOver(std::vector<double>(all.size(), 0.0), all);
  out.mean_time_s = mean.mean_time_s;
  out.standard_error_s = mean.standard_error_s;
  out.mean_cautions = cautions / races;
  found.mean_stops = stops / races;
  if (stats != nullptr) *stats = found;
  if (times != nullptr) *times = std::move(all);
  return out;
}

Decision CautionDecision(const RacePolicy& p, int lap, int age, int laps_since_fill,
                         int sets_used) {
  const int fuel = p.fuel_units - laps_since_fill * p.green_burn - 2 * p.caution_burn;
  if (lap < 1 || lap > p.rules.laps) return Decision::kNone;
  return p.caution.At(lap, age, fuel, sets_used);
}

const char* DecisionName(Decision d) {
  switch (d) {
    case Decision::kStayOut:
      return "stay out";
    case Decision::kFuelOnly:
      return "fuel only";
    case Decision::kFourTyresAndFuel:
      return "four tyres and fuel";
    case Decision::kNone:
      break;
  }
  return "none";
}

}  // namespace hotlap::race
