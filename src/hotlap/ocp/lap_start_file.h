#pragma once
/// @file
/// A solved lap kept in a file for later solves to start from: its layout and its solve (point
/// and multipliers). Another solve of the same car and track, on the same or another mesh, with or
/// without the disc limit (the layout is the same), starts from it as coarse to fine starts from
/// the coarse solve: `hotlap optimise --save-solution FILE` writes one, `--warm-start FILE` reads
/// it (docs/optimal-control.md). The file is binary, this machine's byte order, not for archives.
/// A lap on a non-uniform mesh (an adaptive one's) keeps its nodes' distances as a second record,
/// and starts a solve through ResampleLapPointOnMesh and ResampleLapMultipliersOnMesh.

#include <filesystem>

#include "hotlap/ocp/optimal_lap.h"
#include "hotlap/track/track.h"

namespace hotlap::ocp {

/// What the file holds.
struct LapStart {
  double track_length_m = 0.0;  ///< of the track it was solved on
  LapLayout layout;
  SolveResult solve;
};

/// Writes `solution` (solved on a track of length `track_length_m`) to `path` atomically.
/// InputError if the solution has no point or the file cannot be written.
void WriteLapStart(const std::filesystem::path& path, const LapSolution& solution,
                   double track_length_m);

/// Reads a file WriteLapStart wrote. InputError naming the file if it cannot be read, is not
/// such a file, or its sizes do not agree with its layout.
LapStart ReadLapStart(const std::filesystem::path& path);

/// Makes `options` start from `start`: the point (ResampleLapPoint) and the multipliers
/// (ResampleLapMultipliers, a warm start) on the mesh of options.step_m on `track`; the coarse
/// solve is then skipped. InputError if the start was solved on a track of another length; the
/// solve itself refuses a point of another node size (InputError), and multipliers of another row
/// layout (e.g. a periodic thermal start against a fixed one) are left unused.
void UseLapStart(const LapStart& start, const track::Track& track, OptimalLapOptions& options);

}  // namespace hotlap::ocp
