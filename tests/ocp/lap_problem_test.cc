// The lap problem's brakes that feed nothing back (ocp/lap_problem.h
// LapProblemOptions::all_brake_states): left out of the programme and integrated after the solve,
// they give the same solution as the programme that carries them, with fewer rows. Its wear left
// out likewise, its periodic lap, and the car's own gas-and-rim tyres and bulk discs as states.

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/units.h"
#include "hotlap/ocp/lap_problem.h"
#include "hotlap/ocp/optimal_lap.h"
#include "hotlap/track/track_io.h"
#include "test_util.h"

namespace hotlap::ocp {
namespace {

double MaxAbsDifference(const std::vector<double>& a, const std::vector<double>& b) {
  EXPECT_EQ(a.size(), b.size());
  double d = 0.0;
  for (size_t i = 0; i < std::min(a.size(), b.size()); ++i) d = std::max(d, std::abs(a[i] - b[i]));
  return d;
}

// The Darlington lap of these tests, the car and its warm-up (racing start, 25/40 degC).
struct TestLap {
  // The paper's models: their brakes feed nothing back (a gas-and-rim tyre's rim takes its brake's
  // heat, which keeps every brake in the programme).
  vehicle::Car car = vehicle::PaperModelsOf(vehicle::LoadCar(test::Gen7Dir() / "car.yaml"));
  track::Track track = track::LoadTrack("darlington");
  LapWarmUp warm_up;
  LapProblemOptions lap;

