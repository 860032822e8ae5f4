#pragma once
// Test-only bridge to CalculiX (`ccx`, Debian's calculix-ccx), the independent implicit check of
// the explicit solver: writes an input deck for a hotlap Mesh of one Yeoh rubber (a static,
// geometrically nonlinear step with fixed increments), runs ccx in a folder and reads the node
// tables of its .dat file. Units are the caller's (SI here: m, N, Pa).
//
// Pitfalls this file handles:
// - ccx's *HYPERELASTIC, YEOH card is C10, C20, C30, D1, D2, D3 with
//   W = sum Ci0 (I1b - 3)^i + sum (J - 1)^(2i) / Di (rubber.f), and ccx replaces every D below
//   1e-10 by (0.1 / mu0)^i (hyperelastics.f): D2 = D3 = 0 silently adds a stiff (J - 1)^4 term and
//   makes the rubber almost incompressible whatever D1 is (a one-element tension test showed J =
//   1.0005 against the 1.018 of K = 2 / D1). The deck therefore writes D2 = D3 = 1e30, which makes
//   those terms vanish; hotlap's W is C10..C30 plus (K / 2)(J - 1)^2, i.e. D1 = 2 / K.
// - ccx exits with 0 even when it gives up ("*ERROR: too many cutbacks"): RunCalculix reads the
//   log, and callers check that the last increment reached the step's end.

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "hotlap/fe/mesh.h"
#include "hotlap/fe/yeoh.h"

