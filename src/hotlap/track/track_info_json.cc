#include "hotlap/track/track_info_json.h"

#include <cmath>

#include "hotlap/common/json_output.h"
#include "hotlap/common/units.h"

namespace hotlap::track {

const char* TurnDirectionName(int direction) { return direction > 0 ? "left" : "right"; }

nlohmann::json TrackInfoJson(const TrackFile& file, const TrackSummary& s,
                             const SummaryOptions& options, const std::string& out) {
  const Track& t = file.track;
  nlohmann::json solved = nlohmann::json::object();
  for (const LoopUnknown& u : file.solved) {
    const bool angle = u.kind == UnknownKind::kAngle;
    solved[u.name] = RoundSignificant(angle ? RadToDeg(u.value) : u.value);
  }
  nlohmann::json segments = nlohmann::json::array();
  for (const SegmentSpan& g : file.segments) {
    nlohmann::json row = {{"index", g.index},
                          {"type", SegmentTypeName(g.type)},
                          {"start_m", RoundSignificant(g.start_m)},
                          {"length_m", RoundSignificant(g.length_m)},
                          {"curvature_start_per_m", RoundSignificant(g.curvature_start_per_m)},
                          {"curvature_end_per_m", RoundSignificant(g.curvature_end_per_m)},
                          {"bank_start_deg", RoundSignificant(RadToDeg(g.bank_start_rad))},
                          {"bank_end_deg", RoundSignificant(RadToDeg(g.bank_end_rad))}};
    if (g.type == SegmentType::kArc) {
      row["radius_m"] = RoundSignificant(1.0 / std::abs(g.curvature_start_per_m));
    }
    segments.push_back(row);
  }
  nlohmann::json turns = nlohmann::json::array();
  for (const TrackTurn& turn : s.turns) {
    turns.push_back({{"direction", TurnDirectionName(turn.direction)},
                     {"entry_m", RoundSignificant(turn.entry_m)},
                     {"apex_m", RoundSignificant(turn.apex_m)},
                     {"exit_m", RoundSignificant(turn.exit_m)},
                     {"min_radius_m", RoundSignificant(turn.min_radius_m)},
                     {"max_bank_deg", RoundSignificant(RadToDeg(turn.max_bank_rad))}});
  }
  nlohmann::json j = {
      {"command", "track info"},
      {"track", t.name()},
      {"file", file.path.string()},
      {"format", TrackFormatName(file.format)},
      {"length_m", RoundSignificant(s.length_m)},
      {"winding", s.winding},
      {"closure_error_m", RoundSignificant(s.closure.position_m())},
      {"closure_error_rad", RoundSignificant(s.closure.heading_rad)},
      {"min_radius_m", RoundSignificant(s.min_radius_m)},
      {"min_radius_at_m", RoundSignificant(s.min_radius_at_m)},
      {"bank_min_deg", RoundSignificant(RadToDeg(s.bank_min_rad))},
      {"bank_max_deg", RoundSignificant(RadToDeg(s.bank_max_rad))},
      {"width_min_m", RoundSignificant(s.width_min_m)},
      {"width_max_m", RoundSignificant(s.width_max_m)},
      {"turn_radius_m", options.turn_radius_m},
      {"turns", turns},
      {"segments", segments},
      {"solved", solved},
  };
  if (!out.empty()) j["out"] = out;
  return j;
}

}  // namespace hotlap::track
