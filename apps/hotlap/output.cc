#include "output.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "hotlap/common/atomic_file.h"
#include "hotlap/common/error.h"

namespace hotlap::app {

void WriteJsonFile(const std::filesystem::path& path, const nlohmann::json& json) {
  WriteFileAtomically(path, [&](std::ostream& out) { out << json.dump(2) << '\n'; });
}

void CheckOutputFolder(const std::filesystem::path& path, const char* option) {
  const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : ".";
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec)) {
    throw InputError(std::string(option) + " '" + path.string() + "': folder '" + folder.string() +
                     "' does not exist");
  }
  if (std::filesystem::is_directory(path, ec)) {
    throw InputError(std::string(option) + " '" + path.string() + "' is a folder, not a file");
  }
}

double RoundSignificant(double x, int digits) {
  if (!std::isfinite(x) || x == 0.0) return x;
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, x);
  return std::strtod(buffer, nullptr);
}

nlohmann::json JsonOrNull(const std::optional<double>& x, int digits) {
  return x ? nlohmann::json(RoundSignificant(*x, digits)) : nlohmann::json(nullptr);
}

}  // namespace hotlap::app
