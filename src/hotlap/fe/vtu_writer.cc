#include "hotlap/fe/vtu_writer.h"

#include <cmath>
#include <ostream>

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "hotlap/common/atomic_file.h"

namespace hotlap::fe {

void WriteVtu(const std::filesystem::path& path, const ExplicitSolver& solver) {
  const Mesh& mesh = solver.mesh();
  const auto& x = solver.positions();
  const auto& v = solver.velocities();
  WriteFileAtomically(path, [&](std::ostream& out) {
    const size_t nn = x.size(), ne = mesh.elements.size();
    fmt::print(out,
               "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\">\n"
               "<UnstructuredGrid>\n<Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n",
               nn, ne);
    out << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (const auto& p : x) fmt::print(out, "{:.9g} {:.9g} {:.9g}\n", p.x(), p.y(), p.z());
    out << "</DataArray>\n</Points>\n<Cells>\n"
           "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    for (const auto& e : mesh.elements) {
      fmt::print(out, "{} {} {} {} {} {} {} {}\n", e[0], e[1], e[2], e[3], e[4], e[5], e[6], e[7]);
    }
    out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    for (size_t e = 0; e < ne; ++e) fmt::print(out, "{}\n", 8 * (e + 1));
    out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
    for (size_t e = 0; e < ne; ++e) out << "12\n";  // VTK_HEXAHEDRON
    out << "</DataArray>\n</Cells>\n<PointData Vectors=\"displacement_m\">\n"
           "<DataArray type=\"Float64\" Name=\"displacement_m\" NumberOfComponents=\"3\" "
           "format=\"ascii\">\n";
    for (size_t a = 0; a < nn; ++a) {
      const Eigen::Vector3d u = x[a] - mesh.nodes[a];
      fmt::print(out, "{:.6g} {:.6g} {:.6g}\n", u.x(), u.y(), u.z());
    }
    out << "</DataArray>\n<DataArray type=\"Float64\" Name=\"velocity_mps\" "
           "NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (const auto& p : v) fmt::print(out, "{:.6g} {:.6g} {:.6g}\n", p.x(), p.y(), p.z());
    out << "</DataArray>\n</PointData>\n<CellData>\n"
           "<DataArray type=\"Int32\" Name=\"region\" format=\"ascii\">\n";
    for (int m : mesh.element_material) fmt::print(out, "{}\n", m);
    out << "</DataArray>\n<DataArray type=\"Float64\" Name=\"pressure_Pa\" format=\"ascii\">\n";
    std::vector<double> mises(ne);
    for (size_t e = 0; e < ne; ++e) {
      const Eigen::Matrix3d s = solver.ElementStress(static_cast<int>(e));
      const double p = -s.trace() / 3.0;
      const Eigen::Matrix3d dev = s + p * Eigen::Matrix3d::Identity();
      mises[e] = std::sqrt(1.5 * dev.squaredNorm());
      fmt::print(out, "{:.6g}\n", p);
    }
    out << "</DataArray>\n<DataArray type=\"Float64\" Name=\"von_mises_Pa\" format=\"ascii\">\n";
    for (double m : mises) fmt::print(out, "{:.6g}\n", m);
    out << "</DataArray>\n</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  });
}

}  // namespace hotlap::fe
