#pragma once
/// @file
/// The race run as `hotlap race` and Python's `hotlap.race` make it (docs/race.md): the options in
/// their plain form checked (named in the caller's spelling), the road along the
/// minimum-curvature line, the race (race/race_run.h), the optimal-lap spot checks, and the JSON
/// summary both give. The command and the binding parse their arguments into RaceCommandOptions
/// and call these, nothing else.

#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hotlap/race/race_run.h"
#include "hotlap/runs/option_name.h"
#include "hotlap/runs/race_spot_checks.h"
#include "hotlap/track/track.h"
#include "hotlap/vehicle/car.h"

namespace hotlap::runs {

struct RaceCommandOptions {
  race::RaceRunOptions run;         ///< rules (but the stage ends), fall-off, races, policy, cache
  std::string stages = "115,230";   ///< laps that end a stage
  std::string cautions = "record";  ///< ParseCautions
  double step_m = 2.0;              ///< the QSS laps' road spacing, in [0.5, 10] m
  std::string spot_checks;          ///< ages for the optimal-lap spot checks ("" none)
  double spot_check_step_m = 6.0;   ///< their mesh, in [1, 20] m
};

/// A checked run, before it runs: its options as the library takes them, the spot checks' ages.
struct RaceCommandPlan {
  race::RaceRunOptions run;
  std::vector<int> spot_ages;
  double step_m = 0.0, spot_check_step_m = 0.0;
};

/// The options checked (InputError naming the option in `style`'s spelling), nothing run.
RaceCommandPlan PlanRaceCommand(const RaceCommandOptions& options, NameStyle style);

struct RaceCommandRun {
  race::RaceRun race;
  race::CautionModel cautions;
  RaceSpotChecks spot_checks;  ///< none where no ages were asked for
  bool has_spot_checks = false;
};

/// Runs it: the road, the race, the spot checks. `progress` (may be empty) is told of the
/// fall-off's runs and the spot checks' solves.
RaceCommandRun RunRaceCommand(const vehicle::Car& car, const track::Track& track,
                              const RaceCommandPlan& plan,
                              const std::function<void(const std::string&)>& progress = {});

/// The JSON summary (docs/json-output.md, "race"): race::RaceJson with `spot_checks`.
nlohmann::json RaceCommandJson(const RaceCommandRun& run);

/// The terminal's summary: race::RaceText, the spot checks, and the times.
std::string RaceCommandText(const RaceCommandRun& run);

}  // namespace hotlap::runs
