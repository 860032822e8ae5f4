#pragma once
/// @file
/// Reading a whole input file into memory: the one place that opens a file for its bytes, so every
/// reader (CSV, `.tir`, fastest-lap XML, YAML text edits) fails with the same message.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace hotlap {

/// The bytes of the file at `path`, unchanged (binary mode: no line-ending conversion). Throws
/// InputError "cannot read 'FILE': REASON" when the path is a folder, cannot be opened (the
/// system's reason, e.g. "No such file or directory") or fails while being read.
std::string ReadWholeFile(const std::filesystem::path& path);

/// The lines of a text file's contents, line k + 1 at index k: a UTF-8 byte-order mark dropped
/// from the start, split at "\n", a trailing "\r" (CRLF files) removed; nothing else touched.
/// The views point into `text`. A final line end gives no extra empty line.
std::vector<std::string_view> TextLines(std::string_view text);

}  // namespace hotlap
