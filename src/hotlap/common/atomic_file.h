#pragma once
/// @file
/// Writing result files so that an interrupted or failed run never leaves a half-written file
/// under the final name: write to a temporary file in the target folder, then rename it into
/// place (rename within one folder is atomic on POSIX file systems).

#include <filesystem>
#include <functional>
#include <ostream>

namespace hotlap {

/// Calls `write(stream)` on a temporary file beside `path`, then renames it to `path`.
/// If `write` throws, or the stream fails, the temporary is removed, `path` is left as it was,
/// and the error is rethrown (stream failures as InputError naming the path).
void WriteFileAtomically(const std::filesystem::path& path,
                         const std::function<void(std::ostream&)>& write);

}  // namespace hotlap
