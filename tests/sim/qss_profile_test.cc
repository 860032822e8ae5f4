#include "hotlap/sim/qss_profile.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/vehicle/car.h"
#include "qss_test_roads.h"
#include "test_util.h"

namespace hotlap::sim {
namespace {

const vehicle::Car& ProfileGen7() {
  static const vehicle::Car car = vehicle::LoadCar(test::Gen7Dir() / "car.yaml");
  return car;
}

// Cornering-drag coefficients of about the size the lap's tyres give (4 degrees of slip mid-turn),
// `scale` times, with a ripple so that no two neighbours move alike.
std::vector<double> Drag(const std::vector<RoadPoint>& road, double scale) {
  std::vector<double> drag(road.size());
  for (size_t i = 0; i < road.size(); ++i) {
    drag[i] = scale * (0.01 + 4.0 * road[i].curvature * (1.0 + 0.1 * std::sin(0.37 * i)));
  }
  return drag;
}

double LapTime(const std::vector<RoadPoint>& road, const SpeedProfile& p) {
  const size_t n = road.size();
  const double ds = road[1].distance - road[0].distance;
  double t = 0.0;
  for (size_t i = 0; i < n; ++i) t += 2.0 * ds / (p.speed[i] + p.speed[(i + 1) % n]);
  return t;
}

// The next profile of the drag's fixed point starts its searches from the last one's: it is the
// profile a search from scratch gives, to the searches' tolerances (1 mm/s on a cornering limit,
// 0.5 N on a drive or brake force), in a fraction of the force balances.
TEST(QssProfileTest, ProfileFromTheLastOneIsTheProfileFromScratch) {
  const QssVehicle car(*ProfileGen7().vehicle);
  const std::vector<RoadPoint> road = testing::Oval(400.0, 150.0, 60.0);
  std::array<std::vector<double>, 4> grip;
  for (auto& g : grip) g.assign(road.size(), 0.95);
  const SpeedProfile last = CalcSpeedProfile(car, road, grip, Drag(road, 1.0));
  for (const double scale : {1.003, 1.05, 0.8}) {
    const std::vector<double> drag = Drag(road, scale);
    const SpeedProfile fresh = CalcSpeedProfile(car, road, grip, drag);
    const SpeedProfile near = CalcSpeedProfile(car, road, grip, drag, {}, &last);
    double worst = 0.0;
    size_t other_limit = 0;
    for (size_t i = 0; i < road.size(); ++i) {
      worst = std::max(worst, std::abs(near.speed[i] - fresh.speed[i]));
      EXPECT_NEAR(near.cornering_limit[i], fresh.cornering_limit[i], 1e-3) << i;
      if (near.limit[i] != fresh.limit[i]) ++other_limit;
    }
    EXPECT_LT(worst, 2e-3) << scale;
    EXPECT_LE(other_limit, road.size() / 100) << scale;
    // A limit 1 mm/s low at every point would cost 0.5 ms here; the two laps agree far closer.
    EXPECT_NEAR(LapTime(road, near), LapTime(road, fresh), 1.5e-4) << scale;
    // The drag moved the lap: the comparison is not between two copies of the last profile.
    EXPECT_GT(std::abs(LapTime(road, fresh) - LapTime(road, last)), 1e-4) << scale;
  }
  // Nothing changed: every search keeps its answer, and the profile is the last one.
  const SpeedProfile same = CalcSpeedProfile(car, road, grip, Drag(road, 1.0), {}, &last);
  EXPECT_EQ(same.speed, last.speed);
}

// A search started from a nearby answer (LimitSearch) finds the same limit, and leaves its own.
TEST(QssProfileTest, LimitSearchFromANearbyAnswer) {
  const QssVehicle car(*ProfileGen7().vehicle);
  const std::vector<RoadPoint> road = testing::Circle(150.0, 12.0);
  const std::array<double, 4> grip = {0.95, 0.95, 0.95, 0.95};
  LimitSearch search;
  const double v0 = CalcCorneringLimit(car, road[0], grip, 0.05, -1.0, &search);
  EXPECT_EQ(search.value, v0);
  EXPECT_GT(search.slope, 0.0);
  for (const double drag : {0.051, 0.06, 0.03}) {
    LimitSearch from = search;
    const double near = CalcCorneringLimit(car, road[0], grip, drag, -1.0, &from);
    const double fresh = CalcCorneringLimit(car, road[0], grip, drag);
    EXPECT_NEAR(near, fresh, 1e-3) << drag;
    EXPECT_EQ(from.value, near);
  }
  LimitSearch brake;
  const double b0 = CalcMaxBrakeForce(car, road[0], 35.0, grip, &brake);
  for (const double speed : {35.2, 32.0}) {
    LimitSearch from = brake;
    EXPECT_NEAR(CalcMaxBrakeForce(car, road[0], speed, grip, &from),
                CalcMaxBrakeForce(car, road[0], speed, grip), 0.5)
        << speed;
  }
  EXPECT_GT(b0, 0.0);
}

}  // namespace
}  // namespace hotlap::sim
