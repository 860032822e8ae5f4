// The disc-limit comparison as a library call (ocp/disc_limit_comparison.h), on Darlington with a
// coarse 20 m mesh (solves of about 3,000 variables, about ten seconds each): the limit holds,
// binds, costs time, and the limited lap starts from the free one.

#include "hotlap/ocp/disc_limit_comparison.h"

#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/track/track_io.h"
#include "test_util.h"

namespace hotlap::ocp {
namespace {

OptimalLapOptions Coarse() {
  OptimalLapOptions o;
  o.step_m = 20.0;
  o.ambient_temp = CelsiusToKelvin(25.0);
  o.track_temp = CelsiusToKelvin(40.0);
  return o;
}

double PeakFrontLeftDisc(const SolvedLap& s) {
  const std::vector<double>& t = s.run.solution.corners[CornerIndex(Corner::kFrontLeft)].disc_temp;
  return *std::max_element(t.begin(), t.end());
}

TEST(DiscLimitComparisonTest, LimitHoldsBindsAndCostsTime) {
  const vehicle::Car car = vehicle::LoadCar(test::Gen7Dir() / "car.yaml");
  const track::Track track = track::LoadTrack("darlington");
  const double limit = CelsiusToKelvin(480.0);
  std::vector<std::string> lines;
  int iterations = 0;
  const DiscLimitComparison c = CompareDiscLimit(
      car, track, Coarse(), limit,
      [&](const std::string&, int, double, double, double) {
        ++iterations;
        return true;
      },
      [&](const std::string& line) { lines.push_back(line); });
  ASSERT_TRUE(c.converged()) << c.free.run.solution.solve.message << " / "
                             << c.limited.run.solution.solve.message;
  // The free lap's front-left disc goes above the limit (it binds), the limited one's does not.
  EXPECT_GT(PeakFrontLeftDisc(c.free), limit + 5.0);
  EXPECT_LE(PeakFrontLeftDisc(c.limited), limit + 1e-3);
  EXPECT_FALSE(c.free.front_disc_limit.has_value());
  ASSERT_TRUE(c.limited.front_disc_limit.has_value());
  EXPECT_DOUBLE_EQ(*c.limited.front_disc_limit, limit);
  // The limit costs time: the limited lap is slower than the free one by more than the few
  // milliseconds between two local optima, and the free solve found its lap by itself. (The
  // comparison keeps the better of the free lap and a free solve from the limited lap, so
  // delta_s() >= 0 holds by construction: checked alone it could not fail.)
  EXPECT_FALSE(c.free_solved_again) << "the free solve stopped at a worse local optimum";
  EXPECT_GT(c.delta_s(), 0.01) << "the limit costs no time";
  EXPECT_NEAR(c.delta_s(), c.limited.run.solution.lap_time - c.free.run.solution.lap_time, 1e-12);
  // Warm-started from the free lap, the limited one takes fewer iterations than the same
  // problem from the QSS guess, and lands on the same lap. Straight from the guess on this 20 m
  // mesh the limited solve is a rounding lottery: it converged until 2026-11-27; with the tyres'
  // cornering drag it nears the lap (29.72 s by iteration 70) and then wanders off to the
  // iteration limit, which is why the comparison starts the limited lap from the free one. From
  // the guess coarse to fine (a 40 m solve first) it converges, so both checks are made always.
  OptimalLapOptions cold = Coarse();
  cold.front_disc_limit = limit;
  cold.coarse_step_m = 40.0;
  const SolvedLap from_guess = SolveLap(car, track, cold, "from the guess");
  ASSERT_TRUE(from_guess.run.coarse.ok()) << from_guess.run.coarse.message;
  ASSERT_TRUE(from_guess.run.solution.solve.ok()) << from_guess.run.solution.solve.message;
  EXPECT_LT(c.limited.run.solution.solve.iterations,
            from_guess.run.coarse.iterations + from_guess.run.solution.solve.iterations);
  // The same lap within the spread of this mesh's local optima: under 10 ms with the paper's
  // models; with the gas-and-rim tyres and bulk discs 26 ms has been seen (29.852 s from the free
  // lap, 29.826 s from the guess, with assumed pressure terms in the .tir files, 2026-11-29): a
  // cost measured on 20 m is good to a few tens of milliseconds.
  EXPECT_NEAR(c.limited.run.solution.lap_time, from_guess.run.solution.lap_time, 0.03);
  // Progress came for every iteration of every solve; the log names both solves.
  EXPECT_GE(iterations,
            c.free.run.solution.solve.iterations + c.limited.run.solution.solve.iterations);
  ASSERT_GE(lines.size(), 4u);
  EXPECT_TRUE(test::Contains(lines[0], "no limit: solving (20.0 m mesh)"));
  EXPECT_TRUE(test::Contains(lines[2], "discs <= 480 degC: solving"));
  EXPECT_TRUE(test::Contains(lines[2], "from the other solution"));
  // Figures and turn approaches come with each lap: no brake work against the engine.
  for (const SolvedLap* s : {&c.free, &c.limited}) {
    EXPECT_GT(s->figures.brake_energy_J, 1e5);
    EXPECT_LT(s->figures.brake_energy_under_drive_J, 0.005 * s->figures.brake_energy_J);
    EXPECT_EQ(s->approaches.size(), 2u);
  }
}

TEST(DiscLimitComparisonTest, ProgressCanStopASolve) {
  const vehicle::Car car = vehicle::LoadCar(test::Gen7Dir() / "car.yaml");
  const track::Track track = track::LoadTrack("darlington");
  const SolvedLap s = SolveLap(car, track, Coarse(), "stopped", nullptr,
                               [](const std::string& label, int it, double, double, double) {
                                 EXPECT_EQ(label, "stopped");
                                 return it < 3;
                               });
  EXPECT_FALSE(s.run.solution.solve.ok());
  EXPECT_TRUE(test::Contains(s.run.solution.solve.message, "stopped on request"));
  EXPECT_LE(s.run.solution.solve.iterations, 4);
}

TEST(DiscLimitComparisonTest, LimitBelowTheStartingDiscIsBadInput) {
  const vehicle::Car car = vehicle::LoadCar(test::Gen7Dir() / "car.yaml");
  const track::Track track = track::LoadTrack("darlington");
  // The racing start carries the front-left disc at about 400 degC into the lap: refused before
  // any solve starts (nothing logged), naming the disc and both temperatures.
  std::vector<std::string> lines;
  try {
    CompareDiscLimit(car, track, Coarse(), CelsiusToKelvin(300.0), {},
                     [&](const std::string& line) { lines.push_back(line); });
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_TRUE(test::Contains(e.what(), "the fl disc starts at"));
    EXPECT_TRUE(test::Contains(e.what(), "above the 300 degC limit"));
  }
  EXPECT_TRUE(lines.empty());
}

// Coarse to fine, the limited lap is solved in a child process beside the free one's fine solve,
// starting from the free coarse solution: the same
// laps as solving it afterwards in this process, bit for bit (the fine solve's MUMPS ordering,
// SCOTCH's, is reproducible on one thread, which SolveWithIpopt sets; on several its laps
// differed by 1e-14 relative between processes).
TEST(DiscLimitComparisonTest, SecondProcessGivesTheSameLaps) {
  const vehicle::Car car = vehicle::LoadCar(test::Gen7Dir() / "car.yaml");
  const track::Track track = track::LoadTrack("darlington");
  OptimalLapOptions o = Coarse();
  // 20 m from 40 m. On 30 m from 60 m with the tuned wear (2026-11-29) the limited lap from the
  // free lap's coarse solve settled 0.64 s slower than from the QSS guess (30.52 against 29.88 s
  // with the wear in the programme; from the guess with it frozen, a 43.3 s lap): local optima
  // of so coarse a mesh, which the main job's 3 m from 15 m solves do not meet.
  o.step_m = 20.0;
  o.coarse_step_m = 40.0;
  std::vector<std::string> lines;
  const auto log = [&](const std::string& line) { lines.push_back(line); };
  const DiscLimitComparison two = CompareDiscLimit(car, track, o, CelsiusToKelvin(480.0), {}, log);
  // The child starts once the free coarse solve has ended, its coarse solve from that one's.
  ASSERT_GE(lines.size(), 3u);
  EXPECT_TRUE(test::Contains(lines[0], "no limit: solving"));
  EXPECT_TRUE(test::Contains(lines[1], "discs <= 480 degC: solving in a second process"));
  EXPECT_TRUE(test::Contains(lines[1], "its coarse solve from this one's"));
  EXPECT_TRUE(test::Contains(lines[2], "no limit: coarse solve"));
  EXPECT_TRUE(two.limited_in_second_process);
  o.second_process = false;
  lines.clear();
  const DiscLimitComparison one = CompareDiscLimit(car, track, o, CelsiusToKelvin(480.0), {}, log);
  EXPECT_TRUE(std::any_of(lines.begin(), lines.end(), [](const std::string& l) {
    return test::Contains(l, "discs <= 480 degC: solving (20.0 m mesh") &&
           test::Contains(l, "the coarse solve from the other lap's");
  }));
  EXPECT_FALSE(one.limited_in_second_process);
  ASSERT_TRUE(two.converged() && one.converged());
  EXPECT_EQ(two.limited.run.solution.lap_time, one.limited.run.solution.lap_time);
  EXPECT_EQ(two.limited.run.solution.solve.iterations, one.limited.run.solution.solve.iterations);
  EXPECT_EQ(two.limited.run.coarse.iterations, one.limited.run.coarse.iterations);
  EXPECT_GT(two.limited.run.coarse.iterations, 0);
  const std::vector<double>& disc2 = two.limited.run.solution.corners[0].disc_temp;
  const std::vector<double>& disc1 = one.limited.run.solution.corners[0].disc_temp;
  ASSERT_EQ(disc2.size(), disc1.size());
  for (size_t k = 0; k < disc1.size(); ++k) EXPECT_EQ(disc2[k], disc1[k]) << k;
  EXPECT_EQ(two.free.run.solution.lap_time, one.free.run.solution.lap_time);
  EXPECT_EQ(two.delta_s(), one.delta_s());
  // The limited coarse solve from the free one's takes fewer iterations than from the QSS guess,
  // to the same lap.
  OptimalLapOptions cold = o;
  cold.front_disc_limit = CelsiusToKelvin(480.0);
  const SolvedLap from_guess = SolveLap(car, track, cold, "from the guess");
  ASSERT_TRUE(from_guess.run.coarse.ok());
  EXPECT_LT(one.limited.run.coarse.iterations, from_guess.run.coarse.iterations);
  EXPECT_NEAR(one.limited.run.solution.lap_time, from_guess.run.solution.lap_time, 0.01);
}

}  // namespace
}  // namespace hotlap::ocp
