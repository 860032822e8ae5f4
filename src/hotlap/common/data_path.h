#pragma once
/// @file
/// Where the shipped data (cars, tracks, example logs) is found, and how built-in names resolve.

#include <filesystem>
#include <string_view>

namespace hotlap {

/// The data folder: $HOTLAP_DATA_DIR if set, else `<prefix>/share/hotlap/data` beside an
/// installed binary, else the source tree's `data/`.
std::filesystem::path DataDir();

/// A car given as a built-in name ("gen7" -> DataDir()/cars/gen7/car.yaml) or a path to a
/// car.yaml (or to a folder holding one). InputError listing the built-in cars if neither exists.
std::filesystem::path ResolveCarFile(std::string_view name_or_path);

}  // namespace hotlap
