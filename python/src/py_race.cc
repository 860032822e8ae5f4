// hotlap.race: the race plan from the car's own fall-off, as `hotlap race` makes it (docs/race.md).

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>

#include "hotlap/race/fall_off_cache.h"
#include "hotlap/runs/race_command_run.h"
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
  runs::RaceCommandOptions o;
  race::RaceRules& r = o.run.rules;
  r.laps = laps;
  r.fuel_capacity_kg = fuel_capacity_kg;
  r.fuel_per_lap_kg = fuel_per_lap_kg;
  r.tyre_sets = tyre_sets;
  r.pit_loss_s = pit_loss_s;
  r.caution_pit_loss_s = caution_pit_loss_s;
  r.right_side_stops = right_side_stops;
  r.right_tyre_service_s = right_tyre_service_s;
  o.run.fall_off_laps = fall_off_laps;
  o.run.reference_fuel_kg = reference_fuel_kg;
  o.run.races = races;
  o.run.policy = policy;
  o.run.policy_options.fuel_units_per_lap = fuel_units_per_lap;
  if (!cache_dir.is_none()) o.run.cache_dir = py::str(cache_dir).cast<std::string>();
  o.stages = stages;
  o.cautions = cautions;
  o.step_m = step_m;
  o.spot_checks = spot_checks;
  o.spot_check_step_m = spot_check_step_m;
  const runs::RaceCommandPlan plan = runs::PlanRaceCommand(o, runs::NameStyle::kPython);
  runs::RaceCommandRun run;
  {
    py::gil_scoped_release release;
    run = runs::RunRaceCommand(car, track, plan);
  }
  return ToPython(runs::RaceCommandJson(run));
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
