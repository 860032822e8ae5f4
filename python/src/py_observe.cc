// hotlap.observe: the thermal and wear observer over a log, as `hotlap observe` runs it
// (docs/observer.md): the estimates file written, its rows and the summary returned.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "hotlap/common/error.h"
#include "hotlap/common/output_folder.h"
#include "hotlap/observe/observe_json.h"
#include "hotlap/runs/observe_run.h"
#include "hotlap/vehicle/car.h"
#include "py_convert.h"

namespace hotlap::python {

namespace {

py::dict Observe(const vehicle::Car& car, const std::filesystem::path& telemetry,
                 const std::filesystem::path& out, const std::string& models,
                 const std::optional<std::filesystem::path>& config,
                 const std::optional<std::filesystem::path>& noise_from_fit, bool p5_scale,
                 std::optional<double> sensor_lag_s, std::optional<double> tread_C,
                 std::optional<double> carcass_C, std::optional<double> disc_C,
                 std::optional<double> calliper_C, double ambient_C, double track_C,
                 const std::optional<std::filesystem::path>& channel_map, std::optional<int> lap) {
  runs::ObserveRunOptions o;
  o.telemetry = telemetry.string();
  o.out = out.string();
  o.models = models;
  o.config = config ? config->string() : "";
  o.noise_from_fit = noise_from_fit ? noise_from_fit->string() : "";
  o.p5_scale = p5_scale;
  o.sensor_lag_s = sensor_lag_s;
  o.tread_C = tread_C;
  o.carcass_C = carcass_C;
  o.disc_C = disc_C;
  o.calliper_C = calliper_C;
  o.ambient_C = ambient_C;
  o.track_C = track_C;
  o.channel_map = channel_map ? channel_map->string() : "";
  o.lap = lap;
  if (o.telemetry == "-" || o.out == "-") {
    throw InputError("observe: telemetry and out are files here (a stream is the command's)");
  }
  CheckOutputFolder(o.out, "out");
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  runs::ObserveHooks hooks;
  hooks.started = [&](const std::vector<std::string>& names) { columns = names; };
  hooks.row = [&](const std::vector<double>& row) { rows.push_back(row); };
  runs::ObserveRun run;
  {
    py::gil_scoped_release release;
    run = runs::RunObserve(car, o, hooks);
  }
  std::vector<std::vector<double>> values(columns.size(), std::vector<double>(rows.size()));
  for (size_t k = 0; k < rows.size(); ++k) {
    for (size_t j = 0; j < columns.size() && j < rows[k].size(); ++j) values[j][k] = rows[k][j];
  }
  py::dict result;
  result["estimates"] = ColumnsToDict(columns, values);
  result["summary"] = ToPython(observe::ObserveJson(*run.observer, car, run.summary));
  return result;
}

}  // namespace

void BindObserve(py::module_& m) {
  const runs::ObserveRunOptions d;  // the command line's defaults are the module's
  m.def("observe", &Observe, py::arg("car"), py::arg("telemetry"), py::arg("out"), py::kw_only(),
        py::arg("models") = d.models, py::arg("config") = py::none(),
        py::arg("noise_from_fit") = py::none(), py::arg("p5_scale") = d.p5_scale,
        py::arg("sensor_lag_s") = py::none(), py::arg("tread_temp_C") = py::none(),
        py::arg("carcass_temp_C") = py::none(), py::arg("disc_temp_C") = py::none(),
        py::arg("calliper_temp_C") = py::none(), py::arg("ambient_temp_C") = d.ambient_C,
        py::arg("track_temp_C") = d.track_C, py::arg("channel_map") = py::none(),
        py::arg("lap") = py::none(),
        "The thermal and wear observer over a log (a hotlap CSV, MoTeC i2 CSV or .ld file), as "
        "`hotlap observe` runs it: the estimates CSV written to `out`; returns {'estimates': "
        "{column: array} (the file's columns), 'summary': dict (the keys of `hotlap observe "
        "--json`)}. models: 'paper' (the paper's two-mass tyres and lumped discs) or 'car' (the "
        "car's own gas-and-rim tyres with their TPMS readings and surface-and-bulk discs: the gas "
        "temperature and hot pressure estimated with bands). config: a noise file (default "
        "data/observer/default.yaml); noise_from_fit: a fit's JSON summary for the sensor "
        "noise; sensor_lag_s: every temperature sensor's time constant (default: the log's, "
        "else the noise file's).");
}

}  // namespace hotlap::python
