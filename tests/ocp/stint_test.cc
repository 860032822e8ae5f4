// A stint as one optimal-control problem (ocp/stint.h), on Darlington with a coarse 20 m mesh and
// two laps: the repeated track, continuity at the lap line, the look-ahead never slower than the
// greedy driver, accelerated wear slowing the later laps, fuel burnt as the engine's work; and a
// stint resuming from its checkpoints (StintOptions::checkpoint_dir).

#include "hotlap/ocp/stint.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/ocp/stint_checkpoint.h"
#include "hotlap/track/track_io.h"
#include "test_util.h"

namespace hotlap::ocp {
namespace {

namespace fs = std::filesystem;

StintOptions Coarse(int laps) {
  StintOptions o;
  o.laps = laps;
  o.lap.step_m = 20.0;
  o.lap.coarse_step_m = 0.0;
  o.lap.ambient_temp = CelsiusToKelvin(25.0);
  o.lap.track_temp = CelsiusToKelvin(40.0);
  return o;
}

class StintTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    car_ = new vehicle::Car(vehicle::LoadCar(test::Gen7Dir() / "car.yaml"));
    track_ = new track::Track(track::LoadTrack("darlington"));
  }
  static void TearDownTestSuite() {
    delete car_;
    delete track_;
  }
  // Two laps without wear or fuel, solved once for the tests that need them.
  static const StintResult& NoWearNoFuel() {
    static const StintResult r = [] {
      StintOptions o = Coarse(2);
      o.wear_scale = 0.0;
      o.fuel_kg = 0.0;
      // The paper's models from their racing start of a 15 degC carcass rise a lap, whose two laps
      // chain to the greedy driver's within the tolerance. With the gas-and-rim tyres and bulk
      // discs the stint solve from the greedy laps has ended 21 ms slower than them in one run and
      // 5 ms faster in another (another thread count), and the first greedy lap straight from the
      // QSS guess on 20 m converged to a 65 s lap; the paper's models from the 5 degC start (20
      // laps in, carcasses near 200 degC) to a 37.8 s one: local optima the accuracy issue's work
      // has to tame (docs/optimal-control.md, "Stints").
      o.lap.racing_carcass_rise_K = 15.0;
      // The first greedy lap coarse to fine, as the program solves it: straight from the QSS
      // guess on 20 m it converged to a 157-169 s lap once the wear was tuned (2026-11-29).
      o.lap.coarse_step_m = 40.0;
      return SolveStint(vehicle::PaperModelsOf(*car_), *track_, o);
    }();
    return r;
  }
  static vehicle::Car* car_;
  static track::Track* track_;
};
vehicle::Car* StintTest::car_ = nullptr;
track::Track* StintTest::track_ = nullptr;

TEST_F(StintTest, RepeatedTrackIsTheSameRibbonLapAfterLap) {
  const track::Track three = track_->Repeated(3);
  EXPECT_DOUBLE_EQ(three.length_m(), 3.0 * track_->length_m());
  EXPECT_EQ(three.laps(), 3);
  EXPECT_EQ(three.winding(), 3 * track_->winding());
  for (double s : {0.0, 123.4, 987.6, 2000.0}) {
    for (int lap = 0; lap < 3; ++lap) {
      const track::TrackPoint a = track_->At(s), b = three.At(s + lap * track_->length_m());
      EXPECT_NEAR(b.curvature_per_m, a.curvature_per_m, 1e-12);
      EXPECT_NEAR(b.bank_rad, a.bank_rad, 1e-12);
      EXPECT_NEAR(b.x_m, a.x_m, 1e-9);
      EXPECT_NEAR(b.heading_rad, a.heading_rad + 2.0 * 3.141592653589793 * track_->winding() * lap,
                  1e-9);
    }
  }
  EXPECT_THROW(track_->Repeated(0), InputError);
}

