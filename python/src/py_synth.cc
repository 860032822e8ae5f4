// hotlap.synth: a synthetic "measured" log from the lap simulation with chosen true parameters,
// sensor lag and noise, and with the car's own models TPMS channels, as `hotlap synth` makes it.

#include <filesystem>
#include <optional>
#include <string>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "hotlap/common/output_folder.h"
#include "hotlap/runs/synth_run.h"
#include "hotlap/track/track.h"
#include "hotlap/vehicle/car.h"
#include "py_convert.h"

namespace hotlap::python {

namespace {

py::dict Synth(const vehicle::Car& car, const track::Track& track,
               const std::optional<std::filesystem::path>& out, int laps, double rate_hz,
               double noise_C, double lag_s, double wear_noise_mm, double radius_noise_mm,
               const std::string& truth, bool tpms, double tpms_noise_kPa, double tpms_temp_noise_C,
               double tpms_lag_s, const std::string& params, const std::string& process_noise,
               uint64_t seed, double ambient_C, double track_C, double step_m) {
  runs::SynthRunOptions o{.params = params,
                          .process_noise = process_noise,
                          .laps = laps,
                          .rate_hz = rate_hz,
                          .noise_C = noise_C,
                          .lag_s = lag_s,
                          .wear_noise_mm = wear_noise_mm,
                          .radius_noise_mm = radius_noise_mm,
                          .tpms = {.enabled = tpms,
                                   .pressure_noise_kPa = tpms_noise_kPa,
                                   .temp_noise_K = tpms_temp_noise_C,
                                   .lag_s = tpms_lag_s},
                          .truth = truth,
                          .ambient_C = ambient_C,
                          .track_C = track_C,
                          .step_m = step_m,
                          .seed = seed};
  if (out) CheckOutputFolder(out->string(), "out");
  vehicle::Car truth_car = car;  // the true parameters go onto a copy: the caller's car stays
  runs::SynthRun run;
  {
    py::gil_scoped_release release;
    run = runs::RunSynth(truth_car, track, o);
  }
  if (out) runs::WriteSynthRunLog(*out, run, track, o);
  py::dict result;
  result["channels"] = ColumnsToDict(run.log.columns, run.log.values);
  result["summary"] =
      ToPython(runs::SynthRunJson(run, truth_car, track, o, out ? out->string() : ""));
  return result;
}

}  // namespace

void BindSynth(py::module_& m) {
  const runs::SynthRunOptions d;  // the command line's defaults are the module's
  m.def("synth", &Synth, py::arg("car"), py::arg("track"), py::arg("out") = py::none(),
        py::kw_only(), py::arg("laps") = d.laps, py::arg("rate_hz") = d.rate_hz,
        py::arg("noise_C") = d.noise_C, py::arg("lag_s") = d.lag_s,
        py::arg("wear_noise_mm") = d.wear_noise_mm, py::arg("radius_noise_mm") = d.radius_noise_mm,
        py::arg("truth") = d.truth, py::arg("tpms") = d.tpms.enabled,
        py::arg("tpms_noise_kPa") = d.tpms.pressure_noise_kPa,
        py::arg("tpms_temp_noise_C") = d.tpms.temp_noise_K, py::arg("tpms_lag_s") = d.tpms.lag_s,
        py::arg("params") = d.params, py::arg("process_noise") = d.process_noise,
        py::arg("seed") = d.seed, py::arg("ambient_temp_C") = d.ambient_C,
        py::arg("track_temp_C") = d.track_C, py::arg("step_m") = d.step_m,
        "A synthetic measured log, as `hotlap synth` makes it: {'channels': {column: array} (the "
        "log's columns, canonical units), 'summary': dict (the keys of `hotlap synth --json`)}, "
        "and the CSV written to `out` where given. truth: 'paper' (the paper's two masses and "
        "lumped disc, what the fits identify and the observer tracks) or 'car' (the car's own "
        "gas-and-rim tyres and bulk discs; with tpms, the TPMS channels pressure_<c>_kPa and "
        "gas_temp_<c>_C through a first-order lag of tpms_lag_s and noise of tpms_noise_kPa and "
        "tpms_temp_noise_C). params: a file of true values (model: parameter_overrides); "
        "process_noise: an observer noise file or 'default' for a stochastic truth. The car "
        "passed in is not changed.");
}

}  // namespace hotlap::python
