#include "hotlap/common/json_output.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <fmt/format.h>

#include "hotlap/common/atomic_file.h"

namespace hotlap {

void WriteJsonFile(const std::filesystem::path& path, const nlohmann::json& json) {
  WriteFileAtomically(path, [&](std::ostream& out) { out << json.dump(2) << '\n'; });
}

void WriteJsonFileAndSay(const std::filesystem::path& path, const nlohmann::json& json) {
  WriteJsonFile(path, json);
  fmt::print("wrote {}\n", path.string());
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

}  // namespace hotlap
