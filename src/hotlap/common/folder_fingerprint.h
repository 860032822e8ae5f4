#pragma once
/// @file
/// What tells a folder of input files from another in a cache's or a checkpoint's key: each
/// regular file below it, by its path relative to the folder and the FNV-1a hash of its bytes.
/// The fall-off cache (race/fall_off_cache.h) and the stint's checkpoints (runs/stint_run.h) key
/// a car by its folder this way.

#include <filesystem>
#include <string>

namespace hotlap {

/// " <relative path> <16 hex digits>;" for every regular file below `folder`, in path order
/// ("unreadable" for the digits of a file that cannot be read); "" for a folder that is not there.
std::string FolderFingerprint(const std::filesystem::path& folder);

/// " <file name> <16 hex digits>;" of one file ("unreadable" if it cannot be read).
std::string FileFingerprint(const std::filesystem::path& file);

}  // namespace hotlap
