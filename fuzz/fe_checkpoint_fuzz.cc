// libFuzzer target: an FE checkpoint (fe::ReadCheckpointFile, then the explicit solver's state,
// fe::LoadExplicitState, as hotlap fe abs --restart reads it) (docs/reliability.md). Only
// InputError is an expected outcome.
//
// The first byte of an input picks what the rest is: even, a payload, which the target wraps in
// a valid header and hash (random bytes would almost never pass the hash, so the payload reader
// would go unfuzzed); odd, a whole checkpoint file, header and hash included. The solver is a
// small block on a road with a rim, so every part of the state is in the payload.
//
// HOTLAP_FUZZ_WRITE_SEEDS=DIR: write the two seed inputs (a real state as payload and as file)
// to DIR and exit (scripts/fuzz.sh makes the corpus with it).

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fuzz_input.h"
#include "hotlap/common/error.h"
#include "hotlap/common/read_file.h"
#include "hotlap/fe/checkpoint.h"
#include "hotlap/fe/explicit_solver.h"
#include "hotlap/fe/mesh.h"
#include "hotlap/fe/yeoh.h"

namespace {

namespace fe = hotlap::fe;
namespace fuzz = hotlap::fuzz;

// A 2 x 1 x 1 block of 5 mm elements, its top nodes on a free rim, its bottom nodes on the road.
fe::ExplicitSolver MakeSolver() {
  const double h = 0.005;
  fe::Mesh mesh = fe::MakeBlockMesh(2 * h, h, h, 2, 1, 1);
  for (size_t a = 0; a < mesh.nodes.size(); ++a) {
    if (mesh.nodes[a].z() > 0.5 * h) mesh.rim_nodes.push_back(static_cast<int>(a));
    if (mesh.nodes[a].z() < 0.5 * h) mesh.contact_nodes.push_back(static_cast<int>(a));
  }
  fe::ExplicitSolver s(mesh, {fe::MakeYeohMaterial(7.77561e5, -2.76138e5, 9.5427e4, 1178.0, 20.0)},
                       {}, fe::SolverOptions{});
  fe::RimSettings rim;
  rim.centre = Eigen::Vector3d(h, 0.5 * h, 2 * h);
  rim.mass_kg = 0.01;
  rim.inertia_kgm2 = 1e-6;
  rim.x_mode = rim.z_mode = rim.spin_mode = fe::RimDofMode::kFree;
  s.SetRim(rim);
  fe::RoadContact road;
  road.enabled = true;
  road.height_m = 0.0002;
  road.penalty_factor = 0.1;
  road.friction = {0.9, 0.45, 0.5};
  s.SetRoad(road);
  s.SetInitialVelocity(std::vector<Eigen::Vector3d>(s.positions().size(), {1.0, 0.0, 0.0}));
  s.SetRimMotion(1.0, 0.0, 5.0);
  return s;
}

fe::CheckpointKey KeyOf(const fe::ExplicitSolver& s) {
  fe::CheckpointKey key;
  key.mesh_hash = fe::HashMesh(s.mesh());
  key.nodes = s.mesh().nodes.size();
  key.elements = s.mesh().elements.size();
  key.config_hash = 42;
  return key;
}

void WriteSeeds(const std::string& dir) {
  fe::ExplicitSolver s = MakeSolver();
  for (int k = 0; k < 20; ++k) {
    s.rim_loads().force_z_N = -2.0;
    s.Step();
  }
  fe::BinaryWriter w;
  s.SaveState(w);
  std::ofstream(dir + "/payload", std::ios::binary) << '\0' << w.bytes();
  const auto file = fuzz::WorkDir() / "seed.ckpt";
  fe::WriteCheckpointFile(file, KeyOf(s), w.bytes());
  std::ofstream(dir + "/file", std::ios::binary) << '\1' << hotlap::ReadWholeFile(file);
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  if (const char* dir = std::getenv("HOTLAP_FUZZ_WRITE_SEEDS"); dir != nullptr) {
    WriteSeeds(dir);
    std::exit(0);
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  static const auto path = fuzz::WorkDir() / "state.ckpt";
  fe::ExplicitSolver solver = MakeSolver();
  const fe::CheckpointKey key = KeyOf(solver);
  try {
    if (data[0] % 2 == 0) {
      fe::WriteCheckpointFile(path, key, std::string(fuzz::AsText(data + 1, size - 1)));
    } else {
      fuzz::WriteInput(path, data + 1, size - 1);
    }
    const std::string payload = fe::ReadCheckpointFile(path, key);
    fe::BinaryReader r(payload, path.string());
    solver.LoadState(r);
    r.ExpectEnd();
  } catch (const hotlap::InputError&) {
  }
  return 0;
}
