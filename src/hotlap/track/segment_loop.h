#pragma once
/// @file
/// A track described as a loop of straights, circular arcs and clothoids, and the solve that makes
/// the loop close. segment_track_io.h reads this description from YAML (docs/tracks.md).
///
/// Geometry. A straight has zero curvature, an arc the constant curvature +-1/R (positive turning
/// left). A clothoid's curvature changes linearly with distance from the previous segment's
/// curvature to the next one's, and over the same distance its bank and widths blend from the
/// previous segment's values to the next one's along the smoothstep 3u^2 - 2u^3 (u the fraction
/// of the clothoid): continuous with zero slope at both ends, so bank and widths are C1 and
/// curvature C0 with a linear ramp. Straights and arcs hold their bank and widths constant.
///
/// Closure. The loop closes when its end meets its start in x, y and heading (plus whole turns).
/// Lengths, radii and arc angles may be unknowns: SolveSegmentLoop finds them by Newton's method so
/// that the loop closes and, if a target length is given, has that length. There must be as many
/// unknowns as equations (3, or 4 with a target length), or none, in which case the loop as given
/// must close to within 0.01 m and 1e-6 rad (and have the target length to within 0.01 m).

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "hotlap/track/track.h"

namespace hotlap::track {

enum class SegmentType { kStraight, kArc, kClothoid };

/// "straight", "arc" or "clothoid".
const char* SegmentTypeName(SegmentType type);

/// A length, radius or angle: a fixed number, or one of the loop's unknowns.
struct LoopValue {
  double value = 0.0;  ///< SI (m or rad); used when unknown < 0
  int unknown = -1;    ///< index into SegmentLoop::unknowns, or -1
};

/// One segment of the loop.
struct Segment {
  SegmentType type = SegmentType::kStraight;
  std::string field;  ///< where it was read, for messages, e.g. "segments[2]"
  LoopValue length;   ///< m; straight, clothoid, and arc unless given by angle
  LoopValue radius;   ///< m; arc
  LoopValue angle;    ///< rad, > 0; arc when arc_by_angle
  bool arc_by_angle = false;
  int turn_sign = 1;           ///< arc: +1 turning left, -1 turning right
  double bank_rad = 0.0;       ///< straight and arc; positive = left edge down
  double width_left_m = 0.0;   ///< straight and arc
  double width_right_m = 0.0;  ///< straight and arc
};

/// What an unknown is, which fixes its unit: a length or radius (m) or an arc angle (rad).
enum class UnknownKind { kLength, kAngle };

/// A number the loader solves for.
struct LoopUnknown {
  std::string name;  ///< as declared, with its unit suffix (`back_stretch_m`, `arc_deg`)
  UnknownKind kind = UnknownKind::kLength;
  double guess = 0.0;  ///< SI, > 0: where Newton starts
  double value = 0.0;  ///< SI, > 0: the solution (after SolveSegmentLoop)
};

/// A loop of segments, as read from a file.
struct SegmentLoop {
  std::string name;
  std::filesystem::path path;  ///< for messages
  std::vector<Segment> segments;
  std::vector<LoopUnknown> unknowns;
  std::optional<double> target_length_m;  ///< the lap length the solve must give
  double start_finish_fraction = 0.0;     ///< s = 0 at this fraction of the first segment, [0, 1)
};

/// Where a segment lies on the finished track.
struct SegmentSpan {
  int index = 0;  ///< position in SegmentLoop::segments
  SegmentType type = SegmentType::kStraight;
  double start_m = 0.0;   ///< track distance of its start, in [0, length)
  double length_m = 0.0;  ///< it ends at start_m + length_m (mod length)
  double curvature_start_per_m = 0.0;
  double curvature_end_per_m = 0.0;
  double bank_start_rad = 0.0;
  double bank_end_rad = 0.0;
};

/// A built segment track with its solved unknowns.
struct SegmentTrack {
  Track track;
  std::vector<SegmentSpan> spans;
  std::vector<LoopUnknown> unknowns;  ///< with `value` solved
  int newton_iterations = 0;
};

/// Solves the unknowns (if any) and builds the track: s = 0 at the start/finish point, which is
/// the world origin, heading along +x. Throws InputError naming the file and field when the loop
/// cannot close: wrong number of unknowns, unknowns that cannot move the end in every direction,
/// no convergence, a solved value out of range, or a fixed loop that does not close.
SegmentTrack SolveSegmentLoop(const SegmentLoop& loop);

}  // namespace hotlap::track
