#include "hotlap/race/fall_off_cache.h"

#include <algorithm>
#include <cstdlib>
#include <sstream>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "hotlap/common/atomic_file.h"
#include "hotlap/common/error.h"
#include "hotlap/common/fnv1a.h"
#include "hotlap/common/folder_fingerprint.h"
#include "hotlap/common/read_file.h"

namespace hotlap::race {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kHeader = "hotlap race fall-off 2";

// The key on one line (line ends would end it early).
std::string OneLine(std::string key) {
  for (char& c : key) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  return key;
}

void WriteSeries(std::ostream& out, const char* name, const std::vector<double>& v) {
  out << name << ' ' << v.size();
  for (double x : v) out << ' ' << fmt::format("{:.17g}", x);
  out << '\n';
}

bool ReadSeries(std::istringstream& in, const char* name, std::vector<double>* v) {
  std::string word;
  size_t n = 0;
  if (!(in >> word) || word != name || !(in >> n) || n > 100000) return false;
  v->resize(n);
  for (double& x : *v) {
    if (!(in >> x)) return false;
  }
  return true;
}

bool ReadNumber(std::istringstream& in, const char* name, double* x) {
  std::string word;
  return (in >> word) && word == name && (in >> *x);
}

}  // namespace

fs::path DefaultCacheDir() {
  if (const char* d = std::getenv("HOTLAP_CACHE_DIR"); d != nullptr) return d;  // "": none
  if (const char* d = std::getenv("XDG_CACHE_HOME"); d != nullptr && *d != '\0') {
    return fs::path(d) / "hotlap";
  }
  if (const char* d = std::getenv("HOME"); d != nullptr && *d != '\0') {
    return fs::path(d) / ".cache" / "hotlap";
  }
  return {};
}

std::string CarFilesKey(const vehicle::Car& car) {
  std::string key = "car " + car.name + ":";
  std::error_code ec;
  const fs::path folder = car.path.parent_path();
  key +=
      car.path.empty() || !fs::is_directory(folder, ec) ? " no files;" : FolderFingerprint(folder);
  for (const vehicle::CarOverride& o : car.overrides)
    key += fmt::format(" set {}={:.17g};", o.key, o.value);
  return key;
}

fs::path FallOffCacheFile(const fs::path& dir, const std::string& key) {
  return dir / fmt::format("race-fall-off-{:016x}.txt", Fnv1a64(key));
}

std::optional<FallOff> ReadCachedFallOff(const fs::path& file, const std::string& key,
                                         std::optional<SideStopCheck>* check) {
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) return std::nullopt;
  std::string text;
  try {
    text = ReadWholeFile(file);
  } catch (const InputError&) {
    return std::nullopt;
  }
  const std::string first = std::string(kHeader) + '\n' + "key " + OneLine(key) + '\n';
  if (text.compare(0, first.size(), first) != 0) return std::nullopt;
  std::istringstream in(text.substr(first.size()));
  FallOff f;
  if (!ReadSeries(in, "lap_time_s", &f.lap_time_s) || f.lap_time_s.size() < 2 ||
      !ReadSeries(in, "heat_only_lap_time_s", &f.heat_only_lap_time_s) ||
      !ReadNumber(in, "fuel_s_per_kg", &f.fuel_s_per_kg) ||
      !ReadNumber(in, "reference_fuel_kg", &f.reference_fuel_kg) ||
      !ReadNumber(in, "restart_penalty_s", &f.restart_penalty_s)) {
    return std::nullopt;
  }
  std::string word;
  size_t laps = 0;
  if (!(in >> word) || word != "set_laps" || !(in >> laps) || laps > 100000) return std::nullopt;
  f.set_laps.resize(laps);
  for (SetLap& l : f.set_laps) {
    for (std::array<double, 4>* a :
         {&l.tread_temp, &l.carcass_temp, &l.disc_peak_temp, &l.wear_mm, &l.pressure}) {
      for (double& x : *a) {
        if (!(in >> x)) return std::nullopt;
      }
    }
  }
  size_t stops = 0;
  if (!(in >> word) || word != "right_stops" || !(in >> stops) || stops > 1000) return std::nullopt;
  for (size_t i = 0; i < stops; ++i) {
    int after = 0;
    f.right_stop_lap_time_s.emplace_back();
    if (!(in >> word) || word != "after" || !(in >> after) ||
        !ReadSeries(in, "lap_time_s", &f.right_stop_lap_time_s.back())) {
      return std::nullopt;
    }
    f.right_stop_after_laps.push_back(after);
  }
  std::optional<SideStopCheck> side;
  if (!(in >> word)) return std::nullopt;
  if (word == "side_check") {
    side.emplace();
    if (!(in >> side->before >> side->after) ||
        !ReadNumber(in, "max_abs_difference_s", &side->max_abs_difference_s) ||
        !ReadNumber(in, "mean_difference_s", &side->mean_difference_s) ||
        !ReadSeries(in, "driven_s", &side->driven_s) ||
        !ReadSeries(in, "fall_off_s", &side->fall_off_s) || !(in >> word)) {
      return std::nullopt;
    }
  }
  if (word != "end") return std::nullopt;
  if (check != nullptr) *check = std::move(side);
  return f;
}

void WriteCachedFallOff(const fs::path& file, const std::string& key, const FallOff& f,
                        const std::optional<SideStopCheck>& check) {
  std::error_code ec;
  fs::create_directories(file.parent_path(), ec);
  if (ec) {
    throw InputError(fmt::format("cannot make the cache folder '{}': {}",
                                 file.parent_path().string(), ec.message()));
  }
  WriteFileAtomically(file, [&](std::ostream& out) {
    out << kHeader << '\n' << "key " << OneLine(key) << '\n';
    WriteSeries(out, "lap_time_s", f.lap_time_s);
    WriteSeries(out, "heat_only_lap_time_s", f.heat_only_lap_time_s);
    out << "fuel_s_per_kg " << fmt::format("{:.17g}", f.fuel_s_per_kg) << '\n';
    out << "reference_fuel_kg " << fmt::format("{:.17g}", f.reference_fuel_kg) << '\n';
    out << "restart_penalty_s " << fmt::format("{:.17g}", f.restart_penalty_s) << '\n';
    out << "set_laps " << f.set_laps.size() << '\n';
    for (const SetLap& l : f.set_laps) {
      for (const std::array<double, 4>* a :
           {&l.tread_temp, &l.carcass_temp, &l.disc_peak_temp, &l.wear_mm, &l.pressure}) {
        for (double x : *a) out << fmt::format("{:.17g} ", x);
      }
      out << '\n';
    }
    out << "right_stops " << f.right_stop_after_laps.size() << '\n';
    for (size_t i = 0; i < f.right_stop_after_laps.size(); ++i) {
      out << "after " << f.right_stop_after_laps[i] << ' ';
      WriteSeries(out, "lap_time_s", f.right_stop_lap_time_s[i]);
    }
    if (check) {
      out << "side_check " << check->before << ' ' << check->after << '\n';
      out << "max_abs_difference_s " << fmt::format("{:.17g}", check->max_abs_difference_s) << '\n';
      out << "mean_difference_s " << fmt::format("{:.17g}", check->mean_difference_s) << '\n';
      WriteSeries(out, "driven_s", check->driven_s);
      WriteSeries(out, "fall_off_s", check->fall_off_s);
    }
    out << "end\n";
  });
}

}  // namespace hotlap::race
