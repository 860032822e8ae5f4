#pragma once
/// @file
/// Where the shipped data (cars, tracks, example logs) is found, and how built-in names resolve.

#include <filesystem>
#include <string_view>

namespace hotlap {

/// The data folder: $HOTLAP_DATA_DIR if set, else `<prefix>/share/hotlap/data` beside an
/// installed binary, else up to four folders above the shared object holding the library (the
/// installed Python package), else the source tree's `data/` while it exists, else the data
/// folder of the install prefix the library was configured for (CMAKE_INSTALL_PREFIX; a program
/// of the user's linked with the static libraries installed elsewhere needs HOTLAP_DATA_DIR).
std::filesystem::path DataDir();

/// A car given as a built-in name ("gen7" -> DataDir()/cars/gen7/car.yaml) or a path to a
/// car.yaml (or to a folder holding one). InputError listing the built-in cars if neither exists.
std::filesystem::path ResolveCarFile(std::string_view name_or_path);

/// A track given as a built-in name ("darlington" -> DataDir()/tracks/darlington.yaml; a built-in
/// is any DataDir()/tracks/NAME.yaml, NAME.yml, NAME.csv or NAME.xml) or a path to an existing
/// file (the track loader checks its extension). InputError listing the built-in tracks if
/// neither exists.
std::filesystem::path ResolveTrackFile(std::string_view name_or_path);

/// A tyre force model's file given as a built-in name ("brush_example" ->
/// DataDir()/tyres/brush_example.yaml, any DataDir()/tyres/NAME.yaml, NAME.yml or NAME.tir; a
/// car's tyre as CAR/NAME, "gen7/left" -> DataDir()/cars/gen7/tyres/left.tir) or a path (an
/// existing file, or any name with an extension or absolute: returned as it is, for the loader
/// to check). InputError listing the built-in tyres for a name that is neither.
std::filesystem::path ResolveTyreFile(std::string_view name_or_path);

}  // namespace hotlap
