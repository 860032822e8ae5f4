#include "hotlap/common/folder_fingerprint.h"

#include <algorithm>
#include <vector>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/common/fnv1a.h"
#include "hotlap/common/read_file.h"

namespace hotlap {

namespace fs = std::filesystem;

namespace {

std::string Digits(const fs::path& file) {
  try {
    return fmt::format("{:016x}", Fnv1a64(ReadWholeFile(file)));
  } catch (const InputError&) {
    return "unreadable";
  }
}

}  // namespace

std::string FolderFingerprint(const fs::path& folder) {
  std::error_code ec;
  std::vector<fs::path> files;
  for (const auto& e : fs::recursive_directory_iterator(folder, ec)) {
    if (e.is_regular_file()) files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  std::string out;
  for (const fs::path& p : files) {
    out += fmt::format(" {} {};", fs::relative(p, folder, ec).string(), Digits(p));
  }
  return out;
}

std::string FileFingerprint(const fs::path& file) {
  return fmt::format(" {} {};", file.filename().string(), Digits(file));
}

}  // namespace hotlap
