#pragma once
/// @file
/// Reading a whole input file into memory: the one place that opens a file for its bytes, so every
/// reader (CSV, `.tir`, fastest-lap XML, YAML text edits) fails with the same message.

#include <filesystem>
#include <string>

namespace hotlap {

/// The bytes of the file at `path`, unchanged (binary mode: no line-ending conversion). Throws
/// InputError "cannot read 'FILE': REASON" when the path is a folder, cannot be opened (the
/// system's reason, e.g. "No such file or directory") or fails while being read.
std::string ReadWholeFile(const std::filesystem::path& path);

}  // namespace hotlap