  // On 30 m, or with Hermite-Simpson on 60 m intervals (their midpoints nodes: as many nodes).
  explicit TestLap(Collocation collocation) {
    OptimalLapOptions o;
    o.ambient_temp = CelsiusToKelvin(25.0);
    o.track_temp = CelsiusToKelvin(40.0);
    warm_up = RunLapWarmUp(car, track, o);
    lap.collocation = collocation;
    lap.step_m = collocation == Collocation::kHermiteSimpson ? 60.0 : 30.0;
    lap.ambient_temp = o.ambient_temp;
    lap.track_temp = o.track_temp;
    lap.initial = warm_up.start;
  }
  LapSolution Solve(const IpoptOptions& ipopt = LapIpoptOptions()) const {
    return SolveMinimumTimeLap(car, track, lap, warm_up.guess, ipopt);
  }
  // Solved again from `from`'s point and multipliers (a warm start at a tiny barrier).
  LapSolution SolveFrom(const LapSolution& from) {
    lap.start_point = from.solve.x;
    IpoptOptions warm = LapIpoptOptions();
    warm.warm_z_lower = from.solve.z_lower;
    warm.warm_z_upper = from.solve.z_upper;
    warm.warm_lambda = from.solve.lambda;
    warm.warm_mu = 1e-9;
    return Solve(warm);
  }
};

class BrakesLeftOutTest : public ::testing::TestWithParam<std::tuple<bool, Collocation>> {};

// From the solution of the full programme (point and multipliers), the programme without the
// brakes that feed nothing back is already solved: Ipopt stops at once on the same lap, and the
// brakes integrated after the solve are the full programme's to the solver's tolerance. The full
// programme starts from a solved lap, the reduced programme's from the QSS guess (as the
// library's solves do): from the guess itself its solve is a lottery of local optima and
// iteration counts (the limited Hermite-Simpson lap has run into the iteration limit, the free
// lap has ended where the reduced programme moved its discs by 0.05 K).
TEST_P(BrakesLeftOutTest, SameSolutionAsTheFullProgramme) {
  const auto [limited, collocation] = GetParam();
  TestLap t(collocation);
  if (limited) t.lap.front_disc_limit = CelsiusToKelvin(500.0);
  // The wear in the programme every time (left out, it is frozen at each start point's: other
  // forces in the next solve; WearLeftOutTest).
  t.lap.wear_in_programme = true;
  const LapSolution from_guess = t.Solve();
  ASSERT_TRUE(from_guess.solve.ok()) << from_guess.solve.message;
  t.lap.all_brake_states = true;
  const LapSolution full = t.SolveFrom(from_guess);
  ASSERT_TRUE(full.solve.ok()) << full.solve.message;
  EXPECT_LE(full.solve.iterations, 5);  // the converse: the reduced solution solves the full one

  t.lap.all_brake_states = false;
  const LapSolution reduced = t.SolveFrom(full);
  ASSERT_TRUE(reduced.solve.ok()) << reduced.solve.message;

  // The same variables (the brakes left out are fixed ones), two rows fewer per interval and brake.
  const int brakes_left_out = limited ? 2 : 4;
  EXPECT_EQ(reduced.variables, full.variables);
  EXPECT_EQ(reduced.constraints, full.constraints - 2 * brakes_left_out * (full.layout.nodes - 1));
  EXPECT_EQ(reduced.layout.rows(), full.layout.rows());
  EXPECT_LE(reduced.solve.iterations, 5);
  EXPECT_NEAR(reduced.lap_time, full.lap_time, 5e-6);  // 1.5e-6 s seen, 2026-11-29
  // Every brake temperature, integrated or solved for, to well under a tenth of a kelvin (the
  // solver's tolerance on the full programme's defects is 1e-7 of 100 K; the discs have been
  // 0.014 K apart with the tuned wear, 2026-11-29).
  for (int c = 0; c < 4; ++c) {
    EXPECT_LT(MaxAbsDifference(reduced.corners[c].disc_temp, full.corners[c].disc_temp), 0.03) << c;
    EXPECT_LT(MaxAbsDifference(reduced.corners[c].calliper_temp, full.corners[c].calliper_temp),
              1e-3)
        << c;
  }
  // The integrated brakes heat up over the lap (they are not left at their guess or start).
  const std::vector<double>& rear = reduced.corners[CornerIndex(Corner::kRearLeft)].disc_temp;
  EXPECT_GT(*std::max_element(rear.begin(), rear.end()), rear.front() + 20.0);
  // The reduced solve's multipliers come back in the full layout, zero on the defects left out:
  // the full programme's are zero there too (a state that feeds nothing back has no costate).
  ASSERT_EQ(static_cast<int>(reduced.solve.lambda.size()), reduced.layout.rows());
  ASSERT_EQ(full.solve.lambda.size(), reduced.solve.lambda.size());
  const int defects = reduced.layout.nodes * reduced.layout.rows_per_node;
  const int per_interval = reduced.layout.defects_per_interval;
  double largest = 0.0;
  for (int k = 0; k + 1 < reduced.layout.nodes; ++k) {
    for (const int j : {3, 4}) {  // disc, calliper
      const int row = defects + k * per_interval + 5 + 5 * CornerIndex(Corner::kRearLeft) + j;
      EXPECT_EQ(reduced.solve.lambda[row], 0.0);
      largest = std::max(largest, std::abs(full.solve.lambda[row]));
    }
  }
  EXPECT_LT(largest, 1e-6);
}

INSTANTIATE_TEST_SUITE_P(
    FreeAndLimited, BrakesLeftOutTest,
    ::testing::Combine(::testing::Bool(),
                       ::testing::Values(Collocation::kTrapezoid, Collocation::kHermiteSimpson)),
    [](const auto& info) {
      return std::string(std::get<0>(info.param) ? "Limited" : "Free") +
             (std::get<1>(info.param) == Collocation::kHermiteSimpson ? "HermiteSimpson" : "");
    });

class WearLeftOutTest : public ::testing::TestWithParam<Collocation> {};

// The wear left out of the programme (LapProblemOptions::wear_in_programme false) is frozen for
// the forces at the start point's and integrated after the solve. From the full programme's
// solution, whose wear it then freezes, the reduced programme is solved within a few iterations
// on the same lap, and its integrated wear is the full programme's to a few per cent: the wear's
// costates, which it drops, move the sliding a little (with the tuned wear, 0.1 mm a lap at the
// right rear, 1.9 um apart and h 2.3e-4, 2026-11-29).
TEST_P(WearLeftOutTest, SameLapAndWearAsTheFullProgramme) {
  TestLap t(GetParam());
  t.lap.wear_in_programme = true;
  const LapSolution full = t.Solve();
  ASSERT_TRUE(full.solve.ok()) << full.solve.message;
  EXPECT_EQ(full.frozen_wear_grip_difference, 0.0);

  t.lap.wear_in_programme = false;
  const LapSolution reduced = t.SolveFrom(full);
  ASSERT_TRUE(reduced.solve.ok()) << reduced.solve.message;

  // The same variables (the wear is fixed ones), one defect fewer per tyre and interval.
  EXPECT_EQ(reduced.variables, full.variables);
  EXPECT_EQ(reduced.constraints, full.constraints - 4 * (full.layout.nodes - 1));
  EXPECT_EQ(reduced.layout.rows(), full.layout.rows());
  EXPECT_LE(reduced.solve.iterations, 10);
  // Without the wear's costates the driver does not see the grip a lap's wear takes: half a
  // millisecond faster with the tuned wear (0.51 and 0.57 ms, 2026-11-29).
  EXPECT_NEAR(reduced.lap_time, full.lap_time, 1.5e-3);
  EXPECT_LE(reduced.lap_time, full.lap_time + 1e-6);
  for (int c = 0; c < 4; ++c) {
    const std::vector<double>& wear = reduced.corners[c].wear;
    // Integrated from the start's wear, and rising over the lap.
    EXPECT_EQ(wear.front(), t.warm_up.start.tyres[c].wear) << c;
    EXPECT_GT(wear.back(), wear.front() + 1e-4) << c;
    const double lap_wear = full.corners[c].wear.back() - full.corners[c].wear.front();
    EXPECT_LT(MaxAbsDifference(wear, full.corners[c].wear), 0.05 * lap_wear) << c;
  }
  // Frozen at the full programme's wear: h barely differs from the integrated wear's.
  EXPECT_GT(reduced.frozen_wear_grip_difference, 0.0);
  EXPECT_LT(reduced.frozen_wear_grip_difference, 1e-3);
  // A start whose wear began elsewhere (a lap saved from another start) is frozen at its wear
  // gained along the lap, from this lap's start: the same lap and grip (h moves 0.06 over the first
  // 0.5 mm).
  std::vector<double> worn = full.solve.x;
  for (int k = 0; k < full.layout.nodes; ++k) {
    for (int c = 0; c < 4; ++c) worn[k * full.layout.vars_per_node + 5 + 5 * c + 2] += 0.5;
  }
  LapSolution shifted = full;
  shifted.solve.x = worn;
  const LapSolution from_worn = t.SolveFrom(shifted);
  ASSERT_TRUE(from_worn.solve.ok()) << from_worn.solve.message;
  EXPECT_NEAR(from_worn.lap_time, reduced.lap_time, 1e-6);
  EXPECT_LT(from_worn.frozen_wear_grip_difference, 1e-3);
  for (int c = 0; c < 4; ++c) {
    EXPECT_LT(MaxAbsDifference(from_worn.corners[c].wear, reduced.corners[c].wear), 1e-9) << c;
  }
  // The reduced solve's multipliers come back in the full layout, zero on the wear's defects.
  ASSERT_EQ(static_cast<int>(reduced.solve.lambda.size()), reduced.layout.rows());
  const int defects = reduced.layout.nodes * reduced.layout.rows_per_node;
  for (int k = 0; k + 1 < reduced.layout.nodes; ++k) {
    for (int c = 0; c < 4; ++c) {
      const int row = defects + k * reduced.layout.defects_per_interval + 5 + 5 * c + 2;
      EXPECT_EQ(reduced.solve.lambda[row], 0.0);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(BothCollocations, WearLeftOutTest,
                         ::testing::Values(Collocation::kTrapezoid, Collocation::kHermiteSimpson),
                         [](const auto& info) {
                           return std::string(info.param == Collocation::kHermiteSimpson
                                                  ? "HermiteSimpson"
                                                  : "Trapezoid");
                         });

// A periodic lap closes its temperatures, not its wear: the wear only grows (it was once closed
// too, which no lap can do: the solve ended locally infeasible).
TEST(PeriodicLapTest, ClosesTheTemperaturesNotTheWear) {
  const vehicle::Car car = vehicle::LoadCar(test::Gen7Dir() / "car.yaml");
  const track::Track track = track::LoadTrack("darlington");
  OptimalLapOptions o;
  o.step_m = 30.0;
  o.coarse_step_m = 0.0;
  o.thermal_start = ThermalStart::kPeriodic;
  o.ambient_temp = CelsiusToKelvin(25.0);
  o.track_temp = CelsiusToKelvin(40.0);
  const OptimalLapRun run = RunOptimalLap(car, track, o);
  const LapSolution& s = run.solution;
  ASSERT_TRUE(s.solve.ok()) << s.solve.message;
  for (int c = 0; c < 4; ++c) {
    const CornerTrace& t = s.corners[c];
    // The car's gas-and-rim tyres and bulk discs: their rims and bulks close too.
    ASSERT_FALSE(t.rim_temp.empty());
    ASSERT_FALSE(t.disc_bulk_temp.empty());
    for (const std::vector<double>* v : {&t.tread_temp, &t.carcass_temp, &t.disc_temp,
                                         &t.calliper_temp, &t.rim_temp, &t.disc_bulk_temp}) {
      EXPECT_NEAR(v->back(), v->front(), 1e-4) << c;
    }
    EXPECT_EQ(t.wear.front(), run.start.tyres[c].wear) << c;
    EXPECT_GT(t.wear.back(), t.wear.front() + 1e-4) << c;
  }
  // The thermal steady state of this car is hot (tread peaks 133-151 degC, well past the grip
  // optimum of 98 degC): about 31.0 s on 30 m against 29.67 s from the racing start.
  EXPECT_GT(s.lap_time, 29.67);
  EXPECT_LT(s.lap_time, 32.0);
}

// The optimal lap with the car's own gas-and-rim tyres and surface-and-bulk discs: the rims and
// disc bulks are states of the programme, each tyre's rolling resistance its own function of
// carcass and gas, and the exact models replayed over the solution agree with it.

// The time integral of a node channel by the trapezoid.
double Integral(const std::vector<double>& time, const std::vector<double>& values) {
  double sum = 0.0;
  for (size_t k = 0; k + 1 < time.size(); ++k) {
    sum += 0.5 * (values[k] + values[k + 1]) * (time[k + 1] - time[k]);
  }
  return sum;
}

TEST(LapWheelStatesTest, RimsBulksAndRollingResistanceAreTheExactModels) {
  const vehicle::Car car = vehicle::LoadCar(test::Gen7Dir() / "car.yaml");
  const track::Track track = track::LoadTrack("darlington");
  OptimalLapOptions o;
  o.step_m = 30.0;
  o.coarse_step_m = 0.0;
  o.ambient_temp = CelsiusToKelvin(25.0);
  o.track_temp = CelsiusToKelvin(40.0);
  const OptimalLapRun run = RunOptimalLap(car, track, o);
  const LapSolution& s = run.solution;
  ASSERT_TRUE(s.solve.ok()) << s.solve.message;
  ASSERT_EQ(run.exact.audits.size(), 1u);
  const size_t n = s.time.size();
  for (int c = 0; c < 4; ++c) {
    const CornerTrace& t = s.corners[c];
    const sim::CornerHistory& exact = run.exact.corners[c];
    ASSERT_EQ(t.rim_temp.size(), n) << c;
    ASSERT_EQ(t.disc_bulk_temp.size(), n) << c;
    ASSERT_EQ(t.pressure.size(), n) << c;
    // States of the programme: they move over the lap (a bulk takes its surface's heat after a
    // stop and gives it to the vanes' air).
    EXPECT_NE(t.rim_temp.back(), t.rim_temp.front()) << c;
    const auto [lo, hi] = std::minmax_element(t.disc_bulk_temp.begin(), t.disc_bulk_temp.end());
    EXPECT_GT(*hi - *lo, 2.0) << c;
    // The exact models (RK4 over the solution's channels) within the collocation's error on 30 m.
    EXPECT_LT(MaxAbsDifference(t.rim_temp, exact.rim_temp), 0.5) << c;
    EXPECT_LT(MaxAbsDifference(t.disc_bulk_temp, exact.disc_bulk_temp), 3.0) << c;
    EXPECT_LT(MaxAbsDifference(t.gas_temp, exact.gas_temp), 1.0) << c;
    EXPECT_LT(MaxAbsDifference(t.pressure, exact.pressure), 500.0) << c;  // Pa
    // The rolling resistance the programme's car paid, u c_rr Fz over the lap, is the work the
    // tyre's thermal model books as hysteresis heat (the audit's rolling work, exact replay).
    std::vector<double> rolling_power(n);
    for (size_t k = 0; k < n; ++k)
      rolling_power[k] = t.speed[k] * t.rolling_resistance[k] * t.fz[k];
    const sim::CornerEnergyAudit& audit = run.exact.audits[0][c];
    EXPECT_NEAR(Integral(s.time, rolling_power), audit.tyre[sim::kRollingWork],
                0.01 * audit.tyre[sim::kRollingWork])
        << c;
    // A gas-and-rim tyre's coefficient is its own, not the force model's QSY1 (0.008).
    EXPECT_GT(t.rolling_resistance.front(), 0.002) << c;
    EXPECT_LT(t.rolling_resistance.front(), 0.03) << c;
    // The audit of the lap closes and no tyre makes more heat than the car's work on it.
    EXPECT_LT(std::abs(audit.TyreClosure()), 1e-9) << c;
    EXPECT_LT(std::abs(audit.RimClosure()), 1e-9) << c;
    EXPECT_LT(std::abs(audit.BrakeClosure()), 1e-9) << c;
    EXPECT_LE(audit.HeatOverWork(), 1.0) << c;
  }
}

}  // namespace
}  // namespace hotlap::ocp
