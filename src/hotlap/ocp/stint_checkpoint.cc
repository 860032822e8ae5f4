#include "hotlap/ocp/stint_checkpoint.h"

#include <cstring>
#include <fstream>
#include <system_error>
#include <vector>

#include <fmt/format.h>

#include "hotlap/common/atomic_file.h"
#include "hotlap/common/error.h"
#include "hotlap/common/fnv1a.h"
#include "hotlap/ocp/solve_result_bytes.h"
#include "hotlap/ocp/stint.h"

namespace hotlap::ocp {

namespace fs = std::filesystem;

namespace {

constexpr char kMagic[8] = {'h', 'o', 't', 'l', 'a', 'p', 'S', '1'};

template <class T>
std::string_view Bytes(const T& v) {
  return {reinterpret_cast<const char*>(&v), sizeof(T)};
}

std::string_view Bytes(const std::vector<double>& v) {
  return {reinterpret_cast<const char*>(v.data()), v.size() * sizeof(double)};
}

}  // namespace

StintCheckpoints::StintCheckpoints(fs::path dir, std::uint64_t fingerprint)
    : dir_(std::move(dir)), fingerprint_(fingerprint) {
  std::error_code ec;
  fs::create_directories(dir_, ec);
  if (!fs::is_directory(dir_)) {
    throw InputError(fmt::format("checkpoint folder '{}': {}", dir_.string(),
                                 ec ? ec.message() : "not a folder"));
  }
}

std::optional<std::string> StintCheckpoints::ReadPayload(const fs::path& path) const {
  // Only a regular file is a checkpoint (anything else is not used, not an error).
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return std::nullopt;
  std::string bytes;
  try {
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  } catch (const std::exception&) {
    return std::nullopt;
  }
  const size_t header = sizeof(kMagic) + sizeof(std::uint64_t);
  if (bytes.size() < header + sizeof(std::uint64_t) ||
      std::memcmp(bytes.data(), kMagic, sizeof(kMagic)) != 0) {
    return std::nullopt;
  }
  std::uint64_t fingerprint = 0, hash = 0;
  std::memcpy(&fingerprint, bytes.data() + sizeof(kMagic), sizeof(fingerprint));
  std::memcpy(&hash, bytes.data() + bytes.size() - sizeof(hash), sizeof(hash));
  // A file cut short or changed is not used (the writes are atomic, so only a foreign hand).
  if (Fnv1a64(std::string_view(bytes).substr(0, bytes.size() - sizeof(hash))) != hash) {
    return std::nullopt;
  }
  if (fingerprint != fingerprint_) {
    ++foreign_;
    return std::nullopt;
  }
  return bytes.substr(header, bytes.size() - header - sizeof(hash));
}

void StintCheckpoints::WritePayload(const fs::path& path, const std::string& payload) const {
  std::string bytes(kMagic, sizeof(kMagic));
  bytes += Bytes(fingerprint_);
  bytes += payload;
  const std::uint64_t hash = Fnv1a64(bytes);
  bytes += Bytes(hash);
  WriteFileAtomically(path, [&](std::ostream& out) { out.write(bytes.data(), bytes.size()); });
}

std::optional<PresolvedLap> StintCheckpoints::ReadGreedyLap(int lap) const {
  const std::optional<std::string> payload =
      ReadPayload(dir_ / fmt::format("greedy_lap_{}.bin", lap));
  if (!payload) return std::nullopt;
  try {
    std::vector<SolveResult> s = DecodeSolveResults(*payload);
    if (s.size() != 2) return std::nullopt;
    return PresolvedLap{std::move(s[0]), std::move(s[1]), {}, {}, {}};
  } catch (const InputError&) {
    return std::nullopt;
  }
}

void StintCheckpoints::WriteGreedyLap(int lap, const PresolvedLap& solves) const {
  WritePayload(dir_ / fmt::format("greedy_lap_{}.bin", lap),
               EncodeSolveResults({solves.coarse, solves.fine}));
}

std::optional<SolveResult> StintCheckpoints::ReadStintIterate() const {
  const std::optional<std::string> payload = ReadPayload(dir_ / "stint_iterate.bin");
  if (!payload) return std::nullopt;
  try {
    std::vector<SolveResult> s = DecodeSolveResults(*payload);
    if (s.size() != 1 || s[0].x.empty()) return std::nullopt;
    return std::move(s[0]);
  } catch (const InputError&) {
    return std::nullopt;
  }
}

void StintCheckpoints::WriteStintIterate(const SolveResult& iterate) const {
  WritePayload(dir_ / "stint_iterate.bin", EncodeSolveResults({iterate}));
}

std::uint64_t StintFingerprint(const StintOptions& o, const track::Track& track,
                               const LapWarmUp& warm_up) {
  std::uint64_t h = Fnv1a64("hotlap stint " HOTLAP_VERSION);
  h = Fnv1a64(o.checkpoint_key, h);
  for (const double v : {static_cast<double>(o.laps),
                         o.wear_scale,
                         o.fuel_kg,
                         o.bsfc_kg_per_J,
                         o.lap.step_m,
                         o.lap.front_disc_limit.value_or(-1.0),
                         static_cast<double>(o.lap.thermal_start),
                         o.lap.racing_carcass_rise_K,
                         o.lap.ambient_temp,
                         o.lap.track_temp,
                         o.lap.line_margin_m,
                         o.lap.car_half_width_m,
                         o.lap.coarse_step_m,
                         o.lap.pedal_smoothing,
                         o.lap.steer_smoothing_weight,
                         o.lap.pedal_smoothing_weight,
                         static_cast<double>(o.lap.convex_element_hessians),
                         static_cast<double>(o.lap.all_brake_states),
                         static_cast<double>(o.lap.wear_in_programme),
                         o.lap.ipopt.tolerance,
                         o.lap.ipopt.constraint_tolerance,
                         track.length_m()}) {
    h = Fnv1a64(Bytes(v), h);
  }
  for (const auto& [name, value] : o.lap.ipopt.extra) h = Fnv1a64(name + "=" + value + ";", h);
  for (int c = 0; c < 4; ++c) {
    const sim::CornerHistory& t = warm_up.guess.thermal.corners[c];
    for (const std::vector<double>* v : {&t.tread_temp, &t.carcass_temp, &t.wear, &t.disc_temp,
                                         &t.calliper_temp, &t.rim_temp, &t.disc_bulk_temp}) {
      h = Fnv1a64(Bytes(*v), h);
    }
  }
  h = Fnv1a64(Bytes(warm_up.guess.speed), h);
  h = Fnv1a64(Bytes(warm_up.guess.time), h);
  return h;
}

}  // namespace hotlap::ocp
