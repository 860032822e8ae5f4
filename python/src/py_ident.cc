// hotlap.fit: a car's tyre, contact-length or brake parameters fitted to a log, with standard
// errors, intervals and warnings: the summary `hotlap fit ... --json` writes, the measured and
// fitted channels of each corner, and (with out=) the fitted car's files.

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include <fmt/format.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "hotlap/common/corner.h"
#include "hotlap/common/error.h"
#include "hotlap/ident/car_log_fit.h"
#include "hotlap/ident/channel_fit.h"
#include "hotlap/ident/fit_run.h"
#include "hotlap/ident/fit_run_json.h"
#include "hotlap/logs/telemetry.h"
#include "hotlap/runs/fit_run.h"
#include "hotlap/vehicle/car.h"
#include "py_convert.h"

namespace hotlap::python {

namespace {

py::dict Fit(const vehicle::Car& car, const py::handle& telemetry, const std::string& kind,
             const std::string& corners, const std::string& loss, const std::string& initial_state,
             std::optional<double> ambient_C, std::optional<double> track_C,
             const std::map<std::string, double>& wear_per_lap_mm, int threads,
             const std::filesystem::path& out_path, double loss_scale, double max_relative_ci,
             int random_starts, uint64_t seed, double sensor_lag_s, double max_step_s,
             std::optional<int> laps, double wear_sd_mm, const py::object& channel_map,
             std::optional<int> lap, double tpms_lag_s) {
  runs::FitRunOptions options;
  options.kind = runs::ParseFitKind(kind, runs::NameStyle::kPython);
  const Telemetry log = LogFrom(telemetry, ReadOptionsFrom(channel_map, lap));
  options.corners = corners;
  options.loss = loss;
  options.initial_state = initial_state;
  options.ambient_C = ambient_C;
  options.track_C = track_C;
  for (const auto& [name, mm] : wear_per_lap_mm) {
    const std::optional<Corner> c = ParseCorner(name);
    if (!c)
      throw InputError(fmt::format("wear_per_lap_mm: '{}' is not a corner (fl fr rl rr)", name));
    options.wear_per_lap_mm[*c] = mm;
  }
  options.threads = threads;
  options.out = out_path.string();
  ident::CarFitOptions& numeric = options.numeric;
  numeric.fit.solver.loss_scale = loss_scale;
  numeric.fit.solver.max_relative_ci = max_relative_ci;
  numeric.fit.random_starts = random_starts;
  numeric.fit.seed = seed;
  numeric.fit.sensor_lag_s = sensor_lag_s;
  numeric.fit.tpms_lag_s = tpms_lag_s;
  numeric.fit.max_step_s = max_step_s;
  numeric.laps = laps;
  numeric.wear_sd_mm = wear_sd_mm;
  ident::FitRun run;
  {
    py::gil_scoped_release release;
    run = runs::RunFit(car, log, options,
                       {fmt::format("hotlap {} (Python)", HOTLAP_VERSION), log.path().string()},
                       runs::NameStyle::kPython);
  }
  py::dict result;
  result["summary"] = ToPython(ident::FitRunJson(run));
  py::dict channels;
  for (const ident::CornerFitOutcome& corner : run.result.corners) {
    py::dict c;
    for (const ident::ChannelPair& pair : corner.channels) {
      c[py::str(pair.quantity + "_measured_" + pair.column_unit)] = ToArray(pair.measured);
      c[py::str(pair.quantity + "_model_" + pair.column_unit)] = ToArray(pair.model);
    }
    channels[py::str(std::string(CornerName(corner.corner)))] = c;
  }
  result["channels"] = channels;
  result["time_s"] = ToArray(run.time);
  return result;
}

}  // namespace

void BindIdent(py::module_& m) {
  const ident::CarFitOptions defaults;  // the library's defaults are the module's
  m.def("fit", &Fit, py::arg("car"), py::arg("telemetry"), py::kw_only(), py::arg("kind") = "tyre",
        py::arg("corners") = "all", py::arg("loss") = "huber", py::arg("initial_state") = "fitted",
        py::arg("ambient_temp_C") = py::none(), py::arg("track_temp_C") = py::none(),
        py::arg("wear_per_lap_mm") = std::map<std::string, double>{}, py::arg("threads") = 0,
        py::arg("out") = "", py::arg("loss_scale") = defaults.fit.solver.loss_scale,
        py::arg("max_relative_ci") = defaults.fit.solver.max_relative_ci,
        py::arg("random_starts") = defaults.fit.random_starts, py::arg("seed") = defaults.fit.seed,
        py::arg("sensor_lag_s") = defaults.fit.sensor_lag_s,
        py::arg("max_step_s") = defaults.fit.max_step_s, py::arg("laps") = py::none(),
        py::arg("wear_sd_mm") = defaults.wear_sd_mm, py::arg("channel_map") = py::none(),
        py::arg("lap") = py::none(), py::arg("tpms_lag_s") = defaults.fit.tpms_lag_s,
        "Fits the car's 'tyre', 'contact-length' or 'brake' parameters to a log (a path to a "
        "hotlap CSV, MoTeC i2 CSV or MoTeC .ld log, or a dict of arrays; channel_map and lap as "
        "--channel-map and --lap; tpms_lag_s as --tpms-lag-s). Returns {'summary': dict (the keys "
        "of `hotlap fit --json`), "
        "'channels': {corner: {quantity_measured_unit, quantity_model_unit: array}}, 'time_s': "
        "array}; with out='fitted/car.yaml' also writes the fitted car's files.");
}

}  // namespace hotlap::python
