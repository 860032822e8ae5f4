#pragma once
/// @file
/// What every lap solution of the project (the stock car's lap problem, the F1 peer's) reports
/// along its mesh in the road frame, and its extraction from a solved programme's point.

#include <vector>

namespace hotlap::ocp {

/// A lap solution's road-frame channels at its mesh nodes.
struct RoadFrameChannels {
  std::vector<double> distance;  ///< m along the centre line
  std::vector<double> time;      ///< s, the trapezoid of dt/ds from the first node
  std::vector<double> u, v;      ///< body-axis speeds, m/s
  std::vector<double> r;         ///< yaw rate, rad/s
  std::vector<double> n;         ///< lateral offset from the centre line, m (left +)
};

/// Appends the channels of `nodes` (each with the variable indices u, v, r, n and w = dt/ds, on a
/// uniform mesh of spacing `ds` from distance 0) read from the point `x`. Returns the time at
/// the last node.
template <class Node>
double AppendRoadFrameChannels(const std::vector<Node>& nodes, const std::vector<double>& x,
                               double ds, RoadFrameChannels& out) {
  double time = 0.0;
  for (size_t k = 0; k < nodes.size(); ++k) {
    const Node& nd = nodes[k];
    if (k > 0) time += 0.5 * ds * (x[nodes[k - 1].w] + x[nd.w]);
    out.distance.push_back(static_cast<double>(k) * ds);
    out.time.push_back(time);
    out.u.push_back(x[nd.u]);
    out.v.push_back(x[nd.v]);
    out.r.push_back(x[nd.r]);
    out.n.push_back(x[nd.n]);
  }
  return time;
}

}  // namespace hotlap::ocp
