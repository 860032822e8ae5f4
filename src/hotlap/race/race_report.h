#pragma once
/// @file
/// The HTML report of `hotlap race --report` (docs/race.md): the plans and their times, the
/// fall-off, the race traces, the runs on each set, and how many cautions the simulated races saw.

#include <filesystem>
#include <string>

#include "hotlap/race/race_run.h"

namespace hotlap::race {

/// Writes the report (atomically). `car` and `track` name them in the page's header.
void WriteRaceReport(const std::filesystem::path& path, const RaceRun& run, const std::string& car,
                     const std::string& track);

}  // namespace hotlap::race