namespace hotlap::fe::testing {

/// A node set of the deck: hotlap node indices (0-based; the deck numbers nodes from 1).
struct CalculixNodeSet {
  std::string name;
  std::vector<int> nodes;
};

/// Displacement of dofs first_dof..last_dof (1 x, 2 y, 3 z) of a node set, in length units.
struct CalculixBoundary {
  std::string node_set;
  int first_dof = 1;
  int last_dof = 3;
  double value = 0.0;
};

/// A linear spring from a node to the ground along one dof (CalculiX SPRING1), N per length unit.
struct CalculixGroundSpring {
  int node = 0;  ///< hotlap node index (0-based)
  int dof = 3;   ///< 1 x, 2 y, 3 z
  double stiffness = 0.0;
};

/// What to write besides the mesh and the material.
struct CalculixDeck {
  /// C3D8 (full 2x2x2), C3D8R (one point, hourglass control) or C3D8I (incompatible modes).
  std::string element_type = "C3D8I";
  YeohMaterial material;
  std::vector<CalculixNodeSet> node_sets;
  std::vector<CalculixGroundSpring> springs;    ///< e.g. a penalty contact that never opens
  std::vector<CalculixBoundary> fixed;          ///< held from the start (model data)
  std::vector<CalculixBoundary> step_boundary;  ///< ramped linearly over the step
  int increments = 10;                          ///< equal fixed increments (*STATIC, DIRECT)
  std::vector<std::string> force_sets;          ///< sets whose total reaction force is printed
  std::vector<std::string> displacement_sets;   ///< sets whose nodal displacements are printed
};

/// The node tables of one increment of the .dat file.
struct CalculixIncrement {
  double time = 0.0;  ///< step fraction, 1 at the end of the step
  std::map<std::string, Eigen::Vector3d> total_force;
  /// Per set: hotlap node index (0-based) -> displacement.
  std::map<std::string, std::map<int, Eigen::Vector3d>> displacement;
};

inline std::string CalculixNumber(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.12g", v);
  return buf;
}

/// The input deck text for `mesh` (every element of material 0 with deck.material).
inline std::string WriteCalculixDeck(const Mesh& mesh, const CalculixDeck& deck) {
  std::ostringstream s;
  s << "*HEADING\nhotlap FE block, written by tests/fe/calculix_deck.h\n*NODE\n";
  for (size_t a = 0; a < mesh.nodes.size(); ++a) {
    const Eigen::Vector3d& x = mesh.nodes[a];
    s << a + 1 << ", " << CalculixNumber(x.x()) << ", " << CalculixNumber(x.y()) << ", "
      << CalculixNumber(x.z()) << "\n";
  }
  // hex8.h's node order (bottom face counter-clockwise seen from +zeta, then the top face) is
  // CalculiX's C3D8 order.
  s << "*ELEMENT, TYPE=" << deck.element_type << ", ELSET=EALL\n";
  for (size_t e = 0; e < mesh.elements.size(); ++e) {
    s << e + 1;
    for (int a : mesh.elements[e]) s << ", " << a + 1;
    s << "\n";
  }
  // Springs: one element set and *SPRING card per distinct (dof, stiffness to 13 digits); every
  // *SPRING card counts as a material in ccx, so a uniform mesh's few distinct nodal stiffnesses
  // are cheap. The stiffness must contain a decimal point (ccx's springs.f reads a first field
  // without one as a dof line), which %e guarantees.
  std::map<std::pair<int, std::string>, std::vector<int>> spring_groups;
  for (const CalculixGroundSpring& sp : deck.springs) {
    char k[40];
    std::snprintf(k, sizeof k, "%.12e", sp.stiffness);
    spring_groups[{sp.dof, k}].push_back(sp.node);
  }
  size_t next_element = mesh.elements.size() + 1;
  int group = 0;
  for (const auto& [key, nodes] : spring_groups) {
    s << "*ELEMENT, TYPE=SPRING1, ELSET=SPRINGS" << ++group << "\n";
    for (int a : nodes) s << next_element++ << ", " << a + 1 << "\n";
  }
  for (const CalculixNodeSet& set : deck.node_sets) {
    s << "*NSET, NSET=" << set.name << "\n";
    for (size_t i = 0; i < set.nodes.size(); ++i)
      s << set.nodes[i] + 1 << (i + 1 == set.nodes.size() || i % 10 == 9 ? ",\n" : ", ");
  }
  const YeohMaterial& m = deck.material;
  s << "*MATERIAL, NAME=RUBBER\n*HYPERELASTIC, YEOH\n"
    << CalculixNumber(m.c10_Pa) << ", " << CalculixNumber(m.c20_Pa) << ", "
    << CalculixNumber(m.c30_Pa) << ", " << CalculixNumber(2.0 / m.bulk_modulus_Pa)
    << ", 1e30, 1e30\n"
    << "*DENSITY\n"
    << CalculixNumber(m.density_kg_per_m3) << "\n"
    << "*SOLID SECTION, ELSET=EALL, MATERIAL=RUBBER\n";
  group = 0;  // SPRING1 data: the dof, then the stiffness
  for (const auto& [key, nodes] : spring_groups)
    s << "*SPRING, ELSET=SPRINGS" << ++group << "\n" << key.first << ",\n" << key.second << "\n";
  const auto boundary = [&](const std::vector<CalculixBoundary>& list) {
    if (list.empty()) return;
    s << "*BOUNDARY\n";
    for (const CalculixBoundary& b : list)
      s << b.node_set << ", " << b.first_dof << ", " << b.last_dof << ", "
        << CalculixNumber(b.value) << "\n";
  };
  boundary(deck.fixed);
  // Fixed increments: the .dat file then holds the same equally spaced points on every run.
  s << "*STEP, NLGEOM, INC=1000\n*STATIC, DIRECT\n"
    << CalculixNumber(1.0 / deck.increments) << ", 1.0\n";
  boundary(deck.step_boundary);
  for (const std::string& set : deck.force_sets)
    s << "*NODE PRINT, NSET=" << set << ", TOTALS=ONLY\nRF\n";
  for (const std::string& set : deck.displacement_sets) s << "*NODE PRINT, NSET=" << set << "\nU\n";
  s << "*END STEP\n";
  return s.str();
}

/// Reads the tables that *NODE PRINT writes into the .dat file, one entry per increment.
inline std::vector<CalculixIncrement> ParseCalculixDat(const std::string& text) {
  std::vector<CalculixIncrement> increments;
  std::istringstream in(text);
  std::string line;
  // A table header: " total force (fx,fy,fz) for set TOP and time  0.1000000E+00" or
  // " displacements (vx,vy,vz) for set SIDE and time  0.1000000E+00"; rows follow a blank line.
  enum class Table { kNone, kTotalForce, kDisplacement } table = Table::kNone;
  std::string set;
  bool rows_started = false;
  while (std::getline(in, line)) {
    const bool total = line.find("total force (fx,fy,fz) for set ") != std::string::npos;
    const bool disp = line.find("displacements (vx,vy,vz) for set ") != std::string::npos;
    if (total || disp) {
      std::istringstream h(line.substr(line.find("for set ") + 8));
      std::string and_word, time_word;
      double time = 0.0;
      h >> set >> and_word >> time_word >> time;
      if (increments.empty() || std::abs(increments.back().time - time) > 1e-12) {
        increments.emplace_back();
        increments.back().time = time;
      }
      table = total ? Table::kTotalForce : Table::kDisplacement;
      rows_started = false;
      continue;
    }
    if (table == Table::kNone) continue;
    std::istringstream row(line);
    if (line.find_first_not_of(" \t\r") == std::string::npos) {
      if (rows_started) table = Table::kNone;  // the blank line after the rows
      continue;
    }
    rows_started = true;
    CalculixIncrement& inc = increments.back();
    if (table == Table::kTotalForce) {
      Eigen::Vector3d f;
      row >> f.x() >> f.y() >> f.z();
      inc.total_force[set] = f;
      table = Table::kNone;
    } else {
      int node = 0;
      Eigen::Vector3d u;
      row >> node >> u.x() >> u.y() >> u.z();
      if (row) inc.displacement[set][node - 1] = u;
    }
  }
  return increments;
}

/// The full path of `program` if an executable of that name is on PATH.
inline std::optional<std::filesystem::path> FindOnPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return std::nullopt;
  std::istringstream dirs(path);
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    if (dir.empty()) continue;
    const std::filesystem::path p = std::filesystem::path(dir) / program;
    if (std::filesystem::is_regular_file(p) && ::access(p.c_str(), X_OK) == 0) return p;
  }
  return std::nullopt;
}

