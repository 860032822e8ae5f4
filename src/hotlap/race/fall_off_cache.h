#pragma once
/// @file
/// The fall-off kept on disk, so that a race is planned again in seconds once its car, track and
/// settings have been driven (docs/race.md, "The fall-off cache"). One text file per key; the
/// numbers written to 17 significant digits, so that a plan from the cache is the plan from the
/// laps, bit for bit.

#include <filesystem>
#include <optional>
#include <string>

#include "hotlap/race/fall_off.h"

namespace hotlap::race {

/// The folder the command line caches in by default: $HOTLAP_CACHE_DIR where it is set (set and
/// empty: no cache), else $XDG_CACHE_HOME/hotlap, else $HOME/.cache/hotlap; empty (no cache)
/// without any of them.
std::filesystem::path DefaultCacheDir();

/// What tells a car from another in the cache's key: the name and bytes of every file in its
/// car.yaml's folder and below, and the overrides it was loaded with ("no files" for a car made
/// in code: then only the first-lap probe of RunRace tells).
std::string CarFilesKey(const vehicle::Car& car);

/// The cache file for a key in `dir`: race-fall-off-<16 hex digits of the key's hash>.txt.
std::filesystem::path FallOffCacheFile(const std::filesystem::path& dir, const std::string& key);

/// The fall-off the file holds for exactly this key; nothing if the file is missing, holds
/// another key or cannot be read as one (a damaged file is ignored, then replaced). `check`, if
/// not null, gets the right-side stop check written with it (nothing if none was).
std::optional<FallOff> ReadCachedFallOff(const std::filesystem::path& file, const std::string& key,
                                         std::optional<SideStopCheck>* check = nullptr);

/// Writes the fall-off (and the right-side stop check, if any) under the key (the folder made if
/// need be; the file replaced atomically). InputError naming the file if it cannot be written.
void WriteCachedFallOff(const std::filesystem::path& file, const std::string& key,
                        const FallOff& fall_off,
                        const std::optional<SideStopCheck>& check = std::nullopt);

}  // namespace hotlap::race
