// The optimal lap with the car's own gas-and-rim tyres and surface-and-bulk discs: the rims and
// disc bulks are states of the programme, each tyre's rolling resistance its own function of
// carcass and gas, and the exact models replayed over the solution agree with it.

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/units.h"
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
