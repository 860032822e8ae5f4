#include "hotlap/runs/lap_run.h"

#include <algorithm>

#include <fmt/format.h>

#include "hotlap/common/csv.h"
#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/ocp/min_curvature_line.h"
#include "hotlap/runs/celsius_option.h"
#include "hotlap/sim/lap_output.h"
#include "hotlap/sim/lap_report.h"
#include "hotlap/track/racing_line.h"

namespace hotlap::runs {

std::vector<sim::RoadPoint> SampleLapRoad(const track::Track& track, const std::string& line,
                                          double step_m, double line_margin_m) {
  if (line == "centre") return sim::SampleRoad(track, step_m);
  // The racing line on a mesh no finer than 2 m; the road points along it every step_m.
  const double line_step_m = std::max(step_m, 2.0);
  if (line == "min-curvature") {
    return sim::SampleRoadAlongLine(
        track, ocp::MinimumCurvatureLine(track, {.step_m = line_step_m, .margin_m = line_margin_m}),
        step_m);
  }
  return sim::SampleRoadAlongLine(track, track::ReadRacingLine(line, track, line_step_m), step_m);
}

LapPlan PlanLap(const vehicle::Car& car, const track::Track& track, const LapRunOptions& o,
                NameStyle style) {
  if (o.laps < 1 || o.laps > 1000) {
    throw InputError(fmt::format("{} {} must be in [1, 1000]", OptionName(style, "laps"), o.laps));
  }
  if (!(o.step_m > 0.0)) {
    throw InputError(fmt::format("{} {} must be > 0", OptionName(style, "step_m"), o.step_m));
  }
  LapPlan plan;
  plan.road = SampleLapRoad(track, o.line, o.step_m, o.line_margin_m);
  sim::QssOptions& q = plan.options;
  q.laps = o.laps;
  q.track_length = track.length_m();
  q.ambient_temp = CelsiusToKelvin(o.ambient_C);
  q.track_temp = CelsiusToKelvin(o.track_C);
  q.caution_laps = sim::ParseLapList(o.caution_laps, o.laps, OptionName(style, "caution_laps"));
  q.caution_speed =
      sim::CheckCautionSpeed(o.caution_speed_kph, OptionName(style, "caution_speed_kph"));
  q.initial = sim::CarStartState(car, {.tread_temp = KelvinOf(o.tread_C),
                                       .carcass_temp = KelvinOf(o.carcass_C),
                                       .disc_temp = KelvinOf(o.disc_C),
                                       .calliper_temp = KelvinOf(o.calliper_C),
                                       .rim_temp = KelvinOf(o.rim_C),
                                       .disc_bulk_temp = KelvinOf(o.disc_bulk_C),
                                       .ambient_temp = std::nullopt,
                                       .track_temp = std::nullopt});
  return plan;
}

LapRun RunLap(const vehicle::Car& car, const track::Track& track, const LapPlan& plan) {
  LapRun run;
  run.result = sim::RunQssLap(car, plan.road, plan.options);
  run.stint = sim::SummarizeStint(run.result);
  run.columns =
      sim::LapResultColumns(run.result, track, plan.options.ambient_temp, plan.options.track_temp);
  return run;
}

LapFiles WriteLapFiles(const std::filesystem::path& out, const LapRun& run,
                       const LapRunOptions& options, const vehicle::Car& car,
                       const track::Track& track) {
  std::filesystem::create_directories(out);
  LapFiles files{out / "lap.csv", out / "lap.html"};
  std::vector<std::pair<std::string, std::string>> metadata = {
      {"source", fmt::format("hotlap {} lap --method qss", HOTLAP_VERSION)},
      {"track", track.name()},
      {"car", car.path.string()},
      {"laps", std::to_string(options.laps)}};
  if (!car.overrides.empty()) {
    metadata.emplace_back("overrides", vehicle::OverridesText(car.overrides));
  }
  WriteCsv(files.csv, metadata, run.columns.names, run.columns.values);
  sim::WriteLapReport(files.html, {options.line, options.laps, options.ambient_C, options.track_C},
                      car, track, run.columns, run.stint);
  return files;
}

}  // namespace hotlap::runs
