#include "hotlap/sim/qss_lap.h"

#include "hotlap/sim/hot_pressure.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/sim/hot_pressure.h"
#include "hotlap/sim/qss_profile.h"
#include "hotlap/sim/qss_slips.h"
#include "qss_test_roads.h"
#include "test_util.h"

namespace hotlap::sim {
namespace {

using testing::Circle;
using testing::Oval;

const vehicle::Car& Gen7() {
  static const vehicle::Car car = vehicle::LoadCar(test::Gen7Dir() / "car.yaml");
  return car;
}

QssOptions Options(int laps = 1) {
  const vehicle::Car& car = Gen7();
  QssOptions o;
  o.laps = laps;
  o.ambient_temp = CelsiusToKelvin(25.0);
  o.track_temp = CelsiusToKelvin(40.0);
  for (int k = 0; k < 4; ++k) {
    o.initial.tyres[k] = CarStartState(car).tyres[k];
    o.initial.brakes[k] = CarStartState(car).brakes[k];
  }
  return o;
}

double SumAt(const std::array<CornerChannels, 4>& c, std::vector<double> CornerChannels::*ch,
             size_t i) {
  double s = 0.0;
  for (const CornerChannels& x : c) s += (x.*ch)[i];
  return s;
}

// Flat circle: constant speed at the cornering limit; the tyres' lateral forces balance
// m V^2 kappa (acceptance), the loads sum to m g + downforce, the lap time is 2 pi R / V.
TEST(QssLapTest, FlatCircleBalancesCentripetalForce) {
  const vehicle::Car& car = Gen7();
  const auto road = Circle(150.0, 0.0);
  QssOptions o = Options();
  o.couple_first_lap = false;
  const QssResult r = RunQssLap(car, road, o);
  const QssLap& lap = r.laps.at(0);
  const double m = car.vehicle->chassis.mass;
  const double v = lap.speed[0];
  EXPECT_EQ(lap.slip_points_not_reached, 0);
  for (size_t i = 0; i < road.size(); i += 37) {
    // The same speed to the cornering limit's tolerance: each point's drag coefficient is its own
    // slip solve's, the first point's from a solve afresh (9e-5 m/s off), the others' continued
    // from it (alike to 1e-7 m/s).
    EXPECT_NEAR(lap.speed[i], v, 1e-3);
    if (i > 0) {
      EXPECT_NEAR(lap.speed[i], lap.speed[37], 1e-6);
    }
    EXPECT_EQ(lap.limit[i], SpeedLimit::kCornering);
    const double vi = lap.speed[i];
    EXPECT_NEAR(SumAt(lap.corners, &CornerChannels::fy, i), m * vi * vi / 150.0, 5.0);
    const double down =
        0.5 * car.vehicle->aero.air_density * car.vehicle->aero.downforce_area * vi * vi;
    EXPECT_NEAR(SumAt(lap.corners, &CornerChannels::fz, i), m * kGravity + down, 1e-6 * m);
  }
  EXPECT_NEAR(lap.lap_time, road.size() * (road[1].distance - road[0].distance) / v, 1e-4);
  // At the limit: some tyre is at its ellipse (utilisation 1 within the bisection), and 1 m/s
  // faster is infeasible. (The lap's vehicle: its gas-and-rim tyres' force models at the start's
  // hot pressures, sim/hot_pressure.h.)
  const vehicle::Car hot = WithHotPressures(car, HotPressuresAt(car, o.initial, 50.0));
  const QssVehicle q(*hot.vehicle);
  std::array<double, 4> grip;
  for (int k = 0; k < 4; ++k) {
    grip[k] = car.tyre(kAllCorners[k]).compound->GripFactor(o.initial.tyres[k].tread_temp, 0.0);
  }
  std::array<double, 4> fy, alpha;
  for (int k = 0; k < 4; ++k) {
    fy[k] = lap.corners[k].fy[0];
    alpha[k] = lap.corners[k].slip_angle[0];
  }
  const double k_drag = CalcCorneringDragCoefficient(fy, alpha);
  const double drag = CalcResistance(q, road[0], v, k_drag);
  EXPECT_NEAR(CalcForceDemand(q, road[0], v, drag, grip).max_utilization, 1.0, 1e-3);
  EXPECT_FALSE(
      CalcForceDemand(q, road[0], v + 1.0, CalcResistance(q, road[0], v + 1.0, k_drag), grip)
          .Feasible());
  // Holding its speed, the tyres' drive is the aerodynamic drag, the rolling resistance and the
  // cornering drag: the lateral forces of tyres at a slip angle, -Fy sin(alpha) each, against
  // the motion (to the shortfall the profile's settling leaves, 1 mm/s).
  double cornering_drag = 0.0;
  for (int k = 0; k < 4; ++k) cornering_drag -= fy[k] * std::sin(alpha[k]);
  EXPECT_GT(cornering_drag, 500.0);  // about 4 degrees of slip on 17 kN of lateral force
  EXPECT_NEAR(SumAt(lap.corners, &CornerChannels::fx, 0),
              CalcResistance(q, road[0], v) + cornering_drag, 5.0);
  EXPECT_NEAR(CalcResistance(q, road[0], v, k_drag), CalcResistance(q, road[0], v) + cornering_drag,
              1e-3 * cornering_drag);  // the tyres' sum of Fy against m V^2 kappa
}

// Left out (one profile), the cornering drag makes the same circle faster: the tyres have its
// share of their ellipses for the lateral force.
TEST(QssLapTest, CorneringDragSlowsTheCircle) {
  const vehicle::Car& car = Gen7();
  const auto road = Circle(150.0, 0.0);
  QssOptions o = Options();
  o.couple_first_lap = false;
  const double with = RunQssLap(car, road, o).laps.at(0).speed[0];
  o.max_drag_passes = 1;
  const QssLap without = RunQssLap(car, road, o).laps.at(0);
  EXPECT_GT(without.speed[0], with + 0.05);
  const vehicle::Car hot = WithHotPressures(car, HotPressuresAt(car, o.initial, 50.0));
  EXPECT_NEAR(SumAt(without.corners, &CornerChannels::fx, 0),
              CalcResistance(QssVehicle(*hot.vehicle), road[0], without.speed[0]), 5.0);
}

// The cornering drag's fixed point, worked out here from the public parts with every profile
// searched from scratch and every slip solved (no searches started from the last profile's, no
// slips updated from the last solve's), until the speeds stop moving: the lap is that one, to
// the settling tolerance (0.5 ms); left out, the lap is far off.
TEST(QssLapTest, DragFixedPointIsTheOneOfProfilesFromScratch) {
  const vehicle::Car& car = Gen7();
  const auto road = Oval(400.0, 150.0, 60.0);
  QssOptions o = Options();
  o.couple_first_lap = false;
  const QssLap lap = RunQssLap(car, road, o).laps.at(0);
  // The same lap by hand: the tyres at the start's hot pressures, grip and tread temperatures.
  const vehicle::Car hot = WithHotPressures(car, HotPressuresAt(car, o.initial, 50.0));
  const vehicle::VehicleParams& p = *hot.vehicle;
  const QssVehicle q(p);
  std::vector<vehicle::InvertibleTyre> tyres;
  for (Corner c : kAllCorners) tyres.emplace_back(p.corner(c));
  std::array<std::vector<double>, 4> grip;
  for (int k = 0; k < 4; ++k) {
    grip[k].assign(
        road.size(),
        car.tyre(kAllCorners[k]).compound->GripFactor(o.initial.tyres[k].tread_temp, 0.0));
  }
  const size_t n = road.size();
  const double ds = road[1].distance - road[0].distance;
  std::vector<double> drag(n, 0.0);
  SpeedProfile profile;
  for (int pass = 0; pass < 10; ++pass) {
    profile = CalcSpeedProfile(q, road, grip, drag);
    PointSlips last;
    for (size_t i = 0; i < n; ++i) {
      const double v = profile.speed[i];
      const double v_prev = profile.speed[(i + n - 1) % n], v_next = profile.speed[(i + 1) % n];
      const double accel = (v_next * v_next - v_prev * v_prev) / (4.0 * ds);
      const std::array<double, 4> g = {grip[0][i], grip[1][i], grip[2][i], grip[3][i]};
      const double sum_fx = p.chassis.mass * accel + CalcResistance(q, road[i], v, drag[i]);
      const ForceDemand d = CalcForceDemand(q, road[i], v, sum_fx, g);
      const double yaw_rate = v * road[i].curvature * std::cos(road[i].bank);
      PointTargets t;
      for (Corner c : kAllCorners) {
        const int k = CornerIndex(c);
        t.conditions[k] = {std::max(d.fz[k], 1.0),
                           std::max(v - yaw_rate * p.CornerPosition(c)[1], 0.5),
                           o.initial.tyres[k].tread_temp, g[k]};
        t.fx[k] = d.fx[k];
        t.fy[k] = d.fy[k];
      }
      last = SolvePointSlips(tyres, t, last);
      const auto& w = last.wheels;
      drag[i] = CalcCorneringDragCoefficient(
          {w[0].fy, w[1].fy, w[2].fy, w[3].fy},
          {w[0].slip_angle, w[1].slip_angle, w[2].slip_angle, w[3].slip_angle});
    }
  }
  double lap_time = 0.0, moved = 0.0;
  for (size_t i = 0; i < n; ++i) {
    lap_time += 2.0 * ds / (profile.speed[i] + profile.speed[(i + 1) % n]);
    moved += std::abs(lap.speed[i] - profile.speed[i]);
  }
  EXPECT_NEAR(lap.lap_time, lap_time, 5e-4);
  EXPECT_LT(moved / static_cast<double>(n), 3e-3);
  o.max_drag_passes = 1;
  EXPECT_GT(lap_time - RunQssLap(car, road, o).laps.at(0).lap_time, 0.05);
}

// Banked circle: the tyres make exactly what banking does not (spec section 10), and banking
// lets the car go faster than on the flat.
TEST(QssLapTest, BankedCircleTyresMakeWhatBankingDoesNot) {
  const vehicle::Car& car = Gen7();
  QssOptions o = Options();
  o.couple_first_lap = false;
  const double bank = DegToRad(24.0), radius = 170.0;
  const QssLap banked = RunQssLap(car, Circle(radius, 24.0), o).laps.at(0);
  const QssLap flat = RunQssLap(car, Circle(radius, 0.0), o).laps.at(0);
  const double m = car.vehicle->chassis.mass;
  const double v = banked.speed[0];
  const double needed = m * (v * v * std::cos(bank) / radius - kGravity * std::sin(bank));
  EXPECT_NEAR(SumAt(banked.corners, &CornerChannels::fy, 10), needed, 5.0);
  EXPECT_GT(v, flat.speed[0] + 5.0);
}

// An oval: braking zones before each turn, traction or power limited on the way out, the right
// side loaded, a closed lap whose times add up.
TEST(QssLapTest, OvalHasBrakingZonesAtTurnEntries) {
  const vehicle::Car& car = Gen7();
  const auto road = Oval(400.0, 170.0, 150.0);
  const QssLap lap = RunQssLap(car, road, Options()).laps.at(0);
  const size_t n = road.size();
  // Entry of turn 1 at 400 m, of turn 3 half a lap later.
  const double half = 0.5 * road.size() * (road[1].distance - road[0].distance);
  for (double entry : {400.0, 400.0 + half}) {
    bool braking_before = false;
    for (size_t i = 0; i < n; ++i) {
      const double d = road[i].distance;
      if (d > entry - 300.0 && d < entry + 100.0 && lap.limit[i] == SpeedLimit::kBraking) {
        braking_before = true;
      }
    }
    EXPECT_TRUE(braking_before) << entry;
  }
  const auto [vmin, vmax] = std::minmax_element(lap.speed.begin(), lap.speed.end());
  EXPECT_GT(*vmax - *vmin, 3.0);
  // Right side carries more load in the turns.
  const size_t apex = static_cast<size_t>(
      std::round((400.0 + 150.0 + 100.0) / (road[1].distance - road[0].distance)));
  EXPECT_GT(lap.corners[1].fz[apex], 1.5 * lap.corners[0].fz[apex]);
  EXPECT_GT(lap.corners[3].fz[apex], 1.3 * lap.corners[2].fz[apex]);
  // Time is the integral of ds / V.
  double t = 0.0;
  for (size_t i = 0; i < n; ++i) {
    t +=
        (road[1].distance - road[0].distance) * 0.5 * (1.0 / lap.speed[i] + 1.0 / lap.speed[i + 1]);
  }
  EXPECT_NEAR(lap.lap_time, t, 1e-3 * t);
  EXPECT_LE(lap.slip_points_not_reached, static_cast<int>(n / 100));
  // Braking heats the front discs above where they started.
  const auto& disc = lap.thermal.corners[0].disc_temp;
  EXPECT_GT(*std::max_element(disc.begin(), disc.end()), Options().initial.brakes[0].disc_temp);
}

// A stint carries the thermal state from lap to lap and wear accumulates.
TEST(QssLapTest, StintCarriesTheThermalStateOver) {
  const vehicle::Car& car = Gen7();
  const auto road = Oval(400.0, 170.0, 150.0);
  const QssResult r = RunQssLap(car, road, Options(3));
  ASSERT_EQ(r.laps.size(), 3u);
  for (int lap = 1; lap < 3; ++lap) {
    for (int k = 0; k < 4; ++k) {
      const CornerHistory& before = r.laps[lap - 1].thermal.corners[k];
      const CornerHistory& after = r.laps[lap].thermal.corners[k];
      EXPECT_DOUBLE_EQ(after.tread_temp.front(), before.tread_temp.back());
      EXPECT_DOUBLE_EQ(after.disc_temp.front(), before.disc_temp.back());
      EXPECT_DOUBLE_EQ(after.wear.front(), before.wear.back());
      EXPECT_GT(after.wear.back(), before.wear.back());
    }
  }
}

TEST(QssLapTest, BadInputIsRejected) {
  const vehicle::Car& car = Gen7();
  std::vector<RoadPoint> few(10);
  for (int i = 0; i < 10; ++i) few[i].distance = i;
  EXPECT_THROW(RunQssLap(car, few, Options()), InputError);
  auto uneven = Circle(100.0, 0.0);
  uneven[5].distance += 0.3;
  EXPECT_THROW(RunQssLap(car, uneven, Options()), InputError);
  auto bad = Circle(100.0, 0.0);
  bad[7].curvature = std::nan("");
  EXPECT_THROW(RunQssLap(car, bad, Options()), InputError);
  EXPECT_THROW(RunQssLap(car, Circle(100.0, 0.0), Options(0)), InputError);
  auto thermal_only = car;
  thermal_only.vehicle.reset();
  EXPECT_THROW(RunQssLap(thermal_only, Circle(100.0, 0.0), Options()), InputError);
}

}  // namespace
}  // namespace hotlap::sim
