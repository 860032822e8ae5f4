#pragma once
/// @file
/// The check a run makes before any work that an output file can be written where it was asked
/// for, so that it fails at once rather than after writing some of its outputs.

#include <filesystem>

namespace hotlap {

/// InputError unless the folder that will hold `path` exists and `path` is not itself a folder;
/// the message starts with `option` (e.g. "--json") and names the path.
void CheckOutputFolder(const std::filesystem::path& path, const char* option);

}  // namespace hotlap
