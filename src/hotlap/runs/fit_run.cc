#include "hotlap/runs/fit_run.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <thread>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/ident/channel_fit.h"
#include "hotlap/ident/fit_log.h"
#include "hotlap/ident/fitted_car.h"
#include "hotlap/ident/log_fit.h"
#include "hotlap/sim/synth_params.h"

namespace hotlap::runs {

namespace {

// The library's options from the run's: the parsed words, temperatures, wear, threads, sources.
ident::CarFitOptions CarFitOptionsOf(const vehicle::Car& car, const Telemetry& log,
                                     const FitRunOptions& o, NameStyle style) {
  ident::CarFitOptions options = o.numeric;
  options.kind = o.kind;
  options.corners = ident::ParseCornerList(o.corners, OptionName(style, "corners"));
  if (!o.truth.empty()) {
    options.truth = car;
    sim::ApplyParameterOverrides(sim::LoadParameterOverrides(o.truth), *options.truth);
  }
  options.fit.solver.loss = ident::ParseLossKind(o.loss);
  options.fit.initial_state = ident::ParseInitialStateMode(o.initial_state);
  if (o.ambient_C) options.temperatures.ambient_temp = CelsiusToKelvin(*o.ambient_C);
  if (o.track_C) options.temperatures.track_temp = CelsiusToKelvin(*o.track_C);
  options.wear_per_lap_mm = o.wear_per_lap_mm;
  options.threads = o.threads > 0
                        ? o.threads
                        : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  options.source_date = ident::TodayIsoDate();
  options.source_log = log.path().filename().string();
  return options;
}

}  // namespace

ident::CarFitKind ParseFitKind(const std::string& kind, NameStyle style) {
  if (kind == "tyre") return ident::CarFitKind::kTyre;
  if (kind == "contact-length") return ident::CarFitKind::kContactLength;
  if (kind == "brake") return ident::CarFitKind::kBrake;
  throw InputError(fmt::format("{} '{}': one of 'tyre', 'contact-length', 'brake'",
                               OptionName(style, "kind"), kind));
}

const char* FitKindName(ident::CarFitKind kind) {
  switch (kind) {
    case ident::CarFitKind::kTyre:
      return "tyre";
    case ident::CarFitKind::kContactLength:
      return "contact-length";
    case ident::CarFitKind::kBrake:
      break;
  }
  return "brake";
}

void CheckFitOptions(const ident::CarFitOptions& o, NameStyle style) {
  const auto positive = [style](double v, const char* name) {
    if (!(v > 0.0)) throw InputError(fmt::format("{} {} must be > 0", OptionName(style, name), v));
  };
  positive(o.fit.solver.loss_scale, "loss_scale");
  positive(o.fit.solver.max_relative_ci, "max_relative_ci");
  if (o.fit.random_starts < 0) {
    throw InputError(
        fmt::format("{} {} must be >= 0", OptionName(style, "random_starts"), o.fit.random_starts));
  }
  if (!(o.fit.sensor_lag_s >= 0.0)) {
    throw InputError(
        fmt::format("{} {} must be >= 0", OptionName(style, "sensor_lag_s"), o.fit.sensor_lag_s));
  }
  if (!(o.fit.tpms_lag_s >= 0.0)) {
    throw InputError(
        fmt::format("{} {} must be >= 0", OptionName(style, "tpms_lag_s"), o.fit.tpms_lag_s));
  }
  positive(o.fit.max_step_s, "max_step_s");
  positive(o.wear_sd_mm, "wear_sd_mm");
}

ident::FitRun RunFit(const vehicle::Car& car, const Telemetry& log, const FitRunOptions& o,
                     const FitProvenance& provenance, NameStyle style) {
  CheckFitOptions(o.numeric, style);
  const ident::CarFitOptions options = CarFitOptionsOf(car, log, o, style);
  const auto started = std::chrono::steady_clock::now();
  ident::FitRun run;
  run.command = std::string("fit ") + FitKindName(o.kind);
  run.telemetry = log.path().string();
  run.car_name = car.name;
  run.car_path = car.path.string();
  run.out = o.out;
  run.time = log.Channel("time");
  run.log_metadata = log.metadata();
  run.options = {{"loss", o.loss},
                 {"loss_scale", options.fit.solver.loss_scale},
                 {"max_relative_ci", options.fit.solver.max_relative_ci},
                 {"sensor_lag_s", options.fit.sensor_lag_s},
                 {"initial_state", o.initial_state},
                 {"random_starts", options.fit.random_starts},
                 {"seed", options.fit.seed}};
  run.result = ident::FitCarToLog(car, log, options);
  // Only a fit that used TPMS channels names their lag (a log without them reports as before).
  for (const ident::CornerFitOutcome& c : run.result.corners) {
    for (const ident::ReportedFit& f : c.fits) {
      if (f.title == "gas") run.options["tpms_lag_s"] = options.fit.tpms_lag_s;
    }
  }
  if (!o.out.empty()) {
    run.result.edits.header = {
        fmt::format("Fitted by {} {} on {} to {}.", provenance.program, run.command,
                    options.source_date, provenance.log),
        "Fitted values carry their own source comments; all others are as in the file named "
        "below."};
    ident::WriteFittedCar(car, o.out, run.result.edits);
  }
  run.elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return run;
}

}  // namespace hotlap::runs
