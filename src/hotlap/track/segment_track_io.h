#pragma once
/// @file
/// Reading segment track files (YAML, `model: segments`; format in docs/tracks.md, example
/// data/tracks/darlington.yaml). Strict like every parameter file: an unknown or missing key, a
/// value out of range, a key with the wrong unit, or a loop that cannot close is an InputError
/// naming the file, the field, the value and what is allowed.

#include <filesystem>

#include "hotlap/track/segment_loop.h"

namespace hotlap::track {

/// Reads and validates the loop description without solving it.
SegmentLoop ReadSegmentLoop(const std::filesystem::path& path);

/// ReadSegmentLoop, then SolveSegmentLoop: the finished track with its solved unknowns.
SegmentTrack LoadSegmentTrack(const std::filesystem::path& path);

}  // namespace hotlap::track
