#include "hotlap/logs/motec_ld_table.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <system_error>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/common/xml_file.h"
#include "hotlap/logs/telemetry.h"

namespace hotlap {
namespace {

// A column name the CSV writer takes: no comma, no control character.
std::string ColumnSafe(std::string name) {
  for (char& c : name) {
    if (c == ',' || static_cast<unsigned char>(c) < 0x20) c = '_';
  }
  return name;
}

// The `.ldx` beside `ld_path`, whatever the case of its extension, or an empty path.
std::filesystem::path LdxBeside(const std::filesystem::path& ld_path) {
  for (const char* ext : {".ldx", ".LDX", ".Ldx"}) {
    std::filesystem::path p = ld_path;
    p.replace_extension(ext);
    std::error_code ec;
    if (std::filesystem::is_regular_file(p, ec)) return p;
  }
  return {};
}

}  // namespace

std::vector<double> ResampleLinear(const std::vector<double>& values, double rate_hz,
                                   double base_rate_hz, size_t base_count) {
  std::vector<double> out(base_count, std::nan(""));
  if (values.empty()) return out;
  const double last = static_cast<double>(values.size() - 1);
  for (size_t k = 0; k < base_count; ++k) {
    // Position in the channel's samples; k * rate / base is exact where the rates divide.
    double pos = static_cast<double>(k) * rate_hz / base_rate_hz;
    const double nearest = std::round(pos);
    if (std::abs(pos - nearest) <= 1e-9) pos = nearest;
    if (pos > last) break;
    const auto i = static_cast<size_t>(std::floor(pos));
    const double frac = pos - static_cast<double>(i);
    if (frac == 0.0) {
      out[k] = values[i];
    } else {
      out[k] = values[i] + frac * (values[i + 1] - values[i]);  // NaN if either is
    }
  }
  return out;
}

std::optional<std::vector<double>> ReadLdxBeacons(const std::filesystem::path& ld_path) {
  const std::filesystem::path ldx = LdxBeside(ld_path);
  if (ldx.empty()) return std::nullopt;
  const XmlFile xml = XmlFile::Load(ldx);
  std::vector<pugi::xml_node> markers;
  bool named_group = false;
  for (const pugi::xpath_node& g : xml.root().select_nodes("//MarkerGroup[@Name='Beacons']")) {
    named_group = true;
    for (const pugi::xml_node& m : g.node().children("Marker")) markers.push_back(m);
  }
  if (!named_group) {
    for (const pugi::xpath_node& m : xml.root().select_nodes("//Marker")) {
      markers.push_back(m.node());
    }
  }
  std::vector<double> beacons;
  for (const pugi::xml_node& m : markers) {
    const std::string_view text = m.attribute("Time").value();
    double us = std::nan("");
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), us);
    if (text.empty() || ec != std::errc() || end != text.data() + text.size() ||
        !std::isfinite(us)) {
      throw InputError(fmt::format("{}:{}: Marker Time '{}' is not a number (microseconds)",
                                   ldx.string(), xml.Line(m), text));
    }
    const double t = us / 1e6;
    if (!beacons.empty() && !(t > beacons.back())) {
      throw InputError(fmt::format(
          "{}:{}: Marker Time {} s must follow {} s (beacons are lap crossing times, increasing)",
          ldx.string(), xml.Line(m), t, beacons.back()));
    }
    beacons.push_back(t);
  }
  return beacons;
}

