#include "hotlap/ocp/lap_cache.h"

#include <algorithm>
#include <cmath>
#include <ostream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "hotlap/common/atomic_file.h"
#include "hotlap/common/error.h"
#include "hotlap/common/fnv1a.h"
#include "hotlap/common/read_file.h"

namespace hotlap::ocp {

namespace fs = std::filesystem;

std::string CachedLapHash(const CachedLapKey& key) {
  std::string text = key.family + "\n";
  for (const auto& [k, v] : key.coordinates) text += fmt::format("{}={:.17g}\n", k, v);
  return fmt::format("{:016x}", Fnv1a64(text));
}

double CoordinateDistance(const std::map<std::string, double>& a,
                          const std::map<std::string, double>& b,
                          const std::map<std::string, double>& scales) {
  double sum = 0.0;
  for (const auto& [k, v] : a) {
    const auto s = scales.find(k);
    const double scale =
        s != scales.end() && s->second > 0.0 ? s->second : std::max(std::abs(v), 1.0);
    const double d = (v - b.at(k)) / scale;
    sum += d * d;
  }
  return std::sqrt(sum);
}

std::vector<CachedLap> NearestCachedLaps(const fs::path& dir, const CachedLapKey& key,
                                         const std::map<std::string, double>& scales, int count) {
  std::vector<CachedLap> found;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    if (e.path().extension() != ".json") continue;
    fs::path lap = e.path();
    lap.replace_extension(".lap");
    try {
      const nlohmann::json j = nlohmann::json::parse(ReadWholeFile(e.path()));
      if (j.at("family").get<std::string>() != key.family || !fs::exists(lap, ec)) continue;
      std::map<std::string, double> coordinates;
      for (const auto& [k, v] : j.at("coordinates").items()) coordinates[k] = v.get<double>();
      const bool same_keys = std::equal(
          coordinates.begin(), coordinates.end(), key.coordinates.begin(), key.coordinates.end(),
          [](const auto& a, const auto& b) { return a.first == b.first; });
      if (!same_keys) continue;
      found.push_back({j.at("name").get<std::string>(), lap,
                       CoordinateDistance(key.coordinates, coordinates, scales)});
    } catch (const std::exception&) {
      continue;  // not an entry (cut short, another format): not a start
    }
  }
  std::sort(found.begin(), found.end(), [](const CachedLap& a, const CachedLap& b) {
    return a.distance != b.distance ? a.distance < b.distance : a.name < b.name;
  });
  if (static_cast<int>(found.size()) > count) found.resize(std::max(count, 0));
  return found;
}

void KeepCachedLap(const fs::path& dir, const CachedLapKey& key, const std::string& name,
                   const fs::path& saved, double lap_time_s, int iterations) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  const std::string hash = CachedLapHash(key);
  fs::rename(saved, dir / (hash + ".lap"), ec);
  if (ec) {
    throw InputError(
        fmt::format("lap cache {}: cannot keep the lap: {}", dir.string(), ec.message()));
  }
  nlohmann::json coordinates = nlohmann::json::object();
  for (const auto& [k, v] : key.coordinates) coordinates[k] = v;
  const nlohmann::json entry = {{"name", name},
                                {"family", key.family},
                                {"coordinates", coordinates},
                                {"lap_time_s", lap_time_s},
                                {"ipopt_iterations", iterations}};
  WriteFileAtomically(dir / (hash + ".json"),
                      [&](std::ostream& out) { out << entry.dump(1) << "\n"; });
}

}  // namespace hotlap::ocp
