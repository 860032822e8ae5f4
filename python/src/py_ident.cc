// hotlap.fit: a car's tyre, contact-length or brake parameters fitted to a log, with standard
// errors, intervals and warnings: the summary `hotlap fit ... --json` writes, the measured and
// fitted channels of each corner, and (with out=) the fitted car's files.

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <thread>

#include <fmt/format.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "hotlap/common/corner.h"
#include "hotlap/common/error.h"
#include "hotlap/common/telemetry.h"
#include "hotlap/common/units.h"
#include "hotlap/ident/car_log_fit.h"
#include "hotlap/ident/channel_fit.h"
#include "hotlap/ident/fit_log.h"
#include "hotlap/ident/fit_run.h"
#include "hotlap/ident/fit_run_json.h"
#include "hotlap/ident/fitted_car.h"
#include "hotlap/ident/log_fit.h"
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
             std::optional<int> lap) {
  const std::string out = out_path.string();
  ident::CarFitOptions options;
  std::string command;
  if (kind == "tyre") {
    options.kind = ident::CarFitKind::kTyre;
  } else if (kind == "contact-length") {
    options.kind = ident::CarFitKind::kContactLength;
  } else if (kind == "brake") {
    options.kind = ident::CarFitKind::kBrake;
  } else {
    throw InputError(fmt::format("kind '{}': one of 'tyre', 'contact-length', 'brake'", kind));
  }
  command = "fit " + kind;
  const Telemetry log = LogFrom(telemetry, ReadOptionsFrom(channel_map, lap));
  options.corners = ident::ParseCornerList(corners, "corners");
  options.fit.solver.loss = ident::ParseLossKind(loss);
  const auto positive = [](double v, const char* name) {
    if (!(v > 0.0)) throw InputError(fmt::format("{} {} must be > 0", name, v));
    return v;
  };
  options.fit.solver.loss_scale = positive(loss_scale, "loss_scale");
  options.fit.solver.max_relative_ci = positive(max_relative_ci, "max_relative_ci");
  if (random_starts < 0)
    throw InputError(fmt::format("random_starts {} must be >= 0", random_starts));
  options.fit.random_starts = random_starts;
  options.fit.seed = seed;
  if (!(sensor_lag_s >= 0.0))
    throw InputError(fmt::format("sensor_lag_s {} must be >= 0", sensor_lag_s));
  options.fit.sensor_lag_s = sensor_lag_s;
  options.fit.max_step_s = positive(max_step_s, "max_step_s");
  options.laps = laps;
  options.wear_sd_mm = positive(wear_sd_mm, "wear_sd_mm");
  options.fit.initial_state = ident::ParseInitialStateMode(initial_state);
  if (ambient_C) options.temperatures.ambient_temp = CelsiusToKelvin(*ambient_C);
  if (track_C) options.temperatures.track_temp = CelsiusToKelvin(*track_C);
  for (const auto& [name, mm] : wear_per_lap_mm) {
    const std::optional<Corner> c = ParseCorner(name);
    if (!c)
      throw InputError(fmt::format("wear_per_lap_mm: '{}' is not a corner (fl fr rl rr)", name));
    options.wear_per_lap_mm[*c] = mm;
  }
  options.threads =
      threads > 0 ? threads : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  options.source_date = ident::TodayIsoDate();
  options.source_log = log.path().filename().string();

  ident::FitRun run;
  run.command = command;
  run.telemetry = log.path().string();
  run.car_name = car.name;
  run.car_path = car.path.string();
  run.out = out;
  run.time = log.Channel("time");
  run.log_metadata = log.metadata();
  run.options = {{"loss", loss},
                 {"loss_scale", options.fit.solver.loss_scale},
                 {"max_relative_ci", options.fit.solver.max_relative_ci},
                 {"sensor_lag_s", options.fit.sensor_lag_s},
                 {"initial_state", initial_state},
                 {"random_starts", options.fit.random_starts},
                 {"seed", options.fit.seed}};
  const auto started = std::chrono::steady_clock::now();
  {
    py::gil_scoped_release release;
    run.result = ident::FitCarToLog(car, log, options);
  }
  if (!out.empty()) {
    run.result.edits.header = {
        fmt::format("Fitted by hotlap {} (Python) {} on {} to {}.", HOTLAP_VERSION, run.command,
                    options.source_date, run.telemetry),
        "Fitted values carry their own source comments; all others are as in the file named "
        "below."};
    ident::WriteFittedCar(car, out, run.result.edits);
  }
  run.elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
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
        py::arg("lap") = py::none(),
        "Fits the car's 'tyre', 'contact-length' or 'brake' parameters to a log (a path to a "
        "hotlap CSV, MoTeC i2 CSV or MoTeC .ld log, or a dict of arrays; channel_map and lap as "
        "--channel-map and --lap). Returns {'summary': dict (the keys of `hotlap fit --json`), "
        "'channels': {corner: {quantity_measured_unit, quantity_model_unit: array}}, 'time_s': "
        "array}; with out='fitted/car.yaml' also writes the fitted car's files.");
}

}  // namespace hotlap::python
