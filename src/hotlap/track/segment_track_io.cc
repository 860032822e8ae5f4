#include "hotlap/track/segment_track_io.h"

#include <charconv>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "hotlap/common/error.h"
#include "hotlap/common/string_match.h"
#include "hotlap/common/units.h"
#include "hotlap/common/yaml_reader.h"

namespace hotlap::track {

namespace {

const Range kLengthRange = Range::Positive("m");
const Range kAngleRange = Range::OpenClosed(0.0, 360.0, "deg");
const Range kBankRange = Range::Closed(-45.0, 45.0, "deg");
const Range kWidthRange = Range::OpenClosed(0.0, 100.0, "m");

bool EndsWith(const std::string& text, const std::string& suffix) {
  return text.size() > suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::optional<double> ParseNumber(const std::string& text) {
  const char* begin = text.data();
  const char* end = text.data() + text.size();
  if (begin != end && *begin == '+') ++begin;
  double value = 0.0;
  const auto [ptr, ec] = std::from_chars(begin, end, value);
  if (ec != std::errc() || ptr != end) return std::nullopt;
  return value;
}

// Reads the `solve:` mapping: each key is an unknown's name (with its unit suffix), each value
// its initial guess.
std::vector<LoopUnknown> ReadUnknowns(YamlReader& y, const std::filesystem::path& path) {
  std::vector<LoopUnknown> unknowns;
  if (!y.Has("solve")) return unknowns;
  YamlReader solve = y.Map("solve");  // checks that it is a mapping
  // YamlReader reads known keys; the names here are the file's own, so list them from the node.
  const YAML::Node node = YAML::LoadFile(path.string())["solve"];
  for (const auto& kv : node) {
    const std::string name = kv.first.as<std::string>();
    LoopUnknown u;
    u.name = name;
    if (EndsWith(name, "_m")) {
      u.kind = UnknownKind::kLength;
      u.guess = solve.Number(name, kLengthRange);
    } else if (EndsWith(name, "_deg")) {
      u.kind = UnknownKind::kAngle;
      u.guess = DegToRad(solve.Number(name, kAngleRange));
    } else {
      solve.Fail(name,
                 "an unknown's name ends in its unit: _m (a length or radius) or _deg (an arc "
                 "angle)");
    }
    u.value = u.guess;
    unknowns.push_back(u);
  }
  solve.Finish();
  return unknowns;
}

// A length, radius or angle: a number in `range` (in the key's unit, times `to_si`), or the name
// of an unknown of the same kind.
LoopValue ReadValue(YamlReader& seg, const std::string& key, const Range& range, double to_si,
                    UnknownKind kind, const std::vector<LoopUnknown>& unknowns,
                    std::vector<bool>& used) {
  if (!seg.Has(key)) seg.Number(key, range);  // throws the usual "missing field" message
  const std::string text = seg.String(key);
  if (const std::optional<double> number = ParseNumber(text)) {
    if (!range.Contains(*number)) {
      seg.Fail(key,
               fmt::format("value {:g} is out of range: must be {}", *number, range.Describe()));
    }
    return {*number * to_si, -1};
  }
  for (size_t k = 0; k < unknowns.size(); ++k) {
    if (unknowns[k].name != text) continue;
    if (unknowns[k].kind != kind) {
      seg.Fail(key, fmt::format("unknown '{}' has the wrong unit for this field: use an unknown "
                                "whose name ends in _{}",
                                text, kind == UnknownKind::kLength ? "m" : "deg"));
    }
    used[k] = true;
    return {0.0, static_cast<int>(k)};
  }
  std::vector<std::string> names;
  for (const LoopUnknown& u : unknowns) names.push_back(u.name);
  seg.Fail(key, fmt::format("'{}' is neither a number ({}) nor an unknown declared under "
                            "'solve' (declared: {})",
                            text, range.Describe(), QuotedList(names)));
}

Segment ReadSegment(YamlReader& seg, const std::string& field, double default_wl, double default_wr,
                    const std::vector<LoopUnknown>& unknowns, std::vector<bool>& used) {
  Segment s;
  s.field = field;
  const std::string type = seg.Choice("type", {"straight", "arc", "clothoid"});
  const auto length = [&] {
    return ReadValue(seg, "length_m", kLengthRange, 1.0, UnknownKind::kLength, unknowns, used);
  };
  if (type == "clothoid") {
    s.type = SegmentType::kClothoid;
    for (const char* key : {"bank_deg", "width_left_m", "width_right_m", "radius_m", "turn"}) {
      if (seg.Has(key)) {
        seg.Fail(key,
                 "a clothoid takes only length_m: its curvature ramps linearly and its bank and "
                 "widths blend smoothly from the previous segment's values to the next one's");
      }
    }
    s.length = length();
  } else {
    s.type = type == "arc" ? SegmentType::kArc : SegmentType::kStraight;
    if (s.type == SegmentType::kStraight) {
      s.length = length();
    } else {
      s.radius =
          ReadValue(seg, "radius_m", kLengthRange, 1.0, UnknownKind::kLength, unknowns, used);
      const bool has_angle = seg.Has("angle_deg"), has_length = seg.Has("length_m");
      if (has_angle == has_length) {
        seg.Fail("angle_deg", has_angle ? "give the arc's angle_deg or its length_m, not both"
                                        : "missing: an arc needs its angle_deg or its length_m");
      }
      s.arc_by_angle = has_angle;
      if (has_angle) {
        s.angle = ReadValue(seg, "angle_deg", kAngleRange, DegToRad(1.0), UnknownKind::kAngle,
                            unknowns, used);
      } else {
        s.length = length();
      }
      s.turn_sign = seg.Choice("turn", {"left", "right"}) == "left" ? 1 : -1;
    }
    s.bank_rad = DegToRad(seg.Number("bank_deg", kBankRange));
    s.width_left_m = seg.OptionalNumber("width_left_m", kWidthRange).value_or(default_wl);
    s.width_right_m = seg.OptionalNumber("width_right_m", kWidthRange).value_or(default_wr);
    if (s.type == SegmentType::kArc && s.radius.unknown < 0) {
      const double inside = s.turn_sign > 0 ? s.width_left_m : s.width_right_m;
      if (!(s.radius.value > inside)) {
        seg.Fail("radius_m", fmt::format("radius {:g} m is not larger than the inside half-width "
                                         "{:g} m: the inside edge would fold over",
                                         s.radius.value, inside));
      }
    }
  }
  seg.Finish();
  return s;
}

}  // namespace

SegmentLoop ReadSegmentLoop(const std::filesystem::path& path) {
  YamlReader y = YamlReader::Load(path);
  SegmentLoop loop;
  loop.path = path;
  loop.name = y.String("name");
  y.Choice("model", {"segments"});
  loop.target_length_m = y.OptionalNumber("length_m", kLengthRange);
  loop.start_finish_fraction =
      y.OptionalNumber("start_finish_fraction", Range{0.0, 1.0, true, false, ""}).value_or(0.0);
  const double wl = y.Number("width_left_m", kWidthRange);
  const double wr = y.Number("width_right_m", kWidthRange);
  loop.unknowns = ReadUnknowns(y, path);
  std::vector<bool> used(loop.unknowns.size(), false);
  std::vector<YamlReader> items = y.MapList("segments", 1);
  for (size_t i = 0; i < items.size(); ++i) {
    loop.segments.push_back(
        ReadSegment(items[i], fmt::format("segments[{}]", i), wl, wr, loop.unknowns, used));
  }
  y.Finish();

  // A clothoid joins two segments of constant curvature.
  const size_t n = loop.segments.size();
  bool any_fixed = false;
  for (size_t i = 0; i < n; ++i) {
    if (loop.segments[i].type != SegmentType::kClothoid) {
      any_fixed = true;
      continue;
    }
    const size_t prev = (i + n - 1) % n;
    if (n > 1 && loop.segments[prev].type == SegmentType::kClothoid) {
      y.Fail(fmt::format("segments[{}]", i),
             fmt::format("a clothoid must follow a straight or an arc, but segments[{}] is also "
                         "a clothoid (the loop wraps around from the last segment to the first)",
                         prev));
    }
  }
  if (!any_fixed) y.Fail("segments", "needs at least one straight or arc");
  for (size_t k = 0; k < loop.unknowns.size(); ++k) {
    if (!used[k]) {
      y.Fail("solve." + loop.unknowns[k].name, "declared but not used by any segment");
    }
  }
  return loop;
}

SegmentTrack LoadSegmentTrack(const std::filesystem::path& path) {
  return SolveSegmentLoop(ReadSegmentLoop(path));
}

}  // namespace hotlap::track
