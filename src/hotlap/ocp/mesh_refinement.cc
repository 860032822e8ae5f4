#include "hotlap/ocp/mesh_refinement.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "hotlap/common/error.h"

namespace hotlap::ocp {

MeshRefinement RefineMesh(const std::vector<double>& mesh_m,
                          const std::vector<double>& interval_error_s,
                          const MeshRefinementOptions& options) {
  if (mesh_m.size() < 2 || interval_error_s.size() + 1 != mesh_m.size() ||
      !(options.tolerance_s > 0.0)) {
    throw InputError(
        fmt::format("mesh refinement: {} nodes, {} interval errors and a tolerance of {:g} s",
                    mesh_m.size(), interval_error_s.size(), options.tolerance_s));
  }
  const double length = mesh_m.back() - mesh_m.front();
  const size_t intervals = interval_error_s.size();
  const auto share = [&](double h) { return options.tolerance_s * h / length; };
  // How many parts each interval becomes (1: kept).
  std::vector<int> parts(intervals, 1);
  MeshRefinement out;
  for (size_t k = 0; k < intervals; ++k) {
    const double h = mesh_m[k + 1] - mesh_m[k];
    const double over = std::abs(interval_error_s[k]) / share(h);
    if (over <= 1.0) continue;
    const int most = std::min(options.max_split, static_cast<int>(h / options.min_step_m));
    parts[k] = std::clamp(static_cast<int>(std::ceil(std::sqrt(over))), 2, std::max(2, most));
    if (most < 2) {
      parts[k] = 1;
      ++out.over_at_min_step;
      continue;
    }
    ++out.split;
  }
  // Grading: no new interval more than `max_ratio` times its neighbour's (the lap closes, so the
  // last interval's neighbour is the first's).
  const auto piece = [&](size_t k) { return (mesh_m[k + 1] - mesh_m[k]) / parts[k]; };
  const std::vector<int> wanted = parts;
  for (bool changed = options.max_ratio > 1.0; changed;) {
    changed = false;
    for (size_t k = 0; k < intervals; ++k) {
      for (const size_t n : {(k + intervals - 1) % intervals, (k + 1) % intervals}) {
        if (piece(k) > options.max_ratio * piece(n) * (1.0 + 1e-12)) {
          const double h = mesh_m[k + 1] - mesh_m[k];
          parts[k] = static_cast<int>(std::ceil(h / (options.max_ratio * piece(n)) - 1e-9));
          changed = true;
        }
      }
    }
  }
  for (size_t k = 0; k < intervals; ++k) out.graded += parts[k] > wanted[k] ? 1 : 0;
  out.mesh_m.push_back(mesh_m.front());
  for (size_t k = 0; k < intervals; ++k) {
    const double a = mesh_m[k], h = mesh_m[k + 1] - a;
    const size_t before = (k + intervals - 1) % intervals, after2 = (k + 2) % intervals;
    if (parts[k] == 1 && k + 1 < intervals && parts[k + 1] == 1 &&
        (options.max_ratio <= 1.0 ||
         (h + mesh_m[k + 2] - mesh_m[k + 1] <= options.max_ratio * piece(before) &&
          h + mesh_m[k + 2] - mesh_m[k + 1] <= options.max_ratio * piece(after2)))) {
      // Merge with the next one where the union is far within its share.
      const double hb = mesh_m[k + 2] - mesh_m[k + 1], u = h + hb;
      const double density = 0.5 * (std::abs(interval_error_s[k]) / (h * h * h) +
                                    std::abs(interval_error_s[k + 1]) / (hb * hb * hb));
      if (u <= options.max_step_m && density * u * u * u < options.merge_fraction * share(u)) {
        out.mesh_m.push_back(mesh_m[k + 2]);
        ++out.merged;
        ++k;
        continue;
      }
    }
    for (int i = 1; i <= parts[k]; ++i) {
      out.mesh_m.push_back(i == parts[k] ? mesh_m[k + 1] : a + h * i / parts[k]);
    }
  }
  return out;
}

}  // namespace hotlap::ocp
