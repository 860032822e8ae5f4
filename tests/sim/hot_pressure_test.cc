// The pressure that acts (sim/hot_pressure.h): each gas-and-rim tyre's force model and rolling
// radius at its hot pressure, and the hot pressures of a state and over a lap.

#include "hotlap/sim/hot_pressure.h"

#include <cmath>

#include <gtest/gtest.h>

#include "hotlap/common/units.h"
#include "hotlap/tyre/rolling_radius.h"
#include "hotlap/tyre/tyre_thermal.h"
#include "test_util.h"

namespace hotlap::sim {
namespace {

const vehicle::Car& Gen7() {
  static const vehicle::Car car = vehicle::LoadCar(test::Gen7Dir() / "car.yaml");
  return car;
}

TEST(HotPressureTest, OnlyTheGasAndRimTyresTakeTheirHotPressure) {
  const vehicle::Car& car = Gen7();
  const std::array<double, 4> hot = {190e3, 440e3, 205e3, 0.0};
  const vehicle::Car moved = WithHotPressures(car, hot);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(moved.vehicle->corners[c].pressure, hot[c]) << c;
  // No pressure given: the set-up's cold pressure stays.
  EXPECT_EQ(moved.vehicle->corners[3].pressure, car.vehicle->corners[3].pressure);
  EXPECT_EQ(moved.vehicle->corners[3].rolling_radius, car.vehicle->corners[3].rolling_radius);
  // The rollout as set grows by what the pressure changes in the .tir's effective rolling radius
  // at its nominal load: the soft left tyres most, so the rear stagger (right over left) shrinks.
  for (int c = 0; c < 3; ++c) {
    const vehicle::CornerSetup& cold = car.vehicle->corners[c];
    const auto& mf = std::get<tyre::MagicFormulaModel<double>>(cold.forces.params).params;
    EXPECT_DOUBLE_EQ(moved.vehicle->corners[c].rolling_radius - cold.rolling_radius,
                     tyre::CalcRollingRadiusChange(mf, mf.FNOMIN, cold.pressure, hot[c]))
        << c;
    EXPECT_GT(moved.vehicle->corners[c].rolling_radius, cold.rolling_radius + 0.5e-3) << c;
  }
  const auto rear_stagger = [](const vehicle::Car& x) {
    return x.vehicle->corners[3].rolling_radius - x.vehicle->corners[2].rolling_radius;
  };
  EXPECT_LT(rear_stagger(WithHotPressures(car, {0.0, 0.0, 205e3, 397e3})), rear_stagger(car));
  // The paper's tyres have no gas: their set-up is left alone.
  const vehicle::Car paper = vehicle::PaperModelsOf(car);
  const vehicle::Car same = WithHotPressures(paper, hot);
  for (int c = 0; c < 4; ++c) {
    EXPECT_EQ(same.vehicle->corners[c].pressure, paper.vehicle->corners[c].pressure) << c;
    EXPECT_EQ(same.vehicle->corners[c].rolling_radius, paper.vehicle->corners[c].rolling_radius);
  }
  EXPECT_EQ(HotPressuresAt(paper, CarStartState(paper), 50.0), (std::array<double, 4>{}));
}

TEST(HotPressureTest, AStateAndALapGiveTheGasModelsPressures) {
  const vehicle::Car& car = Gen7();
  ReplayInitialState s = CarStartState(car);
  s.tyres[0].carcass_temp = CelsiusToKelvin(110.0);
  s.tyres[0].rim_temp = CelsiusToKelvin(70.0);
  const std::array<double, 4> at = HotPressuresAt(car, s, 60.0);
  EXPECT_DOUBLE_EQ(at[0], tyre::CalcTyreGas(car.tyres[0].params, s.tyres[0].carcass_temp,
                                            s.tyres[0].rim_temp, 60.0)
                              .pressure);
  // Hot above the cold set (the front left at 20 psi cold).
  EXPECT_GT(at[0], car.vehicle->corners[0].pressure + 20e3);

  // The time-mean: the trapezoid in time over unevenly spaced samples, by hand.
  ReplayResult r;
  r.time = {0.0, 1.0, 3.0};
  for (int c = 0; c < 4; ++c) r.corners[c].pressure = {100e3, 200e3, 300e3};
  const std::array<double, 4> mean = MeanHotPressures(car, r);
  // (150e3 * 1 + 250e3 * 2) / 3
  for (int c = 0; c < 4; ++c) EXPECT_NEAR(mean[c], 650e3 / 3.0, 1e-6) << c;
  // The paper's tyres: none.
  EXPECT_EQ(MeanHotPressures(vehicle::PaperModelsOf(car), r), (std::array<double, 4>{}));
}

}  // namespace
}  // namespace hotlap::sim
