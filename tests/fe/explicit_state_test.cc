// The explicit solver split into model, state and step: the state's field lists cover every
// member (so the checkpoint, which walks them, saves the state whole); the free functions on a
// model and a state step exactly as the ExplicitSolver object does; a state saved and loaded
// continues bit for bit; a checkpoint of another model is refused naming the field.

#include "hotlap/fe/explicit_state.h"

#include <algorithm>
#include <cstddef>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "fe/fe_test_util.h"
#include "hotlap/common/error.h"
#include "hotlap/fe/explicit_checkpoint.h"
#include "hotlap/fe/explicit_model.h"
#include "hotlap/fe/explicit_solver.h"
#include "hotlap/fe/explicit_step.h"
#include "hotlap/fe/tyre_steps.h"

namespace hotlap::fe {
namespace {

// The byte ranges [offset, offset + size) of the members VisitFields lists, sorted, must tile
// the struct but for alignment padding: a member left out of the list leaves a hole (or, at the
// end, a struct larger than its fields).
template <typename T>
void ExpectFieldsCoverStruct(const char* name) {
  T s{};
  struct Span {
    size_t offset, size, align;
    std::string field;
  };
  std::vector<Span> spans;
  const char* base = reinterpret_cast<const char*>(&s);
  VisitFields(s, [&](const char* field, auto& member) {
    spans.push_back({static_cast<size_t>(reinterpret_cast<const char*>(&member) - base),
                     sizeof(member), alignof(std::remove_reference_t<decltype(member)>), field});
  });
  std::sort(spans.begin(), spans.end(),
            [](const Span& a, const Span& b) { return a.offset < b.offset; });
  size_t end = 0;
  for (const Span& f : spans) {
    const size_t aligned = (end + f.align - 1) / f.align * f.align;
    EXPECT_EQ(f.offset, aligned) << name << ": a member not in VisitFields before '" << f.field
                                 << "'";
    end = f.offset + f.size;
  }
  const size_t aligned_end = (end + alignof(T) - 1) / alignof(T) * alignof(T);
  EXPECT_EQ(sizeof(T), aligned_end) << name << ": a member not in VisitFields at the end";
}

TEST(FeExplicitState, VisitFieldsCoversEveryMember) {
  ExpectFieldsCoverStruct<ExplicitState>("ExplicitState");
  ExpectFieldsCoverStruct<Energies>("Energies");
  ExpectFieldsCoverStruct<RimSettings>("RimSettings");
  ExpectFieldsCoverStruct<RimState>("RimState");
  ExpectFieldsCoverStruct<RimLoads>("RimLoads");
  ExpectFieldsCoverStruct<RoadContact>("RoadContact");
  ExpectFieldsCoverStruct<FrictionLaw>("FrictionLaw");
  ExpectFieldsCoverStruct<TyreRunState>("TyreRunState");
  ExpectFieldsCoverStruct<StepCursor>("StepCursor");
  ExpectFieldsCoverStruct<BrakeStep>("BrakeStep");
  ExpectFieldsCoverStruct<HistoryRow>("HistoryRow");
}

// A 3 x 2 x 2 block on a road, its top nodes tied to a free rim pushed down and spun, random
// initial velocities, inflated from below: every part of the state in play.
Mesh BlockOnRoad() {
  const double h = 0.005;
  Mesh mesh = MakeBlockMesh(3 * h, 2 * h, 2 * h, 3, 2, 2);
  testing::AddBlockPressureFaces(mesh, 3, 2, 2, /*top=*/false);
  for (size_t a = 0; a < mesh.nodes.size(); ++a) {
    if (mesh.nodes[a].z() > 1.5 * h) mesh.rim_nodes.push_back(static_cast<int>(a));
    if (mesh.nodes[a].z() < 0.5 * h) mesh.contact_nodes.push_back(static_cast<int>(a));
  }
  return mesh;
}

void Prepare(const ExplicitModel& model, ExplicitState& state) {
  const double h = 0.005;
  RimSettings rim;
  rim.centre = Eigen::Vector3d(1.5 * h, h, 3 * h);
  rim.mass_kg = 0.01;
  rim.inertia_kgm2 = 1e-6;
  rim.x_mode = rim.z_mode = rim.spin_mode = RimDofMode::kFree;
  SetRim(model, rim, state);
  RoadContact road;
  road.enabled = true;
  road.height_m = 0.0002;
  road.penalty_factor = 0.1;
  road.friction = {0.9, 0.45, 0.5};
  SetRoad(road, state);
  std::mt19937 rng(5);
  std::normal_distribution<double> n(0.0, 0.05);
  std::vector<Eigen::Vector3d> v(state.x.size());
  for (auto& x : v) x = Eigen::Vector3d(1.0 + n(rng), n(rng), n(rng));
  SetInitialVelocity(model, v, state);
  SetRimMotion(model, 1.0, 0.0, 5.0, state);
  state.pressure_Pa = 20e3;
  state.mass_damping_per_s = 10.0;
}

void Advance(const ExplicitModel& model, const StepOptions& options, ExplicitState& state,
             ExplicitWorkspace& workspace, int steps) {
  for (int k = 0; k < steps; ++k) {
    state.rim_loads.force_z_N = -2.0;
    state.rim_loads.torque_Nm = -0.01 * std::tanh(state.rim.spin_rad_per_s);
    AdvanceExplicit(model, options, state, workspace);
  }
}

// Every field of two states, as the checkpoint writes them: equal bytes.
std::string Bytes(const ExplicitModel& model, const ExplicitState& state) {
  BinaryWriter w;
  SaveExplicitState(model, state, w);
  return w.bytes();
}

TEST(FeExplicitState, FreeFunctionsStepAsTheSolverObject) {
  const ExplicitModel model = MakeExplicitModel(BlockOnRoad(), {testing::Tread()}, {}, {});
  StepOptions options;
  options.kernel = ElementKernel::kPortable;
  ExplicitState state = MakeInitialState(model);
  ExplicitWorkspace workspace;
  Prepare(model, state);
  Advance(model, options, state, workspace, 200);

  ExplicitSolver solver(BlockOnRoad(), {testing::Tread()}, {}, {});
  solver.set_element_kernel(ElementKernel::kPortable);
  Prepare(solver.model(), solver.mutable_state());
  for (int k = 0; k < 200; ++k) {
    solver.rim_loads().force_z_N = -2.0;
    solver.rim_loads().torque_Nm = -0.01 * std::tanh(solver.rim_state().spin_rad_per_s);
    solver.Step();
  }
  EXPECT_EQ(state.steps, 200);
  EXPECT_GT(state.energies.friction, 0.0);  // the road and friction were in play
  EXPECT_TRUE(Bytes(model, state) == Bytes(solver.model(), solver.state()));
}

// Saved at step 40 and loaded into a fresh state of a fresh model (and fresh scratch): equal
// bytes at step 150 to the state run straight through, on the per-thread buffers of 2 threads.
TEST(FeExplicitState, SavedAndLoadedStateContinuesBitForBit) {
  const ExplicitModel model = MakeExplicitModel(BlockOnRoad(), {testing::Tread()}, {}, {});
  StepOptions options;
  options.threads = 2;
  ExplicitState straight = MakeInitialState(model);
  ExplicitWorkspace workspace;
  Prepare(model, straight);
  Advance(model, options, straight, workspace, 40);
  const std::string saved = Bytes(model, straight);

  const ExplicitModel again = MakeExplicitModel(BlockOnRoad(), {testing::Tread()}, {}, {});
  ExplicitState restored = MakeInitialState(again);  // no rim, no road: the file brings them
  BinaryReader r(saved, "memory");
  LoadExplicitState(again, r, restored);
  r.ExpectEnd();
  ASSERT_TRUE(restored.rim_settings.has_value());
  EXPECT_TRUE(Bytes(again, restored) == saved);
  ExplicitWorkspace fresh;
  Advance(model, options, straight, workspace, 110);
  Advance(again, options, restored, fresh, 110);
  EXPECT_TRUE(Bytes(again, restored) == Bytes(model, straight));
  EXPECT_EQ(restored.x, straight.x);
  EXPECT_EQ(restored.energies.BalanceError(), straight.energies.BalanceError());
}

// Another mesh (more nodes), another time step, a damaged field name: refused naming what is
// wrong, the state unchanged.
TEST(FeExplicitState, LoadRefusesAnotherModelAndNamesTheField) {
  const ExplicitModel model = MakeExplicitModel(BlockOnRoad(), {testing::Tread()}, {}, {});
  const ExplicitState state = MakeInitialState(model);
  const std::string saved = Bytes(model, state);
  const auto refusal = [](const ExplicitModel& m, const std::string& bytes) {
    ExplicitState target = MakeInitialState(m);
    const ExplicitState before = target;
    BinaryReader r(bytes, "c.bin");
    try {
      LoadExplicitState(m, r, target);
    } catch (const InputError& e) {
      EXPECT_EQ(target.x, before.x);
      return std::string(e.what());
    }
    return std::string();
  };
  SolverOptions fixed_step;
  fixed_step.time_step_s = 0.5 * model.time_step_s;
  const ExplicitModel other_step =
      MakeExplicitModel(BlockOnRoad(), {testing::Tread()}, {}, fixed_step);
  EXPECT_NE(refusal(other_step, saved).find("is not this model's"), std::string::npos);
  SolverOptions same_step;
  same_step.time_step_s = model.time_step_s;
  const double h = 0.005;
  const ExplicitModel bigger = MakeExplicitModel(MakeBlockMesh(4 * h, 2 * h, 2 * h, 4, 2, 2),
                                                 {testing::Tread()}, {}, same_step);
  const std::string msg = refusal(bigger, saved);
  EXPECT_NE(msg.find("entries where this model has"), std::string::npos) << msg;
  EXPECT_NE(msg.find("'x'"), std::string::npos) << msg;
  std::string renamed = saved;
  const size_t at = renamed.find("on_road");
  ASSERT_NE(at, std::string::npos);
  renamed[at] = 'O';
  EXPECT_NE(refusal(model, renamed).find("field 'on_road' expected, 'On_road' found"),
            std::string::npos)
      << refusal(model, renamed);
}

// Issue 27: SolverOptions::time_step_scale takes that fraction of the step and keeps the road's
// penalty springs of the full step (so a time-step study refines the same model); a scale
// outside (0, 1] is refused.
TEST(FeExplicitState, StepScaleShortensTheStepAndKeepsTheContactStiffness) {
  const ExplicitModel full = MakeExplicitModel(BlockOnRoad(), {testing::Tread()}, {}, {});
  SolverOptions half_options;
  half_options.time_step_scale = 0.5;
  const ExplicitModel half = MakeExplicitModel(BlockOnRoad(), {testing::Tread()}, {}, half_options);
  EXPECT_DOUBLE_EQ(half.time_step_s, 0.5 * full.time_step_s);
  EXPECT_EQ(half.contact_step_s, full.time_step_s);
  EXPECT_EQ(full.contact_step_s, full.time_step_s);
  ExplicitState a = MakeInitialState(full), b = MakeInitialState(half);
  Prepare(full, a);
  Prepare(half, b);
  for (size_t n = 0; n < a.x.size(); ++n) {
    EXPECT_EQ(ContactStiffness(full, a, n), ContactStiffness(half, b, n)) << n;
    EXPECT_EQ(StickStiffness(full, a, n), StickStiffness(half, b, n)) << n;
  }
  for (const double bad : {0.0, -0.5, 1.5}) {
    SolverOptions o;
    o.time_step_scale = bad;
    EXPECT_THROW(MakeExplicitModel(BlockOnRoad(), {testing::Tread()}, {}, o), InputError) << bad;
  }
}

}  // namespace
}  // namespace hotlap::fe
