#pragma once
/// @file
/// Each subcommand registers its options on the app and returns the function that runs it.

#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace hotlap::app {

/// Runs a parsed subcommand; returns the process exit code.
using CommandRunner = std::function<int()>;

/// `--set KEY=VALUE` (repeatable) on the commands that take `--car`: car parameters overridden by
/// their dotted keys, read by vehicle::ParseCarOverrides (docs/overrides.md).
/// An option whose default --help shows (the range, if any, added by the caller: ->check(...)).
template <typename T>
CLI::Option* AddShownOption(CLI::App* sub, const std::string& name, T& value,
                            const std::string& help) {
  return sub->add_option(name, value, help)->capture_default_str();
}

inline CLI::Option* AddSetOption(CLI::App* sub, std::vector<std::string>& set) {
  return sub
      ->add_option("--set", set,
                   "Override a car parameter: KEY=VALUE in the key's own unit, repeatable "
                   "(e.g. chassis.mass_kg=1600, brakes.fl.duct_factor=0.8; "
                   "docs/overrides.md)")
      ->type_name("KEY=VALUE")
      ->allow_extra_args(false);
}

/// `--channel-map FILE` and `--lap N` on the commands that take `--telemetry`: the MoTeC channel
/// map of a MoTeC i2 CSV export, and one lap's samples (Telemetry::Read,
/// docs/telemetry-formats.md).
inline void AddTelemetryReadOptions(CLI::App* sub, std::string& channel_map,
                                    std::optional<int>& lap) {
  sub->add_option("--channel-map", channel_map,
                  "MoTeC channel map (YAML) for a MoTeC i2 CSV or .ld log; default "
                  "data/motec_channels.yaml (docs/telemetry-formats.md)");
  sub->add_option("--lap", lap,
                  "Use only this lap's samples (the log's 'lap' column; a MoTeC "
                  "export's from its Beacon Markers, a .ld log's from its .ldx)");
}

/// `hotlap replay`: thermal and wear models over a telemetry log.
CommandRunner RegisterReplayCommand(CLI::App& app);

/// `hotlap tyre eval|fit`: tyre force models at a point or over a sweep, and fitted to rig data.
CommandRunner RegisterTyreCommand(CLI::App& app);
/// Prints the warnings of reading the `.tir` file `path` (tyre::TirFile::warnings) to stderr as
/// `hotlap: warning: ...` lines (cmd_tyre.cc).
void PrintTirWarnings(const std::string& path);

/// `tyre fit` under the `tyre` command (cmd_tyre_fit.cc); its runner runs the fit.
CommandRunner RegisterTyreFitSubcommand(CLI::App* tyre);

/// `hotlap track info`: length, closure, radii, banking and turns of a track (cmd_track.cc).
CommandRunner RegisterTrackCommand(CLI::App& app);

/// `hotlap lap`: the car round a track by the quasi-steady-state method, thermal models included,
/// or (`--method ocp`) the optimal lap with an optional disc-limit comparison.
CommandRunner RegisterLapCommand(CLI::App& app);

/// `hotlap optimise`: the minimum-lap-time optimal control with thermal states.
CommandRunner RegisterOptimiseCommand(CLI::App& app);

/// `hotlap fit tyre|contact-length|brake`: parameters fitted to a log, with uncertainty.
CommandRunner RegisterFitCommand(CLI::App& app);

/// `hotlap synth`: a synthetic measured log from the lap simulation (docs/fitting.md).
CommandRunner RegisterSynthCommand(CLI::App& app);

/// `hotlap observe`: the live thermal and wear observer over a log or a stream (cmd_observe.cc).
CommandRunner RegisterObserveCommand(CLI::App& app);

/// `hotlap abs`: ABS braking of one wheel, with scenarios (cmd_abs.cc).
CommandRunner RegisterAbsCommand(CLI::App& app);

/// `hotlap fe inflate|footprint|roll|abs`: the finite-element tyre's steps (cmd_fe.cc).
CommandRunner RegisterFeCommand(CLI::App& app);

/// `hotlap log info|convert`: what a log holds, and a log as hotlap CSV (cmd_log.cc).
CommandRunner RegisterLogCommand(CLI::App& app);

/// `hotlap sweep`: hands its arguments to the Python package's hotlap.sweep (cmd_sweep.cc).
CommandRunner RegisterSweepCommand(CLI::App& app);

/// `hotlap stint`: a stint as one optimal-control problem against the greedy driver.
CommandRunner RegisterStintCommand(CLI::App& app);

/// `hotlap race`: the race plan from the car's own fall-off (cmd_race.cc, docs/race.md).
CommandRunner RegisterRaceCommand(CLI::App& app);

/// Option checks with plain messages ("must be positive, not -5"); CLI11's own PositiveNumber and
/// NonNegativeNumber print their range's bound as a 300-digit number.
inline const CLI::Validator kPositive(
    [](std::string& text) -> std::string {
      double v = 0.0;
      if (!CLI::detail::lexical_cast(text, v) || !(v > 0.0) || !std::isfinite(v)) {
        return "must be a positive number, not " + text;
      }
      return {};
    },
    "POSITIVE");
inline const CLI::Validator kNonNegative(
    [](std::string& text) -> std::string {
      double v = 0.0;
      if (!CLI::detail::lexical_cast(text, v) || !(v >= 0.0) || !std::isfinite(v)) {
        return "must be zero or a positive number, not " + text;
      }
      return {};
    },
    "NONNEGATIVE");

}  // namespace hotlap::app
