#include "hotlap/ocp/mesh_resample.h"

#include <algorithm>
#include <cstddef>

#include <fmt/format.h>

#include "hotlap/common/error.h"

namespace hotlap::ocp {

namespace {

// Linear interpolation at `at` of values given at the increasing places `places`; held beyond
// the ends.
struct Interpolant {
  const std::vector<double>& places;
  // The interval of `places` holding `at` and the weight of its right end.
  std::pair<size_t, double> Locate(double at) const {
    if (places.size() < 2 || at <= places.front()) return {0, 0.0};
    if (at >= places.back()) return {places.size() - 2, 1.0};
    const size_t j = static_cast<size_t>(std::upper_bound(places.begin(), places.end(), at) -
                                         places.begin() - 1);
    return {j, (at - places[j]) / (places[j + 1] - places[j])};
  }
};

std::vector<double> Midpoints(const std::vector<double>& m) {
  std::vector<double> out;
  for (size_t k = 0; k + 1 < m.size(); ++k) out.push_back(0.5 * (m[k] + m[k + 1]));
  return out;
}

// Each node's share of the lap (the trapezoid's weight), m.
std::vector<double> NodeShares(const std::vector<double>& m) {
  std::vector<double> w(m.size(), 0.0);
  for (size_t k = 0; k + 1 < m.size(); ++k) {
    w[k] += 0.5 * (m[k + 1] - m[k]);
    w[k + 1] += 0.5 * (m[k + 1] - m[k]);
  }
  return w;
}

// Values at `from` places (stride `per`, `count` of them from `src_begin`) taken onto `to` places
// (into dst from `dst_begin`, the same stride), scaled at the source by `in_scale` and at the
// destination by `out_scale` (each by place; empty: 1).
void Resample(const std::vector<double>& src, size_t src_begin, const std::vector<double>& from,
              const std::vector<double>& in_scale, std::vector<double>& dst, size_t dst_begin,
              const std::vector<double>& to, const std::vector<double>& out_scale, size_t per) {
  const Interpolant at{from};
  for (size_t k = 0; k < to.size(); ++k) {
    const auto [j, w] = at.Locate(to[k]);
    const size_t j1 = std::min(j + 1, from.size() - 1);
    const double a = in_scale.empty() ? 1.0 : 1.0 / in_scale[j];
    const double b = in_scale.empty() ? 1.0 : 1.0 / in_scale[j1];
    const double c = out_scale.empty() ? 1.0 : out_scale[k];
    for (size_t i = 0; i < per; ++i) {
      dst[dst_begin + k * per + i] = c * ((1.0 - w) * a * src[src_begin + j * per + i] +
                                          w * b * src[src_begin + j1 * per + i]);
    }
  }
}

}  // namespace

std::vector<double> LayoutNodeDistances(const LapLayout& layout, double length_m) {
  if (!layout.mesh_m.empty()) return layout.mesh_m;
  std::vector<double> m(layout.nodes);
  const int intervals = layout.nodes - 1;
  for (int k = 0; k < layout.nodes; ++k) {
    m[k] = std::min(k * (length_m / intervals), length_m);
  }
  return m;
}

std::vector<double> ResampleLapPointOnMesh(const std::vector<double>& x,
                                           const std::vector<double>& from_m,
                                           const std::vector<double>& to_m) {
  if (from_m.size() < 2 || to_m.size() < 2 || x.empty() || x.size() % from_m.size() != 0) {
    throw InputError(
        fmt::format("optimal lap: {} values are not {} nodes of a lap", x.size(), from_m.size()));
  }
  const size_t per = x.size() / from_m.size();
  std::vector<double> out(per * to_m.size());
  Resample(x, 0, from_m, {}, out, 0, to_m, {}, per);
  return out;
}

LapMultipliers ResampleLapMultipliersOnMesh(const SolveResult& solve, const LapLayout& from,
                                            const std::vector<double>& from_m, const LapLayout& to,
                                            const std::vector<double>& to_m) {
  if (from.collocation != Collocation::kTrapezoid || to.collocation != Collocation::kTrapezoid ||
      static_cast<int>(from_m.size()) != from.nodes || static_cast<int>(to_m.size()) != to.nodes ||
      from.nodes < 2 || to.nodes < 2 ||
      solve.z_lower.size() != static_cast<size_t>(from.variables()) ||
      solve.z_upper.size() != solve.z_lower.size() ||
      solve.lambda.size() != static_cast<size_t>(from.rows())) {
    throw InputError(fmt::format(
        "optimal lap: multipliers of {} variables and {} rows are not the {}-node trapezoid's",
        solve.z_lower.size(), solve.lambda.size(), from.nodes));
  }
  const std::vector<double> from_w = NodeShares(from_m), to_w = NodeShares(to_m);
  const std::vector<double> from_mid = Midpoints(from_m), to_mid = Midpoints(to_m);
  LapMultipliers out;
  out.z_lower.assign(to.variables(), 0.0);
  out.z_upper.assign(to.variables(), 0.0);
  out.lambda.assign(to.rows(), 0.0);
  // Node quantities: densities per metre of their node's share, interpolated, times the new
  // share.
  Resample(solve.z_lower, 0, from_m, from_w, out.z_lower, 0, to_m, to_w, from.vars_per_node);
  Resample(solve.z_upper, 0, from_m, from_w, out.z_upper, 0, to_m, to_w, from.vars_per_node);
  Resample(solve.lambda, 0, from_m, from_w, out.lambda, 0, to_m, to_w, from.rows_per_node);
  size_t src = static_cast<size_t>(from.nodes) * from.rows_per_node;
  size_t dst = static_cast<size_t>(to.nodes) * to.rows_per_node;
  // The defects: costates, the same on any mesh, at the interval midpoints.
  Resample(solve.lambda, src, from_mid, {}, out.lambda, dst, to_mid, {}, from.defects_per_interval);
  src += static_cast<size_t>(from.intervals()) * from.defects_per_interval;
  dst += static_cast<size_t>(to.intervals()) * to.defects_per_interval;
  std::copy_n(solve.lambda.begin() + src, from.closure_rows, out.lambda.begin() + dst);
  src += from.closure_rows;
  dst += to.closure_rows;
  for (int b = 0; b < from.rate_blocks; ++b) {
    Resample(solve.lambda, src, from_mid, {}, out.lambda, dst, to_mid, {}, 2);
    src += 2 * static_cast<size_t>(from.intervals());
    dst += 2 * static_cast<size_t>(to.intervals());
  }
  return out;
}

void StartFromSolutionOnMesh(const SolveResult& solve, const LapLayout& from, double length_m,
                             const std::vector<double>& to_mesh_m, bool with_multipliers,
                             std::vector<double>& start_point, IpoptOptions& ipopt) {
  const std::vector<double> from_m = LayoutNodeDistances(from, length_m);
  start_point = ResampleLapPointOnMesh(solve.x, from_m, to_mesh_m);
  if (!with_multipliers || from.collocation != Collocation::kTrapezoid) return;
  LapLayout to = from.WithMesh(to_mesh_m);
  const LapMultipliers m = ResampleLapMultipliersOnMesh(solve, from, from_m, to, to_mesh_m);
  ipopt.warm_z_lower = m.z_lower;
  ipopt.warm_z_upper = m.z_upper;
  ipopt.warm_lambda = m.lambda;
}

}  // namespace hotlap::ocp
