#include "hotlap/fe/mesh.h"

namespace hotlap::fe {

Mesh MakeBlockMesh(double lx, double ly, double lz, int nx, int ny, int nz) {
  Mesh m;
  const auto id = [&](int i, int j, int k) { return i + (nx + 1) * (j + (ny + 1) * k); };
  for (int k = 0; k <= nz; ++k) {
    for (int j = 0; j <= ny; ++j) {
      for (int i = 0; i <= nx; ++i) {
        m.nodes.emplace_back(lx * i / nx, ly * j / ny, lz * k / nz);
      }
    }
  }
  for (int k = 0; k < nz; ++k) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        m.elements.push_back({id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
                              id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1),
                              id(i, j + 1, k + 1)});
        m.element_material.push_back(0);
      }
    }
  }
  return m;
}

}  // namespace hotlap::fe
