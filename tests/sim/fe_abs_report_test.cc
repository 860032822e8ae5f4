// WriteFeAbsReport on a hand-made braking history: the page holds the summary in words and the
// paper's figures' series; an empty history is refused and a missing folder is an InputError.

#include "hotlap/sim/fe_abs_report.h"

#include <stdexcept>

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

}  // namespace
}  // namespace hotlap::sim
