#pragma once
/// @file
/// How a run names its options in the messages it throws: as the command line spells them
/// (`--caution-laps`) or as Python's keyword arguments do (`caution_laps`). The runs take their
/// options as one struct whatever the caller; only the words of an error differ.

#include <string>
#include <string_view>

namespace hotlap::runs {

/// Whose spelling an option's name takes in an InputError.
enum class NameStyle {
  kCommandLine,  ///< `--caution-speed-kph`
  kPython,       ///< `caution_speed_kph`
};

/// `name` (snake_case, as the Python keyword) in the caller's spelling: for the command line a
/// leading `--` and each `_` a `-`; units keep their case (`ambient_temp_C` -> `--ambient-temp-C`).
std::string OptionName(NameStyle style, std::string_view name);

}  // namespace hotlap::runs