// Two laps on 20 m, nothing carried but the temperatures (no wear, no fuel): the stint is the
// greedy driver's two laps chained, to the solver's tolerance, and never slower than them by more
// (the greedy laps are a feasible point of the stint but for the jumps of the mechanical states
// at the line, which the stint must close).
TEST_F(StintTest, WithNoWearAndNoFuelTwoLapsAreTheSingleLapsChained) {
  const StintResult& r = NoWearNoFuel();
  ASSERT_TRUE(r.ok()) << r.run.solution.solve.message;
  ASSERT_EQ(r.laps.size(), 2u);
  ASSERT_EQ(r.greedy_laps.size(), 2u);
  EXPECT_NEAR(r.total_time_s, r.laps[0].time_s + r.laps[1].time_s, 1e-9);
  EXPECT_NEAR(r.total_time_s, r.run.solution.lap_time, 1e-6);
  EXPECT_LE(r.total_time_s, r.greedy_total_time_s + 2e-3);
  EXPECT_NEAR(r.total_time_s, r.greedy_total_time_s, 3e-3);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(r.laps[i].time_s, r.greedy_laps[i].time_s, 1e-2) << i;
    EXPECT_EQ(r.laps[i].fuel_burnt_kg, 0.0);
    // Zero to round-off: the wear states' defects are solved with the others (1e-30 mm with
    // SCOTCH's ordering, exactly 0 with PORD's).
    EXPECT_NEAR(r.laps[i].wear_end_mm[3], 0.0, 1e-15);
  }
  // Carried across the line: lap 2 starts where lap 1 ends, so its carcasses are hotter.
  for (int c = 0; c < 4; ++c) {
    EXPECT_GT(r.laps[1].peak_carcass_temp_K[c], r.laps[0].peak_carcass_temp_K[c]) << c;
    EXPECT_GT(r.laps[1].min_carcass_temp_K[c], r.laps[0].min_carcass_temp_K[c]) << c;
  }
  // Each lap's window: the lowest and highest of its nodes' temperatures, the tread cooling on
  // the straights by more than the carcass does.
  const LapSolution& sol = r.run.solution;
  const size_t half = (sol.distance.size() - 1) / 2;
  for (int c = 0; c < 4; ++c) {
    const std::vector<double>& tread = sol.corners[c].tread_temp;
    const auto first = std::minmax_element(tread.begin(), tread.begin() + half + 1);
    EXPECT_DOUBLE_EQ(r.laps[0].min_tread_temp_K[c], *first.first) << c;
    EXPECT_DOUBLE_EQ(r.laps[0].peak_tread_temp_K[c], *first.second) << c;
    for (const StintLap& l : r.laps) {
      EXPECT_LT(l.min_disc_temp_K[c], l.peak_disc_temp_K[c]) << c;
      EXPECT_GT(l.peak_tread_temp_K[c] - l.min_tread_temp_K[c],
                l.peak_carcass_temp_K[c] - l.min_carcass_temp_K[c])
          << c;
    }
  }
  // One solution over both laps: the channels run on through the line without a jump larger
  // than the largest step elsewhere (the greedy laps' mechanical states jump there).
  const LapSolution& s = r.run.solution;
  const size_t line = (s.distance.size() - 1) / 2;
  ASSERT_NEAR(s.distance[line], track_->length_m(), 1e-6);
  double largest = 0.0;
  for (size_t k = 1; k < s.u.size(); ++k) {
    if (k != line) largest = std::max(largest, std::abs(s.u[k] - s.u[k - 1]));
  }
  EXPECT_LE(std::abs(s.u[line] - s.u[line - 1]), largest);
}

