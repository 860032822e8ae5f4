#include "hotlap/logs/motec_channel_map.h"

#include <array>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "hotlap/common/error.h"
#include "hotlap/common/string_match.h"
#include "hotlap/common/yaml_reader.h"
#include "hotlap/logs/telemetry.h"

namespace hotlap {
namespace {

// The kinds of unit; each has a base unit the table converts to.
enum class Kind {
  kSpeed,
  kPressure,
  kTemperature,
  kAcceleration,
  kAngle,
  kRotation,
  kRatio,
  kForce,
  kTime,
  kLength,
  kPower
};

// base = value * scale + offset. Bases: m/s, kPa, degC, m/s^2, rad, rpm, 1, N, s, m, W.
struct MotecUnit {
  std::string_view name;
  Kind kind;
  double scale;
  double offset;
};

constexpr double kStandardGravity = 9.80665;  // m/s^2 per g
constexpr std::array kUnits = {
    MotecUnit{"km/h", Kind::kSpeed, 1.0 / 3.6, 0.0},
    MotecUnit{"mph", Kind::kSpeed, 0.44704, 0.0},
    MotecUnit{"m/s", Kind::kSpeed, 1.0, 0.0},
    MotecUnit{"bar", Kind::kPressure, 100.0, 0.0},
    MotecUnit{"psi", Kind::kPressure, 6.894757293168361, 0.0},
    MotecUnit{"kPa", Kind::kPressure, 1.0, 0.0},
    MotecUnit{"degF", Kind::kTemperature, 5.0 / 9.0, -32.0 * 5.0 / 9.0},
    MotecUnit{"degC", Kind::kTemperature, 1.0, 0.0},
    MotecUnit{"C", Kind::kTemperature, 1.0, 0.0},
    MotecUnit{"K", Kind::kTemperature, 1.0, -273.15},
    // The degree sign as .ld loggers write it (Latin-1 0xB0, read as UTF-8).
    MotecUnit{"\u00B0C", Kind::kTemperature, 1.0, 0.0},
    MotecUnit{"\u00B0F", Kind::kTemperature, 5.0 / 9.0, -32.0 * 5.0 / 9.0},
    // The same in a CSV exported in a Windows code page (the single byte 0xB0), and Fahrenheit
    // as "F" beside "C".
    MotecUnit{"\xB0"
              "C",
              Kind::kTemperature, 1.0, 0.0},
    MotecUnit{"\xB0"
              "F",
              Kind::kTemperature, 5.0 / 9.0, -32.0 * 5.0 / 9.0},
    MotecUnit{"F", Kind::kTemperature, 5.0 / 9.0, -32.0 * 5.0 / 9.0},
    MotecUnit{"g", Kind::kAcceleration, kStandardGravity, 0.0},
    MotecUnit{"m/s^2", Kind::kAcceleration, 1.0, 0.0},
    MotecUnit{"deg", Kind::kAngle, std::numbers::pi / 180.0, 0.0},
    MotecUnit{"rad", Kind::kAngle, 1.0, 0.0},
    MotecUnit{"rpm", Kind::kRotation, 1.0, 0.0},
    MotecUnit{"%", Kind::kRatio, 0.01, 0.0},
    MotecUnit{"", Kind::kRatio, 1.0, 0.0},
    MotecUnit{"N", Kind::kForce, 1.0, 0.0},
    MotecUnit{"kN", Kind::kForce, 1000.0, 0.0},
    MotecUnit{"s", Kind::kTime, 1.0, 0.0},
    MotecUnit{"m", Kind::kLength, 1.0, 0.0},
    MotecUnit{"mm", Kind::kLength, 0.001, 0.0},
    MotecUnit{"W", Kind::kPower, 1.0, 0.0},
    MotecUnit{"kW", Kind::kPower, 1000.0, 0.0},
};

// The kind of a hotlap quantity and the factor from the kind's base to its canonical file unit.
struct QuantityKind {
  Kind kind;
  double base_to_canonical;
};

QuantityKind KindOf(std::string_view quantity) {
  if (quantity == "speed") return {Kind::kSpeed, 1.0};
  if (quantity == "fx" || quantity == "fy" || quantity == "fz") return {Kind::kForce, 1.0};
  if (quantity == "slip_angle") return {Kind::kAngle, 1.0};
  if (quantity.ends_with("_temp")) return {Kind::kTemperature, 1.0};
  if (quantity == "slip_ratio" || quantity == "grip_factor") return {Kind::kRatio, 1.0};
  if (quantity == "wear") return {Kind::kLength, 1000.0};  // canonical mm
  if (quantity == "rolling_radius" || quantity == "distance") return {Kind::kLength, 1.0};
  if (quantity == "time") return {Kind::kTime, 1.0};
  if (quantity == "pressure") return {Kind::kPressure, 1.0};  // canonical kPa
  return {Kind::kPower, 1.0};                                 // brake_power, q1..q7
}

// "FILE:LINE: " for a YAML node.
std::string At(const std::filesystem::path& path, const YAML::Node& node) {
  return fmt::format("{}:{}: ", path.string(), node.Mark().line + 1);
}

}  // namespace

const MotecChannelEntry* MotecChannelMap::Find(std::string_view motec_name) const {
  for (const MotecChannelEntry& e : entries) {
    if (e.motec_name == motec_name) return &e;
  }
  return nullptr;
}

std::vector<std::string> MotecChannelMap::NamesFor(std::string_view quantity,
                                                   std::optional<Corner> corner) const {
  std::vector<std::string> names;
  for (const MotecChannelEntry& e : entries) {
    if (e.quantity == quantity && e.corner == corner) names.push_back(e.motec_name);
  }
  return names;
}

std::filesystem::path MotecChannelMapPath(const std::filesystem::path& data_dir) {
  return data_dir / "motec_channels.yaml";
}

MotecChannelMap LoadMotecChannelMap(const std::filesystem::path& path) {
  const std::string file = path.string();
  YAML::Node root;
  try {
    root = YAML::LoadFile(file);
  } catch (const YAML::BadFile&) {
    throw InputError(fmt::format("cannot read channel map '{}'", file));
  } catch (const YAML::Exception& e) {
    throw InputError(fmt::format("{}:{}: {}", file, e.mark.line + 1, e.msg));
  }
  if (!root.IsMap() || !root["channels"] || !root["channels"].IsMap()) {
    throw InputError(fmt::format(
        "{}: a channel map is a mapping 'channels: {{MoTeC name: hotlap channel}}'", file));
  }
  CheckYamlKeys(root, path);  // every key a name, before the keys are read as text
  for (const auto& key : root) {
    if (key.first.as<std::string>() != "channels") {
      throw InputError(fmt::format("{}unknown key '{}' (the only key is 'channels')",
                                   At(path, key.first), key.first.as<std::string>()));
    }
  }
  MotecChannelMap map;
  map.path = path;
  for (const auto& item : root["channels"]) {
    const std::string name = item.first.as<std::string>();
    if (!item.second.IsScalar()) {
      throw InputError(fmt::format("{}'{}': the value must be a hotlap channel name",
                                   At(path, item.second), name));
    }
    const std::string target = item.second.as<std::string>();
    MotecChannelEntry entry{name, target, std::nullopt};
    const size_t underscore = target.rfind('_');
    if (underscore != std::string::npos) {
      if (const std::optional<Corner> c = ParseCorner(target.substr(underscore + 1))) {
        entry.quantity = target.substr(0, underscore);
        entry.corner = c;
      }
    }
    bool known = true;
    try {
      AcceptedUnits(entry.quantity);
    } catch (const std::invalid_argument&) {
      known = false;
    }
    if (!known || (entry.corner && (entry.quantity == "time" || entry.quantity == "distance"))) {
      throw InputError(fmt::format(
          "{}'{}': '{}' is not a hotlap channel (<quantity>[_<corner>], quantities of "
          "docs/telemetry-csv.md, corners fl, fr, rl, rr; time and distance without corner)",
          At(path, item.second), name, target));
    }
    if (map.Find(name) != nullptr) {
      throw InputError(fmt::format("{}'{}' is given twice", At(path, item.first), name));
    }
    map.entries.push_back(std::move(entry));
  }
  return map;
}

std::vector<std::string_view> MotecUnits() {
  std::vector<std::string_view> names;
  for (const MotecUnit& u : kUnits) {
    if (!u.name.empty()) names.push_back(u.name);
  }
  return names;
}

bool IsMotecUnit(std::string_view unit) {
  for (const MotecUnit& u : kUnits) {
    if (u.name == unit) return true;
  }
  return false;
}

MotecConversion MotecConversionFor(std::string_view unit, std::string_view quantity,
                                   std::string_view where) {
  const QuantityKind q = KindOf(quantity);
  std::vector<std::string> takes;
  for (const MotecUnit& u : kUnits) {
    if (u.kind == q.kind) takes.push_back(u.name.empty() ? "none" : std::string(u.name));
  }
  for (const MotecUnit& u : kUnits) {
    if (u.name != unit) continue;
    if (u.kind != q.kind) {
      throw InputError(fmt::format("{}: unit '{}' is not a unit of {} (it takes {})", where, unit,
                                   quantity, QuotedList(takes)));
    }
    return {u.scale * q.base_to_canonical, u.offset * q.base_to_canonical};
  }
  std::vector<std::string> all;
  for (std::string_view u : MotecUnits()) all.emplace_back(u);
  throw InputError(fmt::format("{}: unknown unit '{}' (units read: {}; {} takes {})", where, unit,
                               QuotedList(all), quantity, QuotedList(takes)));
}

std::vector<MotecChannelPlan> PlanMotecChannels(const std::vector<std::string>& names,
                                                const std::vector<std::string>& units,
                                                const MotecChannelMap& map,
                                                const std::function<std::string(size_t)>& where) {
  // "Time" and "Distance" are time and distance also without a map entry.
  static const MotecChannelEntry kTime{"Time", "time", std::nullopt};
  static const MotecChannelEntry kDistance{"Distance", "distance", std::nullopt};
  const size_t width = names.size();
  std::vector<MotecChannelPlan> plans(width);
  for (size_t c = 0; c < width; ++c) {
    plans[c].entry = map.Find(names[c]);
    if (plans[c].entry == nullptr && names[c] == "Time") plans[c].entry = &kTime;
    if (plans[c].entry == nullptr && names[c] == "Distance") plans[c].entry = &kDistance;
  }
  auto map_rank = [&](const MotecChannelEntry* e) {
    for (size_t i = 0; i < map.entries.size(); ++i) {
      if (&map.entries[i] == e) return i;
    }
    return map.entries.size();  // the built-in Time and Distance
  };
  // Of the names that give one hotlap channel, the first in the map's order wins.
  for (size_t c = 0; c < width; ++c) {
    for (size_t d = 0; d < width && plans[c].entry != nullptr; ++d) {
      const MotecChannelEntry* other = plans[d].entry;
      if (d != c && other != nullptr && other->quantity == plans[c].entry->quantity &&
          other->corner == plans[c].entry->corner && map_rank(other) < map_rank(plans[c].entry)) {
        plans[c].entry = nullptr;
      }
    }
  }
  for (size_t c = 0; c < width; ++c) {
    MotecChannelPlan& plan = plans[c];
    if (plan.entry == nullptr) {
      plan.column = names[c];
      continue;
    }
    const std::string& quantity = plan.entry->quantity;
    plan.conversion = MotecConversionFor(units[c], quantity, where(c));
    plan.column = ChannelColumn(quantity, plan.entry->corner, CanonicalUnit(quantity));
  }
  return plans;
}

std::map<std::string, std::vector<std::string>, std::less<>> MotecSources(
    const MotecChannelMap& map) {
  std::map<std::string, std::vector<std::string>, std::less<>> sources;
  for (const MotecChannelEntry& e : map.entries) {
    std::string key = e.quantity;
    if (e.corner) key += "_" + std::string(CornerName(*e.corner));
    sources[key].push_back(e.motec_name);
  }
  return sources;
}

}  // namespace hotlap
