#include "hotlap/ocp/lap_start_file.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "hotlap/common/atomic_file.h"
#include "hotlap/common/error.h"
#include "hotlap/common/read_file.h"
#include "hotlap/ocp/mesh_resample.h"
#include "hotlap/ocp/solve_result_bytes.h"

namespace hotlap::ocp {

namespace {

// L1: six layout numbers (trapezoid laps, until 2026-11-27); L2: seven, the last the collocation
// (0 trapezoid, 1 Hermite-Simpson).
constexpr char kMagic1[8] = {'h', 'o', 't', 'l', 'a', 'p', 'L', '1'};
constexpr char kMagic[8] = {'h', 'o', 't', 'l', 'a', 'p', 'L', '2'};
constexpr size_t kHeader1 = sizeof(kMagic) + sizeof(double) + 6 * sizeof(int32_t);
constexpr size_t kHeader = sizeof(kMagic) + sizeof(double) + 7 * sizeof(int32_t);

std::vector<int32_t> LayoutNumbers(const LapLayout& l) {
  return {l.nodes,
          l.vars_per_node,
          l.rows_per_node,
          l.defects_per_interval,
          l.closure_rows,
          l.rate_blocks,
          l.collocation == Collocation::kHermiteSimpson};
}

}  // namespace

void WriteLapStart(const std::filesystem::path& path, const LapSolution& solution,
                   double track_length_m) {
  const SolveResult& s = solution.solve;
  if (s.x.empty() || static_cast<int>(s.x.size()) != solution.layout.variables()) {
    throw InputError(fmt::format("'{}': the lap has no solution to save", path.string()));
  }
  std::string bytes(kMagic, sizeof(kMagic));
  bytes.append(reinterpret_cast<const char*>(&track_length_m), sizeof(double));
  for (const int32_t v : LayoutNumbers(solution.layout)) {
    bytes.append(reinterpret_cast<const char*>(&v), sizeof(v));
  }
  // A non-uniform mesh's nodes as a second record (its x).
  std::vector<SolveResult> records{s};
  if (!solution.layout.mesh_m.empty()) {
    records.emplace_back();
    records.back().x = solution.layout.mesh_m;
  }
  bytes += EncodeSolveResults(records);
  WriteFileAtomically(path, [&](std::ostream& out) { out.write(bytes.data(), bytes.size()); });
}

LapStart ReadLapStart(const std::filesystem::path& path) {
  const std::string bytes = ReadWholeFile(path);
  const auto fail = [&](const std::string& why) {
    return InputError(
        fmt::format("'{}' is not a saved lap (--save-solution): {}", path.string(), why));
  };
  const bool version1 =
      bytes.size() >= kHeader1 && std::memcmp(bytes.data(), kMagic1, sizeof(kMagic1)) == 0;
  if (!version1 &&
      (bytes.size() < kHeader || std::memcmp(bytes.data(), kMagic, sizeof(kMagic)) != 0)) {
    throw fail("it does not start as one");
  }
  LapStart s;
  size_t at = sizeof(kMagic);
  std::memcpy(&s.track_length_m, bytes.data() + at, sizeof(double));
  at += sizeof(double);
  int32_t v[7] = {0, 0, 0, 0, 0, 0, 0};
  const size_t numbers = (version1 ? 6 : 7) * sizeof(int32_t);
  std::memcpy(v, bytes.data() + at, numbers);
  at += numbers;
  if (v[6] != 0 && v[6] != 1) throw fail("its collocation is neither of the two");
  s.layout = {v[0],
              v[1],
              v[2],
              v[3],
              v[4],
              v[5],
              v[6] == 1 ? Collocation::kHermiteSimpson : Collocation::kTrapezoid,
              {}};
  std::vector<SolveResult> solves;
  try {
    solves = DecodeSolveResults(bytes.substr(at));
  } catch (const InputError& e) {
    throw fail(e.what());
  }
  if (solves.size() != 1 && solves.size() != 2) throw fail("it holds no solve");
  s.solve = std::move(solves[0]);
  if (solves.size() == 2) {
    s.layout.mesh_m = std::move(solves[1].x);
    if (static_cast<int>(s.layout.mesh_m.size()) != s.layout.nodes ||
        s.layout.collocation != Collocation::kTrapezoid) {
      throw fail("its mesh does not agree with its layout");
    }
  }
  const LapLayout& l = s.layout;
  const bool sizes = l.nodes >= 2 && l.vars_per_node > 0 && l.rows_per_node >= 0 &&
                     l.defects_per_interval >= 0 && l.closure_rows >= 0 && l.rate_blocks >= 0 &&
                     (l.collocation == Collocation::kTrapezoid || l.nodes % 2 == 1) &&
                     std::isfinite(s.track_length_m) && s.track_length_m > 0.0 &&
                     s.solve.x.size() == static_cast<size_t>(l.variables()) &&
                     s.solve.z_lower.size() == s.solve.x.size() &&
                     s.solve.z_upper.size() == s.solve.x.size() &&
                     s.solve.lambda.size() == static_cast<size_t>(l.rows());
  if (!sizes) throw fail("its sizes do not agree with its layout");
  return s;
}

void UseLapStart(const LapStart& start, const track::Track& track, OptimalLapOptions& options) {
  if (std::abs(start.track_length_m - track.length_m()) > 1.0) {
    throw InputError(fmt::format("the saved lap is of a {:.1f} m track, this one is {:.1f} m",
                                 start.track_length_m, track.length_m()));
  }
  // This problem's layout on the target mesh, as far as the file can tell: the same node.
  const int nodes = LapNodeCount(track, options.step_m, options.collocation);
  if (start.layout.mesh_m.empty()) {
    StartFromSolution(start.solve, start.layout, nodes, options.collocation, true,
                      options.start_point, options.ipopt);
    return;
  }
  // From a non-uniform mesh (an adaptive one's) onto the uniform step_m mesh.
  const std::vector<double> to =
      LayoutNodeDistances(start.layout.WithNodes(nodes), track.length_m());
  if (options.collocation == Collocation::kTrapezoid) {
    StartFromSolutionOnMesh(start.solve, start.layout, track.length_m(), to, true,
                            options.start_point, options.ipopt);
  } else {
    options.start_point = ResampleLapPointOnMesh(start.solve.x, start.layout.mesh_m, to);
  }
}

}  // namespace hotlap::ocp
