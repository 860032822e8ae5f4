#include "hotlap/runs/stint_run.h"

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/common/folder_fingerprint.h"
#include "hotlap/common/units.h"

namespace hotlap::runs {

namespace fs = std::filesystem;

void CheckThreads(int threads, NameStyle style) {
  if (threads < 0 || threads > 256) {
    throw InputError(fmt::format("{}: {} is not 0 to 256 (0: one per core)",
                                 OptionName(style, "threads"), threads));
  }
}

ocp::StintOptions MakeStintOptions(const StintRunOptions& s, NameStyle style) {
  CheckThreads(s.run.threads, style);
  ocp::StintOptions o;
  o.laps = s.laps;
  o.wear_scale = s.wear_scale;
  o.fuel_kg = s.fuel_kg;
  if (s.bsfc_g_per_kWh) o.bsfc_kg_per_J = *s.bsfc_g_per_kWh * 1e-3 / 3.6e6;
  o.lap = ocp::MakeOptimalLapOptions(s.run);
  if (!s.checkpoint_dir.empty()) o.checkpoint_dir = s.checkpoint_dir;
  o.checkpoint_every = s.checkpoint_every;
  o.checkpoint_key = s.checkpoint_key;
  if (s.disc_limit_C) {
    if (!(*s.disc_limit_C > 0.0 && *s.disc_limit_C < 1500.0)) {
      throw InputError(fmt::format("{}: {:g} degC is not in (0, 1500)",
                                   OptionName(style, "disc_limit_C"), *s.disc_limit_C));
    }
    o.lap.front_disc_limit = CelsiusToKelvin(*s.disc_limit_C);
  }
  return o;
}

std::string StintCheckpointKey(const fs::path& car_file, const fs::path& track_file,
                               const std::vector<std::string>& overrides) {
  std::string key = FolderFingerprint(car_file.parent_path()) + FileFingerprint(track_file);
  for (const std::string& s : overrides) key += " set " + s + ";";
  return key;
}

}  // namespace hotlap::runs
