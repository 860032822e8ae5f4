// hotlap.race: the race plan from the car's own fall-off, as `hotlap race` makes it (docs/race.md).

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/ocp/min_curvature_line.h"
#include "hotlap/race/fall_off_cache.h"
#include "hotlap/race/race_json.h"
#include "hotlap/race/race_run.h"
#include "hotlap/runs/race_spot_checks.h"
#include "hotlap/sim/road.h"
#include "hotlap/track/track.h"
#include "hotlap/vehicle/car.h"
#include "py_convert.h"

namespace py = pybind11;

namespace hotlap::python {

namespace {

py::dict Race(const vehicle::Car& car, const track::Track& track, int laps,
              const std::string& stages, double fuel_capacity_kg, double fuel_per_lap_kg,
              int tyre_sets, double pit_loss_s, double caution_pit_loss_s, int fall_off_laps,
              double reference_fuel_kg, double step_m, const std::string& cautions, int races,
              bool policy, int fuel_units_per_lap, bool right_side_stops,
              double right_tyre_service_s, const py::object& cache_dir,
              const std::string& spot_checks, double spot_check_step_m) {
  race::RaceRunOptions o;
  o.rules.laps = laps;
  o.rules.stage_ends = race::ParseStageEnds(stages, laps, "stages");
  o.rules.fuel_capacity_kg = fuel_capacity_kg;
  o.rules.fuel_per_lap_kg = fuel_per_lap_kg;
  o.rules.tyre_sets = tyre_sets;
  o.rules.pit_loss_s = pit_loss_s;
  o.rules.caution_pit_loss_s = caution_pit_loss_s;
  o.rules.right_side_stops = right_side_stops;
  o.rules.right_tyre_service_s = right_tyre_service_s;
  if (!cache_dir.is_none()) o.cache_dir = py::str(cache_dir).cast<std::string>();
  o.fall_off_laps = fall_off_laps;
  o.reference_fuel_kg = reference_fuel_kg;
  o.cautions = race::ParseCautions(cautions, "cautions");
  o.races = races;
  o.policy = policy;
  o.policy_options.fuel_units_per_lap = fuel_units_per_lap;
  race::CheckRaceRules(o.rules);
  if (!(step_m >= 0.5 && step_m <= 10.0)) {
    throw InputError(fmt::format("step_m {:g} must be in [0.5, 10] m", step_m));
  }
  const std::vector<int> spot_ages =
      runs::ParseSpotCheckAges(spot_checks, fall_off_laps, "spot_checks");
  if (!(spot_check_step_m >= 1.0 && spot_check_step_m <= 20.0)) {
    throw InputError(fmt::format("spot_check_step_m {:g} must be in [1, 20] m", spot_check_step_m));
  }
  vehicle::RequireVehicle(car, "hotlap.race");
  race::RaceRun run;
  runs::RaceSpotChecks spots;
  {
    py::gil_scoped_release release;
    const std::vector<sim::RoadPoint> road = sim::SampleRoadAlongLine(
        track, ocp::MinimumCurvatureLine(track, {.step_m = std::max(step_m, 2.0), .margin_m = 1.5}),
        step_m);
    run = race::RunRace(car, track.length_m(), road, o);
    if (!spot_ages.empty()) {
      spots = runs::RunRaceSpotChecks(car, track, road,
                                      race::FallOffQssOptions(car, track.length_m(), o),
                                      run.fall_off, spot_ages, spot_check_step_m);
    }
  }
  nlohmann::json j = race::RaceJson(run, o.cautions);
  j["spot_checks"] = spot_ages.empty() ? nlohmann::json(nullptr) : runs::RaceSpotChecksJson(spots);
  return ToPython(j);
}

}  // namespace

void BindRace(py::module_& m) {
  const race::RaceRules d = race::SouthernFiveHundred();
  m.def(
      "race", &Race, py::arg("car"), py::arg("track"), py::kw_only(), py::arg("laps") = d.laps,
      py::arg("stages") = "115,230", py::arg("fuel_capacity_kg") = d.fuel_capacity_kg,
      py::arg("fuel_per_lap_kg") = d.fuel_per_lap_kg, py::arg("tyre_sets") = d.tyre_sets,
      py::arg("pit_loss_s") = d.pit_loss_s, py::arg("caution_pit_loss_s") = d.caution_pit_loss_s,
      py::arg("fall_off_laps") = 60, py::arg("reference_fuel_kg") = 25.0, py::arg("step_m") = 2.0,
      py::arg("cautions") = "record", py::arg("races") = 10000, py::arg("policy") = true,
      py::arg("fuel_units_per_lap") = 2, py::arg("right_side_stops") = d.right_side_stops,
      py::arg("right_tyre_service_s") = d.right_tyre_service_s, py::arg("cache_dir") = py::none(),
      py::arg("spot_checks") = "", py::arg("spot_check_step_m") = 6.0,
      "The race plan from the car's own fall-off over a set (QSS laps from pit-out), by dynamic "
      "programming, against the fixed plans, and the policy under cautions (a stochastic "
      "programme): the summary `hotlap race --json` writes "
      "(docs/race.md). `cache_dir` (a folder, e.g. hotlap.default_cache_dir()): keep the "
      "fall-off there, keyed by the car's files and overrides, the track and the settings; "
      "None: drive its laps every time. `spot_checks` (ages such as \"2,30,59\"): the optimal lap "
      "from the fall-off's state at each, against its QSS lap.");
  m.def(
      "default_cache_dir", [] { return race::DefaultCacheDir().string(); },
      "The folder `hotlap race` caches in by default: $HOTLAP_CACHE_DIR where it is set, else "
      "$XDG_CACHE_HOME/hotlap or ~/.cache/hotlap ('': no cache).");
}

}  // namespace hotlap::python
