// ABS runs end to end on the shipped configuration: the paper's case meets the issue's
// acceptance, ABS stops shorter than locked wheels on dry and wet roads, the energy balance
// closes, halving the step changes the stopping distance by almost nothing, the locked wheel,
// road changes and drum mode behave, and the brake heat reaches the disc.

#include "hotlap/abs/abs_run.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "hotlap/abs/abs_config.h"
#include "hotlap/abs/abs_metrics.h"
#include "hotlap/brake/abs_controller.h"
#include "test_util.h"

namespace {

using hotlap::sim::AbsConfig;
using hotlap::sim::AbsControl;
using hotlap::sim::AbsEvent;
using hotlap::sim::AbsMetrics;
using hotlap::sim::AbsRunResult;
using hotlap::sim::AbsVehicleMode;
using hotlap::sim::CalcAbsMetrics;
using hotlap::sim::RunAbs;

const AbsConfig& RunConfig() {
  static const AbsConfig c =
      hotlap::sim::LoadAbsConfig(hotlap::test::SourcePath("data/abs/paper.yaml"));
  return c;
}

AbsEvent ToStandstill(const std::string& surface, AbsControl control) {
  AbsEvent e = RunConfig().event;
  e.surface = surface;
  e.control = control;
  e.duration_s = 10.0;
  return e;
}

TEST(AbsRunTest, ThePapersCaseMeetsTheAcceptance) {
  const AbsEvent& e = RunConfig().event;
  ASSERT_EQ(e.surface, "paper");
  ASSERT_DOUBLE_EQ(e.initial_speed_mps, 11.165);
  ASSERT_DOUBLE_EQ(e.duration_s, 1.5);
  ASSERT_DOUBLE_EQ(RunConfig().plant.wheel.vertical_load, 4314.0);
  const AbsRunResult run = RunAbs(RunConfig(), e);
  const AbsMetrics m = CalcAbsMetrics(RunConfig(), run);
  EXPECT_DOUBLE_EQ(run.end_time_s, 1.5);
  // 5 to 12 control cycles per second; after the first cycle lambda < 0.135 most of the time;
  // the wheel never locks above the exit speed.
  EXPECT_GE(m.cycles_per_s, 5.0);
  EXPECT_LE(m.cycles_per_s, 12.0);
  ASSERT_TRUE(m.fraction_time_lambda_below_0_135.has_value());
  EXPECT_GE(*m.fraction_time_lambda_below_0_135, 0.9);
  EXPECT_LT(*m.max_lambda_after_first_cycle, 0.25);
  EXPECT_FALSE(m.wheel_locked);
  EXPECT_LT(m.max_lambda, hotlap::sim::kLockedSlip);
  // The slip of the first cycle's peak and the braking it gives, for the record.
  EXPECT_GT(m.mean_deceleration_mps2, 5.0);
  EXPECT_GT(m.peak_disc_temp_K, run.history.disc_temp.front() + 50.0);
}

TEST(AbsRunTest, AbsStopsShorterThanLockedWheelsOnDryAndWetRoads) {
  for (const char* surface : {"dry", "wet", "paper", "split"}) {
    const AbsMetrics abs =
        CalcAbsMetrics(RunConfig(), RunAbs(RunConfig(), ToStandstill(surface, AbsControl::kAbs)));
    const AbsRunResult locked_run =
        RunAbs(RunConfig(), ToStandstill(surface, AbsControl::kDriverOnly));
    const AbsMetrics locked = CalcAbsMetrics(RunConfig(), locked_run);
    ASSERT_TRUE(abs.stopped && locked.stopped) << surface;
    EXPECT_LT(*abs.stopping_distance_m, 0.96 * *locked.stopping_distance_m) << surface;
    // On the mu-jump the wheel dips deep for a moment (docs/abs.md); elsewhere never near lock.
    if (std::string(surface) != "split") {
      EXPECT_LT(abs.max_lambda, 0.3) << surface;
    }
    EXPECT_TRUE(locked.wheel_locked) << surface;
    // Without ABS the wheel is held stopped from its lock to the end: omega never negative.
    EXPECT_EQ(locked_run.history.locked.back(), 1) << surface;
    for (double w : locked_run.history.wheel_speed) ASSERT_GE(w, 0.0) << surface;
  }
}

TEST(AbsRunTest, EnergyClosesWithAndWithoutAbsAndOnTheDrum) {
  std::vector<AbsEvent> events = {RunConfig().event, ToStandstill("dry", AbsControl::kAbs),
                                  ToStandstill("split", AbsControl::kDriverOnly)};
  AbsEvent drum = RunConfig().event;
  drum.vehicle = AbsVehicleMode::kDrum;
  events.push_back(drum);
  for (const AbsEvent& e : events) {
    const AbsMetrics m = CalcAbsMetrics(RunConfig(), RunAbs(RunConfig(), e));
    // The issue asks for 1 %; the quadrature of the powers with the state gives far better.
    EXPECT_LT(std::abs(m.energy.closure_error), 1e-6) << e.surface;
    EXPECT_GT(m.energy.brake_J, 0.0);
    EXPECT_GT(m.energy.tyre_slip_J, 0.0);
    EXPECT_GT(m.energy.rolling_resistance_J, 0.0);
    if (e.vehicle == AbsVehicleMode::kDrum) {
      EXPECT_GT(m.energy.drum_work_J, m.energy.brake_J);
    } else {
      EXPECT_EQ(m.energy.drum_work_J, 0.0);
    }
  }
}

TEST(AbsRunTest, HalvingTheStepChangesTheStoppingDistanceByAlmostNothing) {
  for (const char* surface : {"paper", "dry", "split"}) {
    for (AbsControl control : {AbsControl::kAbs, AbsControl::kDriverOnly}) {
      AbsEvent e = ToStandstill(surface, control);
      const AbsMetrics coarse = CalcAbsMetrics(RunConfig(), RunAbs(RunConfig(), e));
      e.steps_per_period *= 2;
      const AbsMetrics fine = CalcAbsMetrics(RunConfig(), RunAbs(RunConfig(), e));
      ASSERT_TRUE(coarse.stopped && fine.stopped);
      // 1 ms -> 0.5 ms: at most 30 micrometres in 8.8 to 14.3 m (docs/abs.md); 100 allowed.
      EXPECT_NEAR(*coarse.stopping_distance_m, *fine.stopping_distance_m, 1e-4) << surface;
      EXPECT_EQ(coarse.cycles, fine.cycles) << surface;
    }
  }
}

TEST(AbsRunTest, TheRoadChangesExactlyAtTheSegmentBoundary) {
  const AbsRunResult run = RunAbs(RunConfig(), ToStandstill("split", AbsControl::kAbs));
  const auto& h = run.history;
  const double boundary = RunConfig().SurfaceNamed("split").segments[1].start_m;
  // A record sits on the boundary; the dry law before it, the wet one after.
  const auto at = std::find_if(h.distance.begin(), h.distance.end(),
                               [&](double x) { return x >= boundary - 1e-9; });
  ASSERT_NE(at, h.distance.end());
  EXPECT_NEAR(*at, boundary, 1e-7);
  const size_t i = static_cast<size_t>(at - h.distance.begin());
  const auto& dry = RunConfig().friction_laws[1].law;
  const auto& wet = RunConfig().friction_laws[2].law;
  const double v_s_before = std::abs(h.speed[i - 1] * h.transient_slip[i - 1]);
  const double v_s_after = std::abs(h.speed[i] * h.transient_slip[i]);
  EXPECT_NEAR(h.friction[i - 1], dry.Friction(v_s_before), 1e-12);
  EXPECT_NEAR(h.friction[i], wet.Friction(v_s_after), 1e-12);
}

TEST(AbsRunTest, TheControllerRunsAtItsPeriodAndStatesAreRecorded) {
  const AbsRunResult run = RunAbs(RunConfig(), RunConfig().event);
  const auto& h = run.history;
  // The state changes only at controller ticks.
  for (size_t i = 1; i < h.size(); ++i) {
    if (h.state[i] != h.state[i - 1]) {
      const double ticks = h.time[i] / RunConfig().controller.period_s;
      EXPECT_NEAR(ticks, std::round(ticks), 1e-6) << h.time[i];
    }
  }
  for (double t : run.cycle_starts_s) {
    EXPECT_NEAR(t / 0.005, std::round(t / 0.005), 1e-9);
  }
  EXPECT_EQ(h.state.front(), static_cast<int>(hotlap::brake::AbsState::kInitialise));
  // Without ABS there is no controller state.
  AbsEvent off = RunConfig().event;
  off.control = AbsControl::kDriverOnly;
  const AbsRunResult driver = RunAbs(RunConfig(), off);
  EXPECT_TRUE(std::all_of(driver.history.state.begin(), driver.history.state.end(),
                          [](int s) { return s == -1; }));
  EXPECT_TRUE(driver.cycle_starts_s.empty());
}

TEST(AbsRunTest, AbsExitsAtLowSpeedAndTheWheelThenLocks) {
  const AbsRunResult run = RunAbs(RunConfig(), ToStandstill("paper", AbsControl::kAbs));
  ASSERT_TRUE(run.abs_exit_s.has_value());
  const auto& h = run.history;
  for (size_t i = 0; i < h.size(); ++i) {
    if (h.time[i] >= *run.abs_exit_s + 1e-9) {
      EXPECT_EQ(h.state[i], static_cast<int>(hotlap::brake::AbsState::kExit));
      EXPECT_LT(h.speed[i], RunConfig().controller.exit_speed_mps + 0.1);
    }
  }
  EXPECT_EQ(h.locked.back(), 1);  // the driver's full pressure below the exit speed
}

TEST(AbsRunTest, BrakeHeatReachesTheDiscAndCalliper) {
  // With cooling switched off, the heat stored in the disc and calliper is the brake's work.
  AbsConfig c = RunConfig();
  auto& b = c.brake.params;
  b.disc_emissivity = b.calliper_emissivity = 0.0;
  b.disc_convection = b.calliper_convection = {};
  const AbsRunResult run = RunAbs(c, RunConfig().event);
  const AbsMetrics m = CalcAbsMetrics(c, run);
  const double stored =
      b.mass_participation * b.disc_mass * b.disc_heat_capacity *
          (run.final_brake.disc_temp - RunConfig().event.initial_disc_temp_K) +
      b.calliper_mass * b.calliper_heat_capacity *
          (run.final_brake.calliper_temp - RunConfig().event.initial_calliper_temp_K);
  EXPECT_NEAR(stored, m.energy.brake_J, 1e-6 * m.energy.brake_J);
}

TEST(AbsRunTest, TheMagicFormulaTyreRunsToo) {
  // The mfeval MF 6.1 example tyre in place of the brush model, with its own rolling resistance.
  AbsConfig c = RunConfig();
  c.plant.tyre = hotlap::tyre::LoadTyreForceModel(
      hotlap::test::SourcePath("tests/data/tir/mfeval/MagicFormula61_Parameters.tir"));
  c.plant.wheel.rolling_resistance = 0.0;
  const AbsMetrics m = CalcAbsMetrics(c, RunAbs(c, ToStandstill("wet", AbsControl::kAbs)));
  // The controller is tuned for the brush tyre; here only the plumbing is checked.
  EXPECT_TRUE(m.stopped);
  EXPECT_GT(m.cycles, 2);
  EXPECT_LT(std::abs(m.energy.closure_error), 1e-6);
  EXPECT_GT(m.energy.rolling_resistance_J, 0.0);
}

}  // namespace
