#pragma once
// Shared helpers of the libFuzzer targets: most readers take a path, so each input is written to
// a file in this process's own temporary folder (under $TMPDIR, removed at exit), beside copies of
// the shipped files it may refer to by relative path (a car's tyre files, a configuration's ABS
// file).
//
// A target calls the reader and catches hotlap::InputError only: that is how a reader refuses bad
// input. Anything else (another exception, a crash, a sanitizer report, a leak, a hang) is a
// finding.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string_view>

namespace hotlap::fuzz {

/// This process's temporary folder, made on first use and removed at exit.
const std::filesystem::path& WorkDir();

/// WorkDir()/`name`, a copy of the source tree's `data_relative` (a file or a folder, relative to
/// the repository root), made once.
std::filesystem::path CopyOfData(std::string_view data_relative, std::string_view name);

/// Writes `size` bytes to `path` (replacing it) and returns `path`.
const std::filesystem::path& WriteInput(const std::filesystem::path& path, const std::uint8_t* data,
                                        std::size_t size);

/// The input as text.
inline std::string_view AsText(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

}  // namespace hotlap::fuzz
