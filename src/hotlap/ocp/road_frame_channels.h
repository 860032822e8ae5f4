#pragma once
/// @file
/// What every lap solution of the project (the stock car's lap problem, the F1 peer's) reports
/// along its mesh in the road frame, and its extraction from a solved programme's point.

#include <cstddef>
#include <vector>

namespace hotlap::ocp {

/// A lap solution's road-frame channels at its mesh nodes.
struct RoadFrameChannels {
  std::vector<double> distance;  ///< m along the centre line
  std::vector<double> time;      ///< s, dt/ds integrated from the first node as the defects do
  std::vector<double> u, v;      ///< body-axis speeds, m/s
  std::vector<double> r;         ///< yaw rate, rad/s
  std::vector<double> n;         ///< lateral offset from the centre line, m (left +)
};

/// Appends the channels of `nodes` (each with the variable indices u, v, r, n and w = dt/ds, on a
/// uniform mesh of spacing `ds` from distance 0) read from the point `x`. The time is the
/// trapezoid of w, or with `hermite_simpson` (an odd number of nodes, every second one an
/// interval's midpoint) Simpson's rule to an interval's end and Hermite's interpolation to its
/// midpoint. Returns the time at the last node.
template <class Node>
double AppendRoadFrameChannels(const std::vector<Node>& nodes, const std::vector<double>& x,
                               double ds, RoadFrameChannels& out, bool hermite_simpson = false) {
  double time = 0.0;
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    const Node& nd = nodes[k];
    if (hermite_simpson && k % 2 == 1 && k + 1 < nodes.size()) {
      // The midpoint of the interval from node k - 1 to k + 1 (h = 2 ds); `time` becomes the
      // interval's end's.
      const double wa = x[nodes[k - 1].w], wm = x[nd.w], wb = x[nodes[k + 1].w];
      const double tb = time + ds / 3.0 * (wa + 4.0 * wm + wb);
      out.time.push_back(0.5 * (time + tb) + ds / 4.0 * (wa - wb));
      time = tb;
    } else {
      if (k > 0 && !hermite_simpson) time += 0.5 * ds * (x[nodes[k - 1].w] + x[nd.w]);
      out.time.push_back(time);
    }
    out.distance.push_back(static_cast<double>(k) * ds);
    out.u.push_back(x[nd.u]);
    out.v.push_back(x[nd.v]);
    out.r.push_back(x[nd.r]);
    out.n.push_back(x[nd.n]);
  }
  return time;
}

/// As AppendRoadFrameChannels, on a mesh with the nodes at the distances `node_m` (one a node, in
/// m): the trapezoid of w interval by interval.
template <class Node>
double AppendRoadFrameChannelsOnMesh(const std::vector<Node>& nodes, const std::vector<double>& x,
                                     const std::vector<double>& node_m, RoadFrameChannels& out) {
  double time = 0.0;
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    const Node& nd = nodes[k];
    if (k > 0) time += 0.5 * (node_m[k] - node_m[k - 1]) * (x[nodes[k - 1].w] + x[nd.w]);
    out.time.push_back(time);
    out.distance.push_back(node_m[k]);
    out.u.push_back(x[nd.u]);
    out.v.push_back(x[nd.v]);
    out.r.push_back(x[nd.r]);
    out.n.push_back(x[nd.n]);
  }
  return time;
}

}  // namespace hotlap::ocp
