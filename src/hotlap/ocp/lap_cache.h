#pragma once
/// @file
/// A folder of solved laps that later solves start from (`hotlap optimise --lap-cache DIR`, the
/// sweeps' OUT/laps; docs/sweeps.md, "Warm starts and the lap cache"). Each lap is `<hash>.lap`
/// (lap_start_file.h) beside `<hash>.json`, its index entry: the name it was solved for, its
/// family (the text that must be equal for one lap to start another: the build, the car's files,
/// the track, the programme) and its coordinates (the values that may differ between neighbours:
/// overrides, a disc limit, temperatures), with its lap time and iterations. The hash is the
/// family's and the coordinates', so the same inputs find their own lap at distance 0.

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace hotlap::ocp {

/// What a lap is cached under.
struct CachedLapKey {
  std::string family;
  std::map<std::string, double> coordinates;
};

/// A lap of the cache, as NearestCachedLaps finds it.
struct CachedLap {
  std::string name;
  std::filesystem::path lap;  ///< the .lap file
  double distance = 0.0;
};

/// The file name stem of `key`'s lap: 16 hexadecimal digits.
std::string CachedLapHash(const CachedLapKey& key);

/// The scaled distance between two coordinate sets of the same keys:
/// sqrt(sum ((a - b) / scale)^2), each key's scale from `scales`, else max(|a|, 1).
double CoordinateDistance(const std::map<std::string, double>& a,
                          const std::map<std::string, double>& b,
                          const std::map<std::string, double>& scales);

/// The `count` laps in `dir` nearest `key` among those of its family with the same coordinate
/// keys, nearest first (ties by name); entries that cannot be read, or whose lap file is gone,
/// are left out. None for a folder that is not there.
std::vector<CachedLap> NearestCachedLaps(const std::filesystem::path& dir, const CachedLapKey& key,
                                         const std::map<std::string, double>& scales, int count);

/// Moves `saved` (a lap WriteLapStart wrote, on the same filesystem) into `dir` as `key`'s lap and
/// writes its index entry after it, atomically, so an entry always names a whole lap. InputError
/// naming the folder if it cannot be written.
void KeepCachedLap(const std::filesystem::path& dir, const CachedLapKey& key,
                   const std::string& name, const std::filesystem::path& saved, double lap_time_s,
                   int iterations);

}  // namespace hotlap::ocp
