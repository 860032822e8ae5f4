#pragma once
/// @file
/// The fit run as `hotlap fit tyre|contact-length|brake` and Python's `hotlap.fit` make it: the
/// options from plain values, the car fitted to the log (ident/car_log_fit.h), the fitted car's
/// files written with a header naming the run. The command and the binding parse their own
/// arguments into FitRunOptions, read the log, call RunFit and print or return what it gives.

#include <map>
#include <optional>
#include <string>

#include "hotlap/common/corner.h"
#include "hotlap/ident/car_log_fit.h"
#include "hotlap/ident/fit_run.h"
#include "hotlap/logs/telemetry.h"
#include "hotlap/runs/option_name.h"
#include "hotlap/vehicle/car.h"

namespace hotlap::runs {

/// A fit run's options, in the units the command line and Python take (degC).
struct FitRunOptions {
  ident::CarFitKind kind = ident::CarFitKind::kTyre;
  std::string corners = "all";               ///< "all" or a list such as "fl,rr"
  std::string loss = "huber";                ///< huber, cauchy or none
  std::string initial_state = "fitted";      ///< fitted or measured
  std::optional<double> ambient_C, track_C;  ///< when the log has no such column
  std::map<Corner, double> wear_per_lap_mm;  ///< measured wear per lap (tyre fits)
  int threads = 0;                           ///< corners fitted at once; 0: one per core
  std::string truth;  ///< a parameter file of the true values (hotlap synth --params), or ""
  /// The fitted car (.yaml; its parts go in a folder beside it); "": nothing written.
  std::string out;
  /// The numeric options (loss scale, starts, seed, sensor lag, step, laps, wear sd), taken as
  /// they are; kind, corners, loss, initial state, temperatures, wear, threads and the sources are
  /// set from the fields above.
  ident::CarFitOptions numeric;
};

/// Who wrote the fitted car and from what, for its header: "hotlap 0.1.0" (or with " (Python)")
/// and the log as the header names it.
struct FitProvenance {
  std::string program;
  std::string log;
};

/// "tyre", "contact-length" or "brake" as a kind (InputError naming `option` otherwise).
ident::CarFitKind ParseFitKind(const std::string& kind, NameStyle style);

/// The kind's name as the command has it: "tyre", "contact-length" or "brake".
const char* FitKindName(ident::CarFitKind kind);

/// InputError for a numeric option out of its range (loss scale, interval width, starts, sensor
/// lag, step, wear sd), named in `style`.
void CheckFitOptions(const ident::CarFitOptions& numeric, NameStyle style);

/// Fits `car` to `log` and writes the fitted car where `options.out` says (no Python inside:
/// safe without the GIL). The run's `elapsed_s` is the fit's and the writing's.
ident::FitRun RunFit(const vehicle::Car& car, const Telemetry& log, const FitRunOptions& options,
                     const FitProvenance& provenance, NameStyle style);

}  // namespace hotlap::runs
