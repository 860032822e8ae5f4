#pragma once
/// @file
/// Importing a fastest-lap discrete circuit (XML; fastest-lap, MIT licence,
/// data/tracks/LICENSE-fastest-lap.txt), such as data/tracks/catalunya-fl.xml.
///
/// The file holds, at N points equally spaced in arc length: the centre line (x, y), the heading
/// `yaw` and the curvature `yaw_dot` (per metre), and the distances `nl`, `nr` from the centre line
/// to the left and right edges. hotlap builds the track from the curvature (a periodic C2 spline
/// through `yaw_dot`), starting at the first centre-line point with the first `yaw`, and closes it
/// as sampled_track.h describes; the length is the header's `track_length`.
///
/// Axes: fastest-lap writes its circuits in a frame whose y axis points to the right of x (its
/// left edge lies at (x, y) + nl (sin yaw, -cos yaw)), while hotlap uses ISO 8855 (y left). The
/// import mirrors y: y -> -y, yaw -> -yaw, yaw_dot -> -yaw_dot, which keeps `nl` on the left and
/// makes Catalunya clockwise, as the circuit is run (and as TUM's centre line of it is).

#include <filesystem>

#include "hotlap/track/track.h"

namespace hotlap::track {

/// Reads the circuit. The track is named after the file's stem. Throws InputError naming the
/// file, line and element for a missing element, a count that differs from `number_of_points`, a
/// value that is not a number, arc lengths that do not start at 0 and increase to below
/// `track_length`, or a non-positive width; and, naming the file, for curvature from which no
/// closed track can be built (TrackFromCurvature's NumericalError, e.g. a fraction of a turn).
Track LoadFastestLapCircuit(const std::filesystem::path& path);

}  // namespace hotlap::track
