// `hotlap track info`: what a track is (length, closure, tightest radius, banking, turns), and
// optionally its sampled ribbon as a CSV indexed by distance.

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.h"
#include "hotlap/common/csv.h"
#include "hotlap/common/json_output.h"
#include "hotlap/common/output_folder.h"
#include "hotlap/common/units.h"
#include "hotlap/track/track_io.h"
#include "hotlap/track/track_summary.h"

namespace hotlap::app {

namespace {

struct TrackInfoArgs {
  std::string track;
  std::string json;
  std::string out;
  double step_m = 1.0;
};

// The sampled ribbon, one row per step (last row at s = length), canonical units in the names.
void WriteRibbonCsv(const std::string& path, const track::TrackFile& file, double step_m) {
  const track::Track& t = file.track;
  // Steps of at most step_m (a length that is a whole number of steps gives exactly those).
  const int intervals = std::max(1, static_cast<int>(std::ceil(t.length_m() / step_m - 1e-9)));
  const std::vector<track::TrackPoint> points = t.Sample(intervals);
  const std::vector<std::string> columns = {"distance_m",
                                            "x_m",
                                            "y_m",
                                            "z_m",
                                            "heading_rad",
                                            "curvature_per_m",
                                            "curvature_rate_per_m2",
                                            "geodesic_curvature_per_m",
                                            "normal_curvature_per_m",
                                            "bank_deg",
                                            "grade_deg",
                                            "width_left_m",
                                            "width_right_m"};
  std::vector<std::vector<double>> values(columns.size());
  for (const track::TrackPoint& p : points) {
    const double row[] = {p.s_m,
                          p.x_m,
                          p.y_m,
                          p.z_m,
                          p.heading_rad,
                          p.curvature_per_m,
                          p.curvature_rate_per_m2,
                          track::GeodesicCurvature(p),
                          track::NormalCurvature(p),
                          RadToDeg(p.bank_rad),
                          RadToDeg(p.grade_rad),
                          p.width_left_m,
                          p.width_right_m};
    for (size_t c = 0; c < columns.size(); ++c) values[c].push_back(row[c]);
  }
  const std::vector<std::pair<std::string, std::string>> metadata = {
      {"track", t.name()},
      {"source", fmt::format("hotlap {} track info", HOTLAP_VERSION)},
      {"track_file", file.path.string()},
      {"format", track::TrackFormatName(file.format)},
      {"length_m", fmt::format("{:.9g}", t.length_m())},
  };
  WriteCsv(path, metadata, columns, values);
}

std::string Direction(int dir) { return dir > 0 ? "left" : "right"; }

int RunTrackInfo(const TrackInfoArgs& a) {
  if (!a.json.empty()) CheckOutputFolder(a.json, "--json");
  if (!a.out.empty()) CheckOutputFolder(a.out, "--out");
  const track::TrackFile file = track::LoadTrackByName(a.track);
  const track::Track& t = file.track;
  const track::SummaryOptions options;
  const track::TrackSummary s = track::Summarize(t, options);

  fmt::print("track '{}' ({}: {})\n", t.name(), track::TrackFormatName(file.format),
             file.path.string());
  fmt::print("  length          {:.3f} m, {} (winding {:+d}), {} polynomial pieces\n", s.length_m,
             s.winding > 0 ? "anticlockwise" : (s.winding < 0 ? "clockwise" : "figure of eight"),
             s.winding, t.knots_m().size() - 1);
  fmt::print("  closure error   {:.3g} m, {:.3g} rad (of the centre line before any correction)\n",
             s.closure.position_m(), s.closure.heading_rad);
  fmt::print("  minimum radius  {:.3f} m at {:.1f} m\n", s.min_radius_m, s.min_radius_at_m);
  if (s.bank_min_rad == 0.0 && s.bank_max_rad == 0.0) {
    fmt::print("  banking         none (flat)\n");
  } else {
    fmt::print(
        "  banking         {:.2f} deg (at {:.1f} m) to {:.2f} deg (at {:.1f} m), positive = "
        "left edge down\n",
        RadToDeg(s.bank_min_rad), s.bank_min_at_m, RadToDeg(s.bank_max_rad), s.bank_max_at_m);
  }
  fmt::print("  width           {:.2f} to {:.2f} m\n", s.width_min_m, s.width_max_m);

  nlohmann::json solved = nlohmann::json::object();
  if (!file.solved.empty()) {
    fmt::print("  solved unknowns\n");
    for (const track::LoopUnknown& u : file.solved) {
      const bool angle = u.kind == track::UnknownKind::kAngle;
      const double shown = angle ? RadToDeg(u.value) : u.value;
      fmt::print("    {:<24} {:.6f} {}\n", u.name, shown, angle ? "deg" : "m");
      solved[u.name] = RoundSignificant(shown);
    }
  }
  nlohmann::json segments = nlohmann::json::array();
  if (!file.segments.empty()) {
    fmt::print("  segments\n    {:>3} {:<9} {:>9} {:>9} {:>10} {:>10} {:>13}\n", "#", "type",
               "start_m", "end_m", "length_m", "radius_m", "bank_deg");
    for (const track::SegmentSpan& g : file.segments) {
      const double end = t.Wrap(g.start_m + g.length_m);
      const bool arc = g.type == track::SegmentType::kArc;
      const double radius = arc ? 1.0 / std::abs(g.curvature_start_per_m) : 0.0;
      fmt::print("    {:>3} {:<9} {:>9.3f} {:>9.3f} {:>10.3f} {:>10} {:>6.1f}{}\n", g.index,
                 track::SegmentTypeName(g.type), g.start_m, end, g.length_m,
                 arc ? fmt::format("{:.3f}", radius) : "-", RadToDeg(g.bank_start_rad),
                 g.bank_end_rad != g.bank_start_rad
                     ? fmt::format(" ->{:5.1f}", RadToDeg(g.bank_end_rad))
                     : "");
      nlohmann::json row = {{"index", g.index},
                            {"type", track::SegmentTypeName(g.type)},
                            {"start_m", RoundSignificant(g.start_m)},
                            {"length_m", RoundSignificant(g.length_m)},
                            {"curvature_start_per_m", RoundSignificant(g.curvature_start_per_m)},
                            {"curvature_end_per_m", RoundSignificant(g.curvature_end_per_m)},
                            {"bank_start_deg", RoundSignificant(RadToDeg(g.bank_start_rad))},
                            {"bank_end_deg", RoundSignificant(RadToDeg(g.bank_end_rad))}};
      if (arc) row["radius_m"] = RoundSignificant(radius);
      segments.push_back(row);
    }
  }
  nlohmann::json turns = nlohmann::json::array();
  fmt::print("  turns (radius below {:g} m): {}\n", options.turn_radius_m, s.turns.size());
  if (!s.turns.empty()) {
    fmt::print("    {:>3} {:<5} {:>9} {:>9} {:>9} {:>12} {:>12}\n", "#", "dir", "entry_m", "apex_m",
               "exit_m", "min_radius_m", "max_bank_deg");
  }
  for (size_t i = 0; i < s.turns.size(); ++i) {
    const track::TrackTurn& turn = s.turns[i];
    fmt::print("    {:>3} {:<5} {:>9.1f} {:>9.1f} {:>9.1f} {:>12.2f} {:>12.2f}\n", i + 1,
               Direction(turn.direction), turn.entry_m, turn.apex_m, turn.exit_m, turn.min_radius_m,
               RadToDeg(turn.max_bank_rad));
    turns.push_back({{"direction", Direction(turn.direction)},
                     {"entry_m", RoundSignificant(turn.entry_m)},
                     {"apex_m", RoundSignificant(turn.apex_m)},
                     {"exit_m", RoundSignificant(turn.exit_m)},
                     {"min_radius_m", RoundSignificant(turn.min_radius_m)},
                     {"max_bank_deg", RoundSignificant(RadToDeg(turn.max_bank_rad))}});
  }

  if (!a.out.empty()) {
    WriteRibbonCsv(a.out, file, a.step_m);
    fmt::print("wrote {}\n", a.out);
  }
  if (!a.json.empty()) {
    nlohmann::json j = {
        {"command", "track info"},
        {"track", t.name()},
        {"file", file.path.string()},
        {"format", track::TrackFormatName(file.format)},
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
    if (!a.out.empty()) j["out"] = a.out;
    WriteJsonFile(a.json, j);
    fmt::print("wrote {}\n", a.json);
  }
  return 0;
}

}  // namespace

CommandRunner RegisterTrackCommand(CLI::App& app) {
  auto info_args = std::make_shared<TrackInfoArgs>();
  CLI::App* track = app.add_subcommand("track", "Tracks: inspect and export the ribbon");
  track->require_subcommand(1);
  CLI::App* info = track->add_subcommand(
      "info", "Length, closure, tightest radius, banking and turns of a track");
  info->add_option("--track", info_args->track,
                   "Built-in track name (e.g. darlington) or a .yaml, .csv (TUM) or .xml "
                   "(fastest-lap) file")
      ->required();
  info->add_option("--json", info_args->json, "Write the summary as JSON (docs/tracks.md)");
  info->add_option("--out", info_args->out,
                   "Write the sampled ribbon as CSV indexed by distance_m (docs/tracks.md)");
  info->add_option("--step-m", info_args->step_m, "Sampling step of --out, m")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  return [info, info_args] {
    if (info->parsed()) return RunTrackInfo(*info_args);
    return 1;
  };
}

}  // namespace hotlap::app
