#pragma once
/// @file
/// Fitting a car's tyre, contact-length or brake parameters to a telemetry log, every corner
/// asked for, on threads (docs/fitting.md): what `hotlap fit tyre|contact-length|brake` computes
/// before it prints and writes. Per corner: the fits with their uncertainty, the measured
/// channels beside the fitted model's, the warnings, and the edits that write the fitted car
/// (WriteFittedCar). The per-corner fits are tyre_thermal_fit.h, contact_length_fit.h and
/// brake_thermal_fit.h; this adds reading the log, the options they share, the joint intervals
/// over all corners, and the threads.

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "hotlap/common/corner.h"
#include "hotlap/ident/channel_fit.h"
#include "hotlap/ident/fitted_car.h"
#include "hotlap/ident/log_fit.h"
#include "hotlap/logs/telemetry.h"
#include "hotlap/sim/replay_io.h"
#include "hotlap/vehicle/car.h"

namespace hotlap::ident {

/// Which parameters FitCarToLog fits.
enum class CarFitKind {
  kTyre,           ///< p1..p5 to tread and carcass temperatures, then wp1, wp2 to the wear
  kContactLength,  ///< p_cp1, p_cp2 to the rolling radii
  kBrake,          ///< gamma, xi and the convection entries to disc and calliper temperatures
};

/// The model parameters FitCarToLog fits on one corner: 7 (tyre), 2 (contact length), 14 (brake).
int ModelParametersPerCorner(CarFitKind kind);

/// What to fit, and how.
struct CarFitOptions {
  CarFitKind kind = CarFitKind::kTyre;
  /// The corners to fit, each at most once; the result lists them in this order.
  std::vector<Corner> corners{kAllCorners.begin(), kAllCorners.end()};
  /// The options of every corner's fit. FitCarToLog sets solver.joint_family_size to the model
  /// parameters of all corners fitted, so the joint intervals hold all of them at once.
  LogFitOptions fit;
  /// Air and track temperatures (K) where the log has no such column (tyre and brake).
  sim::InitialTemperatureOverrides temperatures;
  /// Tyre: tread depth lost per lap, mm, by corner, measured; those corners fit their wear to it
  /// (times the laps) instead of a wear channel.
  std::map<Corner, double> wear_per_lap_mm;
  double wear_sd_mm = 0.002;  ///< standard deviation of a wear_per_lap_mm value, mm per lap
  /// Laps in the log, for wear_per_lap_mm; unset: the log's "# laps:" line, else 1.
  std::optional<int> laps;
  int threads = 1;  ///< corners fitted at once, >= 1
  /// The car the log was made from, when known: every corner then carries its true values.
  std::optional<vehicle::Car> truth;
  /// The date (YYYY-MM-DD) and the log's name in every fitted value's source comment; empty:
  /// today and the log's file name.
  std::string source_date, source_log;
};

/// One fit of a corner, as it is reported: "thermal", "wear", "brake" or "contact length".
struct ReportedFit {
  std::string title;
  FitResult fit;
  /// Parameters held at the car's value in this fit (key -> value, file units).
  std::map<std::string, double> held;
};

/// A measured channel and the fitted model's version of it, in display units, for plots and
/// tables.
struct ChannelPair {
  std::string quantity;                 ///< e.g. "tread_temp"
  std::string title;                    ///< e.g. "tread temperature"
  std::string unit;                     ///< e.g. "\u00b0C"
  std::string column_unit;              ///< unit suffix of a CSV column, e.g. "C"
  std::vector<double> measured, model;  ///< at the log's samples; NaN where not measured
};

/// What the fit made of one corner.
struct CornerFitOutcome {
  Corner corner = Corner::kFrontLeft;
  bool fitted = false;  ///< at least one fit ran (else the warnings say why not)
  std::vector<ReportedFit> fits;
  std::vector<std::string> warnings;  ///< about the data and what was not fitted
  std::vector<ChannelPair> channels;
  /// RMS errors by key (e.g. "rms_tread_C"), display units.
  std::vector<std::pair<std::string, double>> rms;
  /// The true value of each parameter by key (display units), when CarFitOptions::truth is set.
  std::map<std::string, double> truth;
};

/// The fit of a car to a log.
struct CarFitResult {
  std::vector<CornerFitOutcome> corners;  ///< in the order of CarFitOptions::corners
  /// The fitted values with their source comments, for WriteFittedCar; the caller adds the
  /// header lines.
  FittedCarEdits edits;
  /// The model parameters whose joint intervals hold together (FitOptions::joint_family_size).
  int joint_family_size = 1;
};

/// Fits `options.kind`'s parameters of every corner of `options.corners` to `log`, starting from
/// `car`'s values. Throws InputError for bad options (no corner, a corner twice, threads < 1,
/// laps < 1, a wear standard deviation <= 0) or a log without the inputs the fit needs (naming
/// the file and the column); a measured channel that is missing or unusable is a warning of its
/// corner instead. The result does not depend on `options.threads`.
CarFitResult FitCarToLog(const vehicle::Car& car, const Telemetry& log,
                         const CarFitOptions& options);

/// Every warning of a corner: about the data first, then each fit's, prefixed by its title.
std::vector<std::string> CornerWarnings(const CornerFitOutcome& corner);

/// The model parameters of a corner and their estimates, in order over its fits.
std::vector<std::pair<const FitParameter*, const ParameterEstimate*>> ModelParameters(
    const CornerFitOutcome& corner);

}  // namespace hotlap::ident
