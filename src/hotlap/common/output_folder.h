#pragma once
/// @file
/// The check a run makes before any work that an output file can be written where it was asked
/// for, so that it fails at once rather than after writing some of its outputs.

#include <filesystem>

namespace hotlap {

/// InputError unless the folder that will hold `path` exists and `path` is not itself a folder;
/// the message starts with `option` (e.g. "--json") and names the path.
void CheckOutputFolder(const std::filesystem::path& path, const char* option);

/// For an output that is a folder (created if missing): InputError unless `path` is a folder
/// already, or does not exist and its nearest existing ancestor is a folder this process may
/// write in. Creates nothing, so a run that refuses its input afterwards leaves nothing behind;
/// CreateOutputDirectory() makes it once the input has been accepted.
void CheckOutputDirectory(const std::filesystem::path& path, const char* option);

/// Creates the folder `path` and its missing parents; InputError naming `option`, the path and
/// the system's reason if it cannot.
void CreateOutputDirectory(const std::filesystem::path& path, const char* option);

}  // namespace hotlap