// Wear and fuel carried lap to lap: with the wear rate 30 times, the tyres lose more tread each
// lap and lap 2 is slower than lap 2 without wear; the fuel burnt is the engine's work at the
// assumed consumption, worked out again here from the channels.
TEST_F(StintTest, WearSlowsTheLaterLapsAndFuelIsTheEnginesWork) {
  StintOptions worn = Coarse(2);
  worn.wear_scale = 30.0;
  worn.fuel_kg = 40.0;
  const StintResult& a = NoWearNoFuel();
  const StintResult b = SolveStint(*car_, *track_, worn);
  ASSERT_TRUE(a.ok() && b.ok());
  for (int c = 0; c < 4; ++c) {
    EXPECT_GT(b.laps[0].wear_end_mm[c], 0.0) << c;
    EXPECT_GT(b.laps[1].wear_end_mm[c], 1.5 * b.laps[0].wear_end_mm[c]) << c;
  }
  EXPECT_GT(b.laps[1].time_s, a.laps[1].time_s + 1e-3);
  EXPECT_LE(b.total_time_s, b.greedy_total_time_s + 2e-3);
  // Fuel: 40 kg at the start, lap 1 at the full mass, lap 2 lighter by what lap 1 burnt.
  const double mass0 = car_->vehicle->chassis.mass;
  EXPECT_DOUBLE_EQ(b.laps[0].mass_kg, mass0);
  EXPECT_NEAR(b.laps[1].mass_kg, mass0 - b.greedy_laps[0].fuel_burnt_kg, 1e-9);
  const LapSolution& s = b.run.solution;
  const double eta = car_->vehicle->powertrain.driveline_efficiency;
  double work = 0.0;  // engine work over lap 1, J
  for (size_t k = 0; k + 1 < s.time.size() && s.distance[k + 1] <= track_->length_m() + 1e-6; ++k) {
    work += 0.5 * (s.drive_power[k] + s.drive_power[k + 1]) * (s.time[k + 1] - s.time[k]) / eta;
  }
  EXPECT_NEAR(b.laps[0].fuel_burnt_kg, work * worn.bsfc_kg_per_J, 1e-9);
  // About a kilogram a lap: 300 g/kWh of a 500 kW engine mostly flat out for 30 s.
  EXPECT_GT(b.laps[0].fuel_burnt_kg, 0.5);
  EXPECT_LT(b.laps[0].fuel_burnt_kg, 2.0);
  EXPECT_NEAR(b.laps[1].fuel_end_kg, 40.0 - b.laps[0].fuel_burnt_kg - b.laps[1].fuel_burnt_kg,
              1e-9);
  EXPECT_LT(b.fuel_plan_error_kg, 0.05);
}

TEST_F(StintTest, BadOptionsAreInputErrors) {
  StintOptions o = Coarse(0);
  EXPECT_THROW(SolveStint(*car_, *track_, o), InputError);
  o = Coarse(2);
  o.wear_scale = -1.0;
  EXPECT_THROW(SolveStint(*car_, *track_, o), InputError);
  o = Coarse(2);
  o.fuel_kg = 5000.0;
  EXPECT_THROW(SolveStint(*car_, *track_, o), InputError);
  o = Coarse(2);
  o.lap.thermal_start = ThermalStart::kPeriodic;
  EXPECT_THROW(SolveStint(*car_, *track_, o), InputError);
  o = Coarse(2);
  o.lap.collocation = Collocation::kHermiteSimpson;
  EXPECT_PRED2(test::Contains, test::InputErrorOf([&] { SolveStint(*car_, *track_, o); }),
               "Hermite-Simpson");
}

// The fingerprint changes with the stint's options, the car's parameters (through the warm-up)
// and the caller's key, and with nothing else.
TEST_F(StintTest, FingerprintTellsStintsApart) {
  const StintOptions o = Coarse(2);
  const LapWarmUp w = RunLapWarmUp(*car_, *track_, o.lap);
  const std::uint64_t base = StintFingerprint(o, *track_, w);
  EXPECT_EQ(StintFingerprint(o, *track_, RunLapWarmUp(*car_, *track_, o.lap)), base);
  StintOptions changed = o;
  changed.wear_scale = 2.0;
  EXPECT_NE(StintFingerprint(changed, *track_, w), base);
  changed = o;
  changed.lap.front_disc_limit = CelsiusToKelvin(600.0);
  EXPECT_NE(StintFingerprint(changed, *track_, w), base);
  changed = o;
  changed.checkpoint_key = "car.yaml:123;";
  EXPECT_NE(StintFingerprint(changed, *track_, w), base);
  // A heavier car: another warm-up.
  vehicle::Car heavier = *car_;
  heavier.vehicle->chassis.mass += 20.0;
  EXPECT_NE(StintFingerprint(o, *track_, RunLapWarmUp(heavier, *track_, o.lap)), base);
  // The folder and the checkpoint interval are not the stint.
  changed = o;
  changed.checkpoint_dir = "/elsewhere";
  changed.checkpoint_every = 3;
  EXPECT_EQ(StintFingerprint(changed, *track_, w), base);
}

