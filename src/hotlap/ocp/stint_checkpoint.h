#pragma once
/// @file
/// A stint's checkpoints (StintOptions::checkpoint_dir; docs/reliability.md): each greedy lap's
/// solves as it ends (`greedy_lap_N.bin`) and the stint's own Ipopt iterate every few iterations
/// (`stint_iterate.bin`), each written atomically and stamped with the stint's fingerprint, so a
/// run killed part way resumes where the last file left it, and a file of another stint is never
/// taken for this one's. Binary, this machine's byte order, not for archives.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "hotlap/ocp/optimal_lap.h"

namespace hotlap::ocp {

struct StintOptions;

class StintCheckpoints {
 public:
  /// Creates `dir` if needed (InputError naming it if it cannot be, or is not a folder).
  /// `fingerprint` tells this stint from any other (StintFingerprint).
  StintCheckpoints(std::filesystem::path dir, std::uint64_t fingerprint);

  /// Greedy lap `lap` (1-based) as saved by this stint, or nothing (no file, another stint's,
  /// or a file that does not read: a torn or foreign file is not an error, it is not used).
  std::optional<PresolvedLap> ReadGreedyLap(int lap) const;
  void WriteGreedyLap(int lap, const PresolvedLap& solves) const;

  /// The stint solve's last saved iterate (SolveResult with x, multipliers, barrier_mu and the
  /// iteration it was taken at), or nothing.
  std::optional<SolveResult> ReadStintIterate() const;
  void WriteStintIterate(const SolveResult& iterate) const;

  const std::filesystem::path& dir() const { return dir_; }
  /// Files here that were not this stint's (another fingerprint), seen by the reads so far.
  int foreign_files() const { return foreign_; }

 private:
  std::optional<std::string> ReadPayload(const std::filesystem::path& path) const;
  void WritePayload(const std::filesystem::path& path, const std::string& payload) const;

  std::filesystem::path dir_;
  std::uint64_t fingerprint_;
  mutable int foreign_ = 0;
};

/// What makes two stints the same problem: the stint's options (laps, wear scale, fuel, the
/// lap's mesh, limit, temperatures, smoothing), `key` (the command line adds its input files'
/// bytes), the track's length and the warm-up, whose thermal start and QSS lap depend on every
/// parameter of the car.
std::uint64_t StintFingerprint(const StintOptions& options, const track::Track& track,
                               const LapWarmUp& warm_up);

}  // namespace hotlap::ocp
