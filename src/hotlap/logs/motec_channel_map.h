#pragma once
/// @file
/// The channel map of the MoTeC i2 CSV reader (docs/telemetry-formats.md): which MoTeC channel
/// name is which hotlap channel, and the MoTeC units converted to hotlap's.
///
/// How to use: LoadMotecChannelMap(path) reads a YAML file `channels: {MoTeC name: hotlap
/// channel}` (hotlap channel `<quantity>[_<corner>]`, e.g. `speed`, `disc_temp_fl`);
/// DefaultMotecChannelMapPath() is the shipped one. ConvertMotecValue() converts one value from a
/// MoTeC unit to the canonical file unit of a hotlap quantity (CanonicalUnit in telemetry.h).
///
/// Pitfalls: several MoTeC names may map to one hotlap channel; the first of them in the map's
/// order that the file has is used and the others are carried through unmapped.

#include <cstddef>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hotlap/common/corner.h"

namespace hotlap {

/// One entry of a channel map.
struct MotecChannelEntry {
  /// The channel name as i2 writes it, e.g. "Wheel Speed FL".
  std::string motec_name;
  /// The hotlap quantity of telemetry.h's table, e.g. "speed".
  std::string quantity;
  /// The corner, or nullopt for a whole-car channel.
  std::optional<Corner> corner;
};

/// A channel map, in file order.
struct MotecChannelMap {
  /// The file it was read from, for messages.
  std::filesystem::path path;
  std::vector<MotecChannelEntry> entries;

  /// The entry for a MoTeC name (exact, case-sensitive), or nullptr.
  const MotecChannelEntry* Find(std::string_view motec_name) const;
  /// The MoTeC names that map to this hotlap channel, in map order.
  std::vector<std::string> NamesFor(std::string_view quantity, std::optional<Corner> corner) const;
};

/// The shipped map in the data folder `data_dir`: `data_dir/motec_channels.yaml`.
std::filesystem::path MotecChannelMapPath(const std::filesystem::path& data_dir);

/// Reads a channel map: a YAML mapping with one key `channels`, itself a mapping from MoTeC
/// channel names to hotlap channels `<quantity>[_<corner>]`. Throws InputError naming the file,
/// the line and the entry for YAML errors, an unknown quantity or corner, a corner on `time` or
/// `distance`, or a MoTeC name given twice.
MotecChannelMap LoadMotecChannelMap(const std::filesystem::path& path);

/// The MoTeC units understood: km/h, mph, m/s, bar, psi, kPa, degF, degC (also C), K, g, m/s^2,
/// deg, rad, rpm, %, N, kN, s, m, mm, W, kW and "" (none).
std::vector<std::string_view> MotecUnits();

/// True if `unit` is one of MotecUnits().
bool IsMotecUnit(std::string_view unit);

/// A linear unit conversion: converted = value * scale + offset.
struct MotecConversion {
  double scale = 1.0;
  double offset = 0.0;
  double Apply(double value) const { return value * scale + offset; }
};

/// The conversion from the MoTeC unit `unit` to the canonical file unit of the hotlap `quantity`
/// (speed m/s, forces N, slip_angle rad, temperatures degC, wear mm, rolling_radius m, powers W,
/// dimensionless 1 (% divided by 100), time s, distance m). Throws InputError naming `where`
/// (e.g. "FILE:LINE: channel 'Ground Speed'") and the unit, for a unit that is not a MoTeC unit
/// or is of another kind than the quantity (e.g. "bar" for a speed), listing the units it takes.
MotecConversion MotecConversionFor(std::string_view unit, std::string_view quantity,
                                   std::string_view where);

/// What becomes of one channel of a MoTeC log (CSV export or `.ld`).
struct MotecChannelPlan {
  /// The map entry that gives its hotlap channel, or nullptr: carried through unmapped.
  const MotecChannelEntry* entry = nullptr;
  /// From the logged unit to the hotlap column's canonical unit (identity when unmapped).
  MotecConversion conversion;
  /// The hotlap column (e.g. `speed_mps`), or the MoTeC name when unmapped.
  std::string column;
};

/// Plans a log's channels `names` (unique) with their logged `units`: a name in `map` becomes its
/// hotlap channel in the canonical unit; `Time` and `Distance` are `time` and `distance` also
/// without an entry; where several names give one hotlap channel, the first in the map's order
/// that the log has wins and the others are carried through. The entries point into `map` (or to
/// static built-ins): keep `map` alive. Throws MotecConversionFor's InputError for a mapped
/// channel's unit, with `where(c)` naming channel c (e.g. "FILE:LINE: channel 'X' (column 3)").
std::vector<MotecChannelPlan> PlanMotecChannels(const std::vector<std::string>& names,
                                                const std::vector<std::string>& units,
                                                const MotecChannelMap& map,
                                                const std::function<std::string(size_t)>& where);

/// For each hotlap channel key of the map (`speed`, `disc_temp_fl`, ...), the MoTeC names that
/// would give it, in map order, for the missing-channel messages (Telemetry).
std::map<std::string, std::vector<std::string>, std::less<>> MotecSources(
    const MotecChannelMap& map);

}  // namespace hotlap
