#pragma once
/// @file
/// A hexahedral mesh with what the explicit solver needs to know about it: materials per element,
/// cord layers, pressure faces, the nodes tied to the rigid rim and the nodes that may touch the
/// road. Positions in metres.

#include <array>
#include <vector>

#include <Eigen/Core>

#include "hotlap/fe/rebar.h"

namespace hotlap::fe {

/// The mesh. Elements use the node order of hex8.h.
struct Mesh {
  std::vector<Eigen::Vector3d> nodes;        ///< reference positions, m
  std::vector<std::array<int, 8>> elements;  ///< node indices
  std::vector<int> element_material;         ///< index into the rubber materials, per element
  std::vector<FibreLayer> fibres;            ///< cord layers (any order)
  /// Faces loaded by the inflation pressure; node order such that the right-hand normal
  /// (x2 - x0) x (x3 - x1) points out of the solid, into the pressurised cavity.
  std::vector<std::array<int, 4>> pressure_faces;
  std::vector<int> rim_nodes;      ///< nodes tied to the rigid rim
  std::vector<int> contact_nodes;  ///< nodes checked against the road (empty: none)
};

/// A structured block [0, lx] x [0, ly] x [0, lz] of nx * ny * nz elements of material 0, for
/// tests and examples. Node (i, j, k) has index i + (nx + 1) (j + (ny + 1) k).
Mesh MakeBlockMesh(double lx, double ly, double lz, int nx, int ny, int nz);

}  // namespace hotlap::fe
