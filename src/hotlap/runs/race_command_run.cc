#include "hotlap/runs/race_command_run.h"

#include <algorithm>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/ocp/min_curvature_line.h"
#include "hotlap/race/race_json.h"
#include "hotlap/sim/road.h"

namespace hotlap::runs {

RaceCommandPlan PlanRaceCommand(const RaceCommandOptions& o, NameStyle style) {
  RaceCommandPlan p;
  p.run = o.run;
  p.run.rules.stage_ends =
      race::ParseStageEnds(o.stages, o.run.rules.laps, OptionName(style, "stages"));
  p.run.cautions = race::ParseCautions(o.cautions, OptionName(style, "cautions"));
  race::CheckRaceRules(p.run.rules);
  if (!(o.step_m >= 0.5 && o.step_m <= 10.0)) {
    throw InputError(
        fmt::format("{} {:g} must be in [0.5, 10] m", OptionName(style, "step_m"), o.step_m));
  }
  if (!(o.spot_check_step_m >= 1.0 && o.spot_check_step_m <= 20.0)) {
    throw InputError(fmt::format("{} {:g} must be in [1, 20] m",
                                 OptionName(style, "spot_check_step_m"), o.spot_check_step_m));
  }
  p.spot_ages =
      ParseSpotCheckAges(o.spot_checks, o.run.fall_off_laps, OptionName(style, "spot_checks"));
  p.step_m = o.step_m;
  p.spot_check_step_m = o.spot_check_step_m;
  return p;
}

RaceCommandRun RunRaceCommand(const vehicle::Car& car, const track::Track& track,
                              const RaceCommandPlan& plan,
                              const std::function<void(const std::string&)>& progress) {
  vehicle::RequireVehicle(car, "a race plan");
  const std::vector<sim::RoadPoint> road = sim::SampleRoadAlongLine(
      track,
      ocp::MinimumCurvatureLine(track, {.step_m = std::max(plan.step_m, 2.0), .margin_m = 1.5}),
      plan.step_m);
  race::RaceRunOptions o = plan.run;
  o.progress = progress;
  RaceCommandRun out;
  out.cautions = o.cautions;
  out.race = race::RunRace(car, track.length_m(), road, o);
  if (!plan.spot_ages.empty()) {
    out.spot_checks =
        RunRaceSpotChecks(car, track, road, race::FallOffQssOptions(car, track.length_m(), o),
                          out.race.fall_off, plan.spot_ages, plan.spot_check_step_m, progress);
    out.has_spot_checks = true;
  }
  return out;
}

nlohmann::json RaceCommandJson(const RaceCommandRun& run) {
  nlohmann::json j = race::RaceJson(run.race, run.cautions);
  j["spot_checks"] =
      run.has_spot_checks ? RaceSpotChecksJson(run.spot_checks) : nlohmann::json(nullptr);
  return j;
}

std::string RaceCommandText(const RaceCommandRun& run) {
  const race::RaceRun& r = run.race;
  std::string out = race::RaceText(r);
  if (run.has_spot_checks) out += RaceSpotChecksText(run.spot_checks);
  out += fmt::format("the fall-off {} in {:.1f} s, the plans in {:.2f} s\n",
                     r.fall_off_from_cache      ? "read from the cache"
                     : r.fall_off_cache.empty() ? "driven"
                                                : "driven (and cached)",
                     r.fall_off_seconds, r.plan_seconds);
  return out;
}

}  // namespace hotlap::runs
