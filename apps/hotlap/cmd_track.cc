// `hotlap track info`: what a track is (length, closure, tightest radius, banking, turns), and
// optionally its sampled ribbon as a CSV indexed by distance.

#include <cmath>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "commands.h"
#include "hotlap/common/json_output.h"
#include "hotlap/common/output_folder.h"
#include "hotlap/common/units.h"
#include "hotlap/track/ribbon_csv.h"
#include "hotlap/track/track_info_json.h"
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

  if (!file.solved.empty()) {
    fmt::print("  solved unknowns\n");
    for (const track::LoopUnknown& u : file.solved) {
      const bool angle = u.kind == track::UnknownKind::kAngle;
      const double shown = angle ? RadToDeg(u.value) : u.value;
      fmt::print("    {:<24} {:.6f} {}\n", u.name, shown, angle ? "deg" : "m");
    }
  }
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
    }
  }
  fmt::print("  turns (radius below {:g} m): {}\n", options.turn_radius_m, s.turns.size());
  if (!s.turns.empty()) {
    fmt::print("    {:>3} {:<5} {:>9} {:>9} {:>9} {:>12} {:>12}\n", "#", "dir", "entry_m", "apex_m",
               "exit_m", "min_radius_m", "max_bank_deg");
  }
  for (size_t i = 0; i < s.turns.size(); ++i) {
    const track::TrackTurn& turn = s.turns[i];
    fmt::print("    {:>3} {:<5} {:>9.1f} {:>9.1f} {:>9.1f} {:>12.2f} {:>12.2f}\n", i + 1,
               track::TurnDirectionName(turn.direction), turn.entry_m, turn.apex_m, turn.exit_m,
               turn.min_radius_m, RadToDeg(turn.max_bank_rad));
  }

  if (!a.out.empty()) {
    track::WriteRibbonCsv(a.out, file, a.step_m);
    fmt::print("wrote {}\n", a.out);
  }
  if (!a.json.empty()) WriteJsonFileAndSay(a.json, track::TrackInfoJson(file, s, options, a.out));
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
      ->check(kPositive);
  return [info, info_args] {
    if (info->parsed()) return RunTrackInfo(*info_args);
    return 1;
  };
}

}  // namespace hotlap::app
