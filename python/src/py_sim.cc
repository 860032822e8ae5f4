// hotlap.load_car, load_track, replay and qss_lap: the models over a log or round a track, with
// the same channels and summary keys as `hotlap replay` and `hotlap lap --method qss`.

#include <optional>
#include <string>

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "hotlap/common/data_path.h"
#include "hotlap/common/error.h"
#include "hotlap/logs/telemetry.h"
#include "hotlap/runs/lap_run.h"
#include "hotlap/runs/replay_run.h"
#include "hotlap/sim/lap_json.h"
#include "hotlap/sim/replay_report.h"
#include "hotlap/track/track_io.h"
#include "hotlap/vehicle/car.h"
#include "py_convert.h"

namespace hotlap::python {

namespace {

py::dict Replay(const vehicle::Car& car, const py::handle& telemetry, bool heat_flows,
                double max_step_s, std::optional<double> tread_C, std::optional<double> carcass_C,
                std::optional<double> disc_C, std::optional<double> calliper_C,
                std::optional<double> ambient_C, std::optional<double> track_C,
                const py::object& channel_map, std::optional<int> lap) {
  const Telemetry log = LogFrom(telemetry, ReadOptionsFrom(channel_map, lap));
  const runs::ReplayRunOptions options{.heat_flows = heat_flows,
                                       .max_step_s = max_step_s,
                                       .tread_C = tread_C,
                                       .carcass_C = carcass_C,
                                       .disc_C = disc_C,
                                       .calliper_C = calliper_C,
                                       .ambient_C = ambient_C,
                                       .track_C = track_C};
  runs::ReplayRun run;
  {
    py::gil_scoped_release release;
    run = runs::RunReplay(car, log, options, runs::NameStyle::kPython);
  }
  py::dict out;
  out["channels"] = ColumnsToDict(run.columns.names, run.columns.values);
  out["summary"] =
      ToPython(sim::ReplayJson(run.result, run.summaries, log.path().string(), car, ""));
  return out;
}

py::dict QssLap(const vehicle::Car& car, const track::Track& track, int laps, double step_m,
                const std::filesystem::path& line, double line_margin_m, double ambient_C,
                double track_C, std::optional<double> tread_C, std::optional<double> carcass_C,
                std::optional<double> disc_C, std::optional<double> calliper_C,
                std::optional<double> rim_C, std::optional<double> disc_bulk_C,
                const std::string& caution_laps, double caution_speed_kph) {
  vehicle::RequireVehicle(car, "hotlap.qss_lap");
  runs::LapRunOptions options{.line = line.string(),  // a name or a file (str or os.PathLike)
                              .line_margin_m = line_margin_m,
                              .step_m = step_m,
                              .laps = laps,
                              .ambient_C = ambient_C,
                              .track_C = track_C,
                              .tread_C = tread_C,
                              .carcass_C = carcass_C,
                              .disc_C = disc_C,
                              .calliper_C = calliper_C,
                              .rim_C = rim_C,
                              .disc_bulk_C = disc_bulk_C,
                              .caution_laps = caution_laps,
                              .caution_speed_kph = caution_speed_kph};
  const runs::LapPlan plan = runs::PlanLap(car, track, options, runs::NameStyle::kPython);
  runs::LapRun run;
  {
    py::gil_scoped_release release;
    run = runs::RunLap(car, track, plan);
  }
  py::dict out;
  out["channels"] = ColumnsToDict(run.columns.names, run.columns.values);
  out["summary"] = ToPython(sim::StintJson(run.stint, track, car, "", ""));
  return out;
}

// {key: number} (or None) as the car's overrides, in the dict's order.
std::vector<vehicle::CarOverride> OverridesFrom(const py::handle& overrides) {
  std::vector<vehicle::CarOverride> out;
  if (overrides.is_none()) return out;
  if (!py::isinstance<py::dict>(overrides)) {
    throw InputError(fmt::format("overrides must be a dict {{key: number}}, not {}",
                                 std::string(py::str(overrides.get_type().attr("__name__")))));
  }
  for (const auto& [key, value] : overrides.cast<py::dict>()) {
    if (!py::isinstance<py::str>(key)) {
      throw InputError(
          fmt::format("overrides: the key {} is not a string (a dotted key, e.g. "
                      "'chassis.mass_kg')",
                      std::string(py::repr(key))));
    }
    const std::string name = key.cast<std::string>();
    // Any real number: Python's int and float, NumPy's integer and floating scalars (a value
    // from np.arange or a pandas column); not a bool.
    static const py::object real = py::module_::import("numbers").attr("Real");
    if (py::isinstance<py::bool_>(value) || !py::isinstance(value, real)) {
      throw InputError(fmt::format("override '{}': the value {} is not a number", name,
                                   std::string(py::repr(value))));
    }
    const double number = PyFloat_AsDouble(value.ptr());  // its __float__
    if (number == -1.0 && PyErr_Occurred() != nullptr) {
      PyErr_Clear();
      throw InputError(fmt::format("override '{}': the value {} is not a number", name,
                                   std::string(py::repr(value))));
    }
    out.push_back({name, number});
  }
  return out;
}

}  // namespace

void BindSim(py::module_& m) {
  py::class_<vehicle::Car>(m, "Car", "A car's parameter set (hotlap.load_car).")
      .def_property_readonly("name", [](const vehicle::Car& c) { return c.name; })
      .def_property_readonly("path", [](const vehicle::Car& c) { return c.path.string(); })
      .def_property_readonly(
          "overrides",
          [](const vehicle::Car& c) { return ToPython(vehicle::OverridesJson(c.overrides)); },
          "The overrides the car was loaded with, {key: value}.")
      .def("__repr__", [](const vehicle::Car& c) {
        if (!c.overrides.empty()) {
          return fmt::format("<hotlap.Car '{}' from {} with {}>", c.name, c.path.string(),
                             vehicle::OverridesText(c.overrides));
        }
        return fmt::format("<hotlap.Car '{}' from {}>", c.name, c.path.string());
      });
  py::class_<track::Track>(m, "Track", "A closed track (hotlap.load_track).")
      .def_property_readonly("name", [](const track::Track& t) { return t.name(); })
      .def_property_readonly("length_m", &track::Track::length_m)
      .def("__repr__", [](const track::Track& t) {
        return fmt::format("<hotlap.Track '{}', {:.1f} m>", t.name(), t.length_m());
      });
  m.def(
      "load_car",
      [](const std::filesystem::path& name_or_path, const py::object& overrides) {
        return vehicle::LoadCar(ResolveCarFile(name_or_path.string()), OverridesFrom(overrides));
      },
      py::arg("name_or_path") = "gen7", py::arg("overrides") = py::none(),
      "A built-in car by name ('gen7') or a car.yaml (or its folder) by path; `overrides` "
      "{key: number} sets car parameters by their dotted keys, in the key's own unit, checked "
      "as the files' values are (docs/overrides.md), e.g. {'chassis.mass_kg': 1600, "
      "'brakes.fl.duct_factor': 0.8}.");
  m.def(
      "override_keys",
      [](const std::filesystem::path& name_or_path) {
        return vehicle::OverrideKeys(ResolveCarFile(name_or_path.string()));
      },
      py::arg("name_or_path") = "gen7",
      "Every key load_car's overrides (and --set) accept for this car, in file order.");
  m.def(
      "load_track",
      [](const std::filesystem::path& name_or_path) {
        return track::LoadTrack(name_or_path.string());
      },
      py::arg("name_or_path") = "darlington",
      "A built-in track by name ('darlington') or a track file by path.");
  m.def("replay", &Replay, py::arg("car"), py::arg("telemetry"), py::kw_only(),
        py::arg("heat_flows") = false, py::arg("max_step_s") = 0.02,
        py::arg("tread_temp_C") = py::none(), py::arg("carcass_temp_C") = py::none(),
        py::arg("disc_temp_C") = py::none(), py::arg("calliper_temp_C") = py::none(),
        py::arg("ambient_temp_C") = py::none(), py::arg("track_temp_C") = py::none(),
        py::arg("channel_map") = py::none(), py::arg("lap") = py::none(),
        "The four tyre and four brake thermal models over a log (a path to a hotlap CSV, MoTeC "
        "i2 CSV or MoTeC .ld log, or a dict of arrays keyed by column names with units): "
        "{'channels': {column: array}, 'summary': dict}, as `hotlap replay` writes them. "
        "channel_map: a MoTeC log's channel map (as --channel-map); lap: only that lap's samples "
        "(as --lap).");
  m.def("qss_lap", &QssLap, py::arg("car"), py::arg("track"), py::kw_only(), py::arg("laps") = 1,
        py::arg("step_m") = 1.0, py::arg("line") = "min-curvature", py::arg("line_margin_m") = 1.5,
        py::arg("ambient_temp_C") = 25.0, py::arg("track_temp_C") = 40.0,
        py::arg("tread_temp_C") = py::none(), py::arg("carcass_temp_C") = py::none(),
        py::arg("disc_temp_C") = py::none(), py::arg("calliper_temp_C") = py::none(),
        py::arg("rim_temp_C") = py::none(), py::arg("disc_bulk_temp_C") = py::none(),
        py::arg("caution_laps") = "", py::arg("caution_speed_kph") = 110.0,
        "Quasi-steady-state laps with the thermal models, on the minimum-curvature line, the "
        "centre line ('centre') or a line from a file (as `hotlap lap --line`): {'channels', "
        "'summary'} as `hotlap lap --method qss` writes them.");
}

}  // namespace hotlap::python