// A run stopped part way through the stint's solve (as a kill would stop it) resumes with every
// greedy lap from its file and the stint from its last saved iterate, and ends on the same stint
// having lost at most one checkpoint interval; a run of a finished stint converges at once.
TEST_F(StintTest, StoppedStintResumesFromItsCheckpoints) {
  const test::TempDir dir;
  StintOptions o = Coarse(2);
  o.checkpoint_dir = dir.path() / "checkpoints";
  o.checkpoint_every = 2;
  const StintResult whole = SolveStint(*car_, *track_, o);
  ASSERT_TRUE(whole.ok()) << whole.run.solution.solve.message;
  ASSERT_GT(whole.ipopt_iterations, 6) << "too short to stop part way";
  EXPECT_EQ(whole.greedy_laps_resumed, 0);
  EXPECT_EQ(whole.resumed_from_iteration, 0);
  for (const char* f : {"greedy_lap_1.bin", "greedy_lap_2.bin", "stint_iterate.bin"}) {
    EXPECT_TRUE(fs::is_regular_file(o.checkpoint_dir / f)) << f;
  }

  // The same stint again: nothing solved but a check of the saved end.
  const StintResult again = SolveStint(*car_, *track_, o);
  ASSERT_TRUE(again.ok()) << again.run.solution.solve.message;
  EXPECT_EQ(again.greedy_laps_resumed, 2);
  EXPECT_EQ(again.resumed_from_iteration, whole.ipopt_iterations);
  EXPECT_LE(again.ipopt_iterations, 3);
  EXPECT_NEAR(again.total_time_s, whole.total_time_s, 1e-5);
  EXPECT_DOUBLE_EQ(again.greedy_total_time_s, whole.greedy_total_time_s);

  // Stopped at iteration 5 of the stint's solve: its file holds iteration 4.
  fs::remove(o.checkpoint_dir / "stint_iterate.bin");
  StintOptions stopping = o;
  bool in_stint = false;
  stopping.lap.ipopt.on_iteration = [&in_stint](int it, double, double, double) {
    return !(in_stint && it >= 5);
  };
  const StintResult stopped = SolveStint(*car_, *track_, stopping, [&](const std::string& line) {
    if (line.rfind("the stint:", 0) == 0) in_stint = true;
  });
  EXPECT_FALSE(stopped.ok());
  EXPECT_EQ(stopped.greedy_laps_resumed, 2);
  const StintResult resumed = SolveStint(*car_, *track_, o);
  ASSERT_TRUE(resumed.ok()) << resumed.run.solution.solve.message;
  EXPECT_EQ(resumed.greedy_laps_resumed, 2);
  EXPECT_EQ(resumed.resumed_from_iteration, 4);
  EXPECT_NEAR(resumed.total_time_s, whole.total_time_s, 1e-3);
  EXPECT_LE(resumed.ipopt_iterations, whole.ipopt_iterations - 4 + o.checkpoint_every)
      << "the whole solve took " << whole.ipopt_iterations;
}

// A checkpoint that cannot be written (here its path is a folder; a full disk alike) costs the
// resume, not the run: the stint ends as without checkpoints, with one warning.
TEST_F(StintTest, CheckpointThatCannotBeWrittenIsAWarning) {
  const test::TempDir dir;
  StintOptions o = Coarse(2);
  o.wear_scale = 0.0;
  o.fuel_kg = 0.0;
  o.checkpoint_dir = dir.path();
  o.checkpoint_every = 4;
  for (const char* f : {"greedy_lap_1.bin", "greedy_lap_2.bin", "stint_iterate.bin"}) {
    fs::create_directories(dir.path() / f / "in_the_way");
  }
  std::vector<std::string> warnings;
  const StintResult r = SolveStint(*car_, *track_, o, [&](const std::string& line) {
    if (line.rfind("warning:", 0) == 0) warnings.push_back(line);
  });
  ASSERT_TRUE(r.ok()) << r.run.solution.solve.message;
  EXPECT_EQ(r.greedy_laps_resumed, 0);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("greedy_lap_1.bin"), std::string::npos) << warnings[0];
}

}  // namespace
}  // namespace hotlap::ocp
