#pragma once
/// @file
/// The race policy: what to do at the end of every lap, green or under caution, for every tyre
/// age, fuel and tyre sets used, chosen by a stochastic dynamic programme with the caution in its
/// state, to the least expected race time (docs/race.md). Where a plan fixes its stops before the
/// green flag, the policy answers "pit or stay out?" as the race unfolds.
///
/// The race it plays is RaceUnderCautions' (cautions.h): a random caution comes out at the start
/// of a green lap with the model's rate, a scheduled one after each stage end, each for
/// length_laps laps that burn fuel_share of a green lap's fuel and wear nothing; pit road is closed
/// on a random caution's first lap; a stop under caution or at a stage end costs the caution's pit
/// loss; a green stop that a caution catches on the next lap costs that lap again. Under a caution
/// the policy decides once, on the first lap pit road is open (a stop later in the same caution
/// costs the same). Fuel is counted in 1/fuel_units_per_lap of a green lap's burn, a caution lap's
/// burn rounded up (never less fuel aboard than the count says); tyre ages are at most
/// max_tyre_age laps.

#include <cstdint>
#include <string>
#include <vector>

#include "hotlap/race/cautions.h"
#include "hotlap/race/fall_off.h"
#include "hotlap/race/race_rules.h"

namespace hotlap::race {

struct PolicyOptions {
  int fuel_units_per_lap = 2;  ///< 1 to 10
  int max_tyre_age = 0;        ///< laps; 0: two fuel windows (at most the race)
};

enum class Decision : uint8_t { kStayOut = 0, kFuelOnly = 1, kFourTyresAndFuel = 2, kNone = 3 };

/// The decisions at the end of a lap, for one kind of lap (green, or a caution's first open lap).
/// Two bits a state.
class DecisionTable {
 public:
  DecisionTable() = default;
  DecisionTable(int laps, int ages, int fuels, int sets);
  Decision At(int lap, int age, int fuel, int sets_used) const;
  void Set(int lap, int age, int fuel, int sets_used, Decision d);

 private:
  size_t Index(int lap, int age, int fuel, int sets_used) const;
  int ages_ = 0, fuels_ = 0, sets_ = 0;
  std::vector<uint8_t> bits_;
};

struct RacePolicy {
  RaceRules rules;
  CautionModel cautions;
  PolicyOptions options;
  int fuel_units = 0;    ///< a full cell
  int green_burn = 0;    ///< units a green lap burns
  int caution_burn = 0;  ///< units a caution lap burns
  int max_age = 0;
  /// The least expected race time, s: the programme's value at the green flag.
  double expected_time_s = 0.0;
  /// At the end of green lap l (1 to laps - 1), with the set's age, the fuel (units) and the sets
  /// used after it.
  DecisionTable green;
  /// At the end of the first open lap of a caution that came out on lap m (indexed by m).
  DecisionTable caution;

  /// The fuel aboard with `units` of it, kg (RaceRules' cell less what the burnt units weigh).
  double FuelMass(int units) const;
};

/// InputError for fuel units a lap outside [1, 10] or a negative tyre age cap.
void CheckPolicyOptions(const PolicyOptions& options);

/// The policy (CheckRaceRules first). InputError for options out of range, or if no policy keeps
/// to the fuel and tyre sets.
RacePolicy SolvePolicy(const RaceRules& rules, const FallOff& fall_off,
                       const CautionModel& cautions, const PolicyOptions& options = {});

struct PolicyRace {
  double time_s = 0.0;
  int stops = 0;
  int tyre_sets_used = 1;
  int longest_set_laps = 0;  ///< the most green laps run on one set
  std::vector<int> caution_starts;
};

/// What the policy's races did besides their times.
struct PolicyRaceStats {
  double mean_stops = 0.0;
  int longest_set_laps = 0;  ///< over every race: the most green laps on one set
  int most_tyre_sets = 0;    ///< over every race: the most sets used
};

/// One race under the policy with race stream `stream` (the cautions RaceUnderCautions draws for
/// the same stream: the same cautions as a plan's race of that stream).
PolicyRace RaceWithPolicy(const RacePolicy& policy, const FallOff& fall_off, uint64_t stream);

/// `races` races under the policy, stream i for race i; each race's time in `times` if given.
MonteCarloResult SimulatePolicy(const RacePolicy& policy, const FallOff& fall_off, int races,
                                std::vector<double>* times = nullptr,
                                PolicyRaceStats* stats = nullptr);

/// What the policy says when a caution comes out on lap `lap` (its first open lap the next) with
/// a set of `age` laps and the fuel of a cell filled `laps_since_fill` green laps ago, and
/// `sets_used` sets so far.
Decision CautionDecision(const RacePolicy& policy, int lap, int age, int laps_since_fill,
                         int sets_used);

const char* DecisionName(Decision d);

}  // namespace hotlap::race
