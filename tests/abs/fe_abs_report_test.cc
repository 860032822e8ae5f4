// WriteFeAbsReport on a hand-made braking history: the page holds the summary in words and the
// paper's figures' series; an empty history is refused and a missing folder is an InputError.

#include "hotlap/abs/fe_abs_report.h"

#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "test_util.h"

namespace hotlap::sim {
namespace {

std::vector<fe::HistoryRow> ExampleHistory() {
  std::vector<fe::HistoryRow> h(3);
  for (int k = 0; k < 3; ++k) {
    h[k].time_s = 0.01 * k;
    h[k].rim_vx_mps = 8.0 - k;
    h[k].spin_rad_per_s = 20.0 - 3.0 * k;
    h[k].slip = 0.05 * k;
    h[k].brake_torque_Nm = 100.0 * k;
  }
  return h;
}

TEST(WriteFeAbsReport, WritesTheSummaryAndTheFigures) {
  test::TempDir dir;
  const auto path = dir.path() / "abs_report.html";
  CycleWindow cycles;
  cycles.cycles = 1;
  WriteFeAbsReport(path, ExampleHistory(), cycles, 0.4, {{"configuration", "fe/example.yaml"}});
  const std::string html = test::ReadTextFile(path);
  for (const char* part :
       {"hotlap fe abs", "fe/example.yaml",
        "0.020 s of braking from 8.000 m/s to 6.000 m/s; peak slip 0.100.",
        "1 control cycle(s): no window after the first cycle.", "Brake torque (cf. 002 Fig. 8)",
        "omega R_l", "Slip ratio (cf. 002", "Road longitudinal force", "Energy balance error"}) {
    EXPECT_TRUE(test::Contains(html, part)) << part;
  }
}

TEST(WriteFeAbsReport, RefusesAnEmptyHistoryAndAMissingFolder) {
  test::TempDir dir;
  EXPECT_THROW(WriteFeAbsReport(dir.path() / "r.html", {}, {}, 0.4, {}), std::invalid_argument);
  EXPECT_TRUE(test::Contains(test::InputErrorOf([&] {
                               WriteFeAbsReport(dir.path() / "no" / "r.html", ExampleHistory(), {},
                                                0.4, {});
                             }),
                             "r.html"));
}

// Issue 27: with the lumped run of the same event, every chart draws it and the text compares
// the two runs' cycles, the lumped times counted from the FE braking step's start.
TEST(WriteFeAbsReport, DrawsTheLumpedRunBesideTheFeOne) {
  test::TempDir dir;
  const auto path = dir.path() / "abs_report.html";
  std::vector<fe::HistoryRow> fe_history = ExampleHistory();
  for (fe::HistoryRow& r : fe_history) r.time_s += 0.24;  // the braking step starts at 0.24 s
  CycleWindow cycles;
  cycles.cycles = 2;
  cycles.first_cycle_start_s = 0.24 + 0.125;
  cycles.second_cycle_start_s = 0.24 + 0.27;
  AbsHistory lumped_history;
  lumped_history.time = {0.0, 0.01};
  lumped_history.speed = {8.0, 7.9};
  lumped_history.wheel_speed = {22.0, 21.0};
  lumped_history.lambda = {0.0, 0.04};
  lumped_history.brake_torque = {0.0, 120.0};
  lumped_history.fx = {0.0, -900.0};
  FeAbsLumpedRun lumped{&lumped_history, {}, 0.36, "lumped, same ABS file"};
  lumped.cycles.cycles = 3;
  lumped.cycles.first_cycle_start_s = 0.125;
  lumped.cycles.second_cycle_start_s = 0.19;
  // A second lumped run (the lumped quarter car's own tuning): its own line and sentence.
  FeAbsLumpedRun own = lumped;
  own.label = "lumped, own tuning";
  own.cycles.cycles = 5;
  own.cycles.first_cycle_start_s = 0.13;
  WriteFeAbsReport(path, fe_history, cycles, 0.4, {}, {lumped, own});
  const std::string html = test::ReadTextFile(path);
  for (const char* part : {"`hotlap abs` run of the same event (lumped, same ABS file: rigid wheel",
                           "first pressure release FE 0.125 s, lumped 0.125 s",
                           "second cycle FE 0.270 s, lumped 0.190 s", "cycles FE 2, lumped 3",
                           "torque (lumped, same ABS file)", "Vx (lumped, same ABS file)",
                           "omega R_l (lumped, same ABS file)", "slip (lumped, same ABS file)",
                           "Fx (lumped, same ABS file)", "(lumped, own tuning: rigid wheel",
                           "first pressure release FE 0.125 s, lumped 0.130 s",
                           "cycles FE 2, lumped 5", "slip (lumped, own tuning)"}) {
    EXPECT_TRUE(test::Contains(html, part)) << part;
  }
  WriteFeAbsReport(path, fe_history, cycles, 0.4, {});
  EXPECT_FALSE(test::Contains(test::ReadTextFile(path), "(lumped"));
}

}  // namespace
}  // namespace hotlap::sim