MotecTable MotecLdTable(const LdLog& log, const MotecChannelMap& map,
                        const std::optional<std::vector<double>>& ldx_beacons,
                        const LdTableOptions& options) {
  const std::string file = log.path.string();
  double base_rate = 0.0;
  double end_s = -1.0;
  for (const LdChannel& c : log.channels) {
    if (c.name == "Time") {
      throw InputError(fmt::format(
          "{}: byte {}: channel 'Time': hotlap names the time base so; rename the channel", file,
          c.descriptor_at + 32));
    }
    if (c.values.empty()) continue;
    base_rate = std::max(base_rate, static_cast<double>(c.rate_hz));
    end_s = std::max(end_s, static_cast<double>(c.values.size() - 1) / c.rate_hz);
  }
  if (end_s < 0.0) throw InputError(fmt::format("{}: no channel has any samples", file));
  if (options.rate_hz) {
    if (!(std::isfinite(*options.rate_hz) && *options.rate_hz > 0.0)) {
      throw InputError(
          fmt::format("{}: time base rate {} Hz: must be positive", file, *options.rate_hz));
    }
    base_rate = *options.rate_hz;
  }
  // A bound on the table, so that a corrupted rate or count cannot ask for more memory than a
  // real log needs (a day at 1 kHz is 86.4 million rows).
  constexpr double kMaxRows = 1e8;
  const double rows = std::floor(end_s * base_rate + 1e-9) + 1;
  if (!(rows <= kMaxRows)) {
    throw InputError(fmt::format(
        "{}: {:.6g} s at {:g} Hz would be {:.4g} rows on the time base (at most {:g}): a corrupted "
        "rate or sample count, or choose a lower time base rate",
        file, end_s, base_rate, rows, kMaxRows));
  }
  const auto count = static_cast<size_t>(rows);

  // Time first, then the channels in list order.
  std::vector<std::string> names{"Time"};
  std::vector<std::string> units{"s"};
  for (const LdChannel& c : log.channels) {
    names.push_back(ColumnSafe(c.name));
    units.push_back(c.unit);
  }
  const std::vector<MotecChannelPlan> plans = PlanMotecChannels(names, units, map, [&](size_t c) {
    return c == 0 ? fmt::format("{}: the time base", file)
                  : fmt::format("{}: channel '{}' (descriptor at byte {})", file, names[c],
                                log.channels[c - 1].descriptor_at);
  });

  MotecTable out;
  CsvTable& table = out.table;
  table.path = log.path;
  std::vector<double> time(count);
  for (size_t k = 0; k < count; ++k) time[k] = static_cast<double>(k) / base_rate;
  std::vector<std::string> unmapped;
  for (size_t c = 0; c < names.size(); ++c) {
    table.columns.push_back(plans[c].column);
    if (plans[c].entry == nullptr) unmapped.push_back(names[c]);
    if (c == 0) {
      table.values.push_back(time);
      out.channels.push_back({"Time", "s", base_rate, count});
      continue;
    }
    const LdChannel& ch = log.channels[c - 1];
    std::vector<double> v = ResampleLinear(ch.values, ch.rate_hz, base_rate, count);
    if (plans[c].entry != nullptr) {
      for (double& x : v) x = plans[c].conversion.Apply(x);
    }
    table.values.push_back(std::move(v));
    out.channels.push_back({names[c], ch.unit, static_cast<double>(ch.rate_hz), ch.values.size()});
  }
  for (size_t k = 0; k < count; ++k) table.line_numbers.push_back(static_cast<int>(k) + 2);

  // Laps from the .ldx beacons.
  const std::vector<double> beacons = ldx_beacons.value_or(std::vector<double>{});
  std::vector<double> laps(count);
  int last_lap = 1;
  for (size_t k = 0; k < count; ++k) {
    const int lap = MotecLapAt(time[k], beacons);
    laps[k] = lap;
    last_lap = std::max(last_lap, lap);
  }
  table.columns.push_back("lap");
  table.values.push_back(std::move(laps));

  const LdMetadata& m = log.metadata;
  auto add = [&](const char* key, const std::string& value) {
    if (!value.empty()) table.metadata.emplace_back(key, value);
  };
  add("Format", "MoTeC .ld");
  add("Venue", m.venue);
  add("Vehicle", m.vehicle);
  add("Driver", m.driver);
  add("Device", m.device_type.empty() ? std::string()
                                      : fmt::format("{} serial {} version {}", m.device_type,
                                                    m.device_serial, m.device_version));
  add("Log Date", m.date);
  add("Log Time", m.time);
  add("Event", m.event);
  add("Session", m.session);
  add("Short Comment", m.short_comment);
  add("Sample Rate", fmt::format("{:g} Hz", base_rate));
  add("laps", std::to_string(last_lap));
  add("lap source", ldx_beacons ? "beacons of the .ldx file" : "none (no .ldx file): one lap");
  if (!unmapped.empty()) {
    std::string list;
    for (const std::string& name : unmapped) list += (list.empty() ? "" : ", ") + name;
    add("unmapped channels", list);
  }
  add("channel map", map.path.string());
  // A metadata key holds no colon and no line break; values no line break.
  for (auto& [key, value] : table.metadata) {
    std::replace(key.begin(), key.end(), ':', '-');
    std::replace(value.begin(), value.end(), '\n', ' ');
    std::replace(value.begin(), value.end(), '\r', ' ');
  }
  out.sources = MotecSources(map);
  return out;
}

MotecTable ReadMotecLdTable(const std::filesystem::path& path, const MotecChannelMap& map,
                            const LdTableOptions& options) {
  const LdLog log = ReadMotecLd(path);
  return MotecLdTable(log, map, ReadLdxBeacons(path), options);
}

}  // namespace hotlap