/// What one ccx run left behind.
struct CalculixRun {
  int status = -1;  ///< std::system's status
  std::string log;  ///< ccx's standard output and error
  std::string dat;  ///< the .dat file (empty if none)
  bool ok = false;  ///< exit 0, no "*ERROR" in the log
};

/// Writes `deck_text` to `folder`/`job`.inp and runs `ccx` there on one thread. ccx exits with 0
/// even after "*ERROR: too many cutbacks", so `ok` also requires that no *ERROR was logged, and
/// callers check that every increment is in the .dat file.
inline CalculixRun RunCalculix(const std::filesystem::path& ccx,
                               const std::filesystem::path& folder, const std::string& job,
                               const std::string& deck_text) {
  CalculixRun run;
  std::ofstream(folder / (job + ".inp")) << deck_text;
  const std::string command = "cd '" + folder.string() +
                              "' && OMP_NUM_THREADS=1 CCX_NPROC_EQUATION_SOLVER=1 '" +
                              ccx.string() + "' -i " + job + " >" + job + ".log 2>&1";
  run.status = std::system(command.c_str());
  const auto slurp = [](const std::filesystem::path& p) {
    std::ifstream f(p);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
  };
  run.log = slurp(folder / (job + ".log"));
  run.dat = slurp(folder / (job + ".dat"));
  run.ok = run.status == 0 && run.log.find("*ERROR") == std::string::npos;
  return run;
}

}  // namespace hotlap::fe::testing
