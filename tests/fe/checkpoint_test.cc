// Checkpoints: a solver saved mid-run and loaded into a fresh solver continues bit for bit; every
// truncation of a saved state and every damaged byte of a checkpoint file is refused with an
// InputError (never a crash); a checkpoint of another mesh, configuration or format version is
// refused with a message naming the file; writing leaves no temporary file behind.

#include "hotlap/fe/checkpoint.h"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "fe/fe_test_util.h"
#include "hotlap/common/error.h"
#include "hotlap/fe/explicit_solver.h"
#include "hotlap/fe/mesh.h"
#include "test_util.h"

namespace hotlap::fe {
namespace {

namespace fs = std::filesystem;
using namespace std::string_literals;

// A 3 x 2 x 2 block of 5 mm elements on a road, its bottom-left nodes tied to a free rim that is
// pushed down and spun; random initial velocities. Every part of the state is in play: positions,
// velocities, the rim, contact and friction (stick springs anchored), the energy accumulators.
ExplicitSolver MakeSolver(int threads) {
  const double h = 0.005;
  Mesh mesh = MakeBlockMesh(3 * h, 2 * h, 2 * h, 3, 2, 2);
  for (size_t a = 0; a < mesh.nodes.size(); ++a) {
    if (mesh.nodes[a].z() > 1.5 * h) mesh.rim_nodes.push_back(static_cast<int>(a));
    if (mesh.nodes[a].z() < 0.5 * h) mesh.contact_nodes.push_back(static_cast<int>(a));
  }
  ExplicitSolver s(mesh, {testing::Tread()}, {}, SolverOptions{});
  s.set_threads(threads);
  RimSettings rim;
  rim.centre = Eigen::Vector3d(1.5 * h, h, 3 * h);
  rim.mass_kg = 0.01;
  rim.inertia_kgm2 = 1e-6;
  rim.x_mode = rim.z_mode = rim.spin_mode = RimDofMode::kFree;
  s.SetRim(rim);
  RoadContact road;
  road.enabled = true;
  road.height_m = 0.0002;  // the bottom nodes start 0.2 mm into the road
  road.penalty_factor = 0.1;
  road.friction = {0.9, 0.45, 0.5};
  s.SetRoad(road);
  std::mt19937 rng(3);
  std::normal_distribution<double> n(0.0, 0.05);
  std::vector<Eigen::Vector3d> v(s.positions().size());
  for (auto& x : v) x = Eigen::Vector3d(1.0 + n(rng), n(rng), n(rng));
  s.SetInitialVelocity(v);
  s.SetRimMotion(1.0, 0.0, 5.0);
  return s;
}

void Advance(ExplicitSolver& s, int steps) {
  for (int k = 0; k < steps; ++k) {
    s.rim_loads().force_z_N = -2.0;
    s.rim_loads().torque_Nm = -0.01 * std::tanh(s.rim_state().spin_rad_per_s);
    s.Step();
  }
}

int Anchored(const ExplicitSolver& s) {
  int n = 0;
  for (int a : s.mesh().contact_nodes) {
    n += s.contact_forces()[a] > 0.0 && s.stick_extensions()[a].norm() > 0.0;
  }
  return n;
}

void ExpectSameState(const ExplicitSolver& restored, const ExplicitSolver& straight) {
  EXPECT_EQ(restored.time(), straight.time());
  for (size_t a = 0; a < straight.positions().size(); ++a) {
    ASSERT_EQ(restored.positions()[a], straight.positions()[a]) << a;
    ASSERT_EQ(restored.velocities()[a], straight.velocities()[a]) << a;
    ASSERT_EQ(restored.stick_extensions()[a], straight.stick_extensions()[a]) << a;
  }
  EXPECT_EQ(restored.energies().contact_stored, straight.energies().contact_stored);
  EXPECT_EQ(restored.rim_state().spin_rad_per_s, straight.rim_state().spin_rad_per_s);
  EXPECT_EQ(restored.rim_state().centre, straight.rim_state().centre);
  EXPECT_EQ(restored.energies().friction, straight.energies().friction);
  EXPECT_EQ(restored.energies().external_work, straight.energies().external_work);
  EXPECT_EQ(restored.energies().BalanceError(), straight.energies().BalanceError());
}

// Saved at step 30 with bottom nodes on the road and their stick springs stretched (anchors in
// play), compared at step 60 (still anchored) and 300 (the block has bounced off the road).
TEST(FeCheckpoint, SolverStateRoundTripContinuesBitForBit) {
  ExplicitSolver straight = MakeSolver(2);
  Advance(straight, 30);
  ASSERT_GT(Anchored(straight), 0);
  BinaryWriter w;
  straight.SaveState(w);

  // Restored on the same thread count (per-thread buffers: bits depend on it).
  ExplicitSolver restored = MakeSolver(2);
  BinaryReader r(w.bytes(), "memory");
  restored.LoadState(r);
  r.ExpectEnd();
  EXPECT_EQ(restored.steps(), 30);
  Advance(straight, 30);
  Advance(restored, 30);
  ASSERT_GT(Anchored(straight), 0);
  ExpectSameState(restored, straight);
  Advance(straight, 240);
  Advance(restored, 240);
  ASSERT_GT(straight.energies().friction, 0.0);  // the road and friction were in play
  ExpectSameState(restored, straight);
}

// Every prefix of a saved state is refused, and the solver is left as it was.
TEST(FeCheckpoint, EveryTruncationIsRefusedAndLeavesTheSolverUnchanged) {
  ExplicitSolver s = MakeSolver(1);
  Advance(s, 20);
  BinaryWriter w;
  s.SaveState(w);
  ExplicitSolver target = MakeSolver(1);
  const std::vector<Eigen::Vector3d> before = target.positions();
  for (size_t len = 0; len < w.bytes().size(); len += 7) {
    BinaryReader r(std::string_view(w.bytes()).substr(0, len), "cut");
    EXPECT_THROW(target.LoadState(r), InputError) << len;
  }
  EXPECT_EQ(target.positions(), before);
  EXPECT_EQ(target.steps(), 0);
}

class FeCheckpointFile : public ::testing::Test {
 protected:
  std::string ReadBytes(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
  void WriteBytes(const fs::path& p, const std::string& s) {
    std::ofstream(p, std::ios::binary).write(s.data(), s.size());
  }
  std::string Refusal(const fs::path& p, const CheckpointKey& key) {
    try {
      ReadCheckpointFile(p, key);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }

  const test::TempDir tmp_;
  const fs::path dir_ = tmp_.path();
  const CheckpointKey key_{0x1234, 27, 8, 0x5678};
};

TEST_F(FeCheckpointFile, RoundTripAndNoTemporaryLeft) {
  const fs::path p = dir_ / "c.bin";
  const std::string payload = "the payload\0with a zero"s;
  WriteCheckpointFile(p, key_, payload);
  EXPECT_EQ(ReadCheckpointFile(p, key_), payload);
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir_)) files += e.is_regular_file();
  EXPECT_EQ(files, 1);
}

TEST_F(FeCheckpointFile, DamagedTruncatedOrForeignFilesAreRefusedNamingTheFile) {
  const fs::path p = dir_ / "c.bin", bad = dir_ / "bad.bin";
  WriteCheckpointFile(p, key_, std::string(200, 'x'));
  const std::string good = ReadBytes(p);
  // Every single flipped byte: refused (checksum, header or version), never accepted.
  for (size_t k = 0; k < good.size(); ++k) {
    std::string s = good;
    s[k] ^= 0x20;
    WriteBytes(bad, s);
    const std::string msg = Refusal(bad, key_);
    EXPECT_NE(msg.find("bad.bin"), std::string::npos) << k << ": " << msg;
  }
  // Every truncation.
  for (size_t len = 0; len < good.size(); ++len) {
    WriteBytes(bad, good.substr(0, len));
    EXPECT_NE(Refusal(bad, key_).find("bad.bin"), std::string::npos) << len;
  }
  WriteBytes(bad, good.substr(0, good.size() - 3));
  EXPECT_NE(Refusal(bad, key_).find("truncated"), std::string::npos) << Refusal(bad, key_);
  WriteBytes(bad, "mesh:\n  nodes: 3\n");
  EXPECT_NE(Refusal(bad, key_).find("not a hotlap FE checkpoint"), std::string::npos);
  EXPECT_NE(Refusal(dir_ / "missing.bin", key_).find("does not exist"), std::string::npos);
  EXPECT_NE(Refusal(dir_, key_).find("not a file"), std::string::npos);
}

TEST_F(FeCheckpointFile, AnotherMeshConfigurationOrVersionIsRefused) {
  const fs::path p = dir_ / "c.bin";
  WriteCheckpointFile(p, key_, "state");
  CheckpointKey other = key_;
  other.elements = 9;
  EXPECT_NE(Refusal(p, other).find("another mesh (8 elements, 27 nodes; this configuration "
                                   "makes 9 elements, 27 nodes)"),
            std::string::npos)
      << Refusal(p, other);
  other = key_;
  other.mesh_hash ^= 1;
  EXPECT_NE(Refusal(p, other).find("placed differently"), std::string::npos);
  other = key_;
  other.config_hash ^= 1;
  EXPECT_NE(Refusal(p, other).find("another configuration"), std::string::npos);
  // Files of versions 1 (before the stick anchors), 2 (before the cord strain and the
  // directional cord step), 3 (before the state saved whole), 4 (before the ABS wheel-speed
  // sensor's sums) and 5 (before the wheel-speed filter's state) and of a future version (the
  // checksum made right again): refused by version.
  ASSERT_EQ(kCheckpointVersion, 6u);
  const std::string good = ReadBytes(p);
  for (const char version : {1, 2, 3, 4, 5, 7}) {
    std::string s = good;
    s[8] = version;
    s.resize(s.size() - 8);
    const std::uint64_t h = Fnv1a64(s);
    s.append(reinterpret_cast<const char*>(&h), 8);
    WriteBytes(p, s);
    EXPECT_NE(Refusal(p, key_).find("has format version " + std::to_string(version) +
                                    "; this build reads version 6"),
              std::string::npos)
        << Refusal(p, key_);
  }
}

TEST(FeCheckpointHash, MeshHashSeesAMovedNode) {
  Mesh a = MakeBlockMesh(1, 1, 1, 2, 2, 2), b = a;
  EXPECT_EQ(HashMesh(a), HashMesh(b));
  b.nodes[5].x() += 1e-12;
  EXPECT_NE(HashMesh(a), HashMesh(b));
}

}  // namespace
}  // namespace hotlap::fe
