#pragma once
/// @file
/// Each subcommand registers its options on the app and returns the function that runs it.

#include <functional>

#include <CLI/CLI.hpp>

namespace hotlap::app {

/// Runs a parsed subcommand; returns the process exit code.
using CommandRunner = std::function<int()>;

/// `hotlap replay`: thermal and wear models over a telemetry log.
CommandRunner RegisterReplayCommand(CLI::App& app);

/// `hotlap tyre eval|fit`: tyre force models at a point or over a sweep, and fitted to rig data.
CommandRunner RegisterTyreCommand(CLI::App& app);
CommandRunner RegisterTrackCommand(CLI::App& app);

/// `hotlap lap`: the car round a track by the quasi-steady-state method, thermal models included.
CommandRunner RegisterLapCommand(CLI::App& app);  ///< `hotlap track info` (cmd_track.cc)

/// `hotlap fit tyre|contact-length|brake`: parameters fitted to a log, with uncertainty.
CommandRunner RegisterFitCommand(CLI::App& app);

/// `hotlap synth`: a synthetic measured log from the lap simulation (docs/fitting.md).
CommandRunner RegisterSynthCommand(CLI::App& app);
CommandRunner RegisterAbsCommand(CLI::App& app);  ///< `hotlap abs`: ABS braking (cmd_abs.cc)

}  // namespace hotlap::app
