// WriteLapReport on a hand-made stint: the page is written with the summary tables (laps, corners,
// braking zones) and the map and channel charts; a missing folder is an InputError.

#include "hotlap/sim/lap_report.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "hotlap/track/track_io.h"
#include "sim/qss_example.h"
#include "test_util.h"

namespace hotlap::sim {
namespace {

// Every column the report draws, five samples each.
ColumnSet ExampleColumns() {
  ColumnSet c;
  const auto add = [&](const std::string& name) {
    c.names.push_back(name);
    c.values.push_back({0.0, 25.0, 50.0, 75.0, 100.0});
  };
  for (const char* n :
       {"distance_m", "x_m", "y_m", "speed_mps", "accel_long_mps2", "accel_lat_mps2"}) {
    add(n);
  }
  for (Corner corner : kAllCorners) {
    for (const char* p : {"fz_{}_N", "tread_temp_{}_C", "carcass_temp_{}_C", "wear_{}_mm",
                          "grip_factor_{}", "slip_angle_{}_deg", "slip_ratio_{}", "disc_temp_{}_C",
                          "calliper_temp_{}_C", "brake_power_{}_W"}) {
      add(fmt::format(fmt::runtime(p), CornerName(corner)));
    }
  }
  return c;
}

TEST(WriteLapReport, WritesTheTablesAndCharts) {
  test::TempDir dir;
  vehicle::Car car;
  car.name = "gen7";
  car.path = "cars/gen7/car.yaml";
  const track::Track track = track::LoadTrack("darlington");
  const StintSummary stint = SummarizeStint(testing::MakeExampleQssResult(2));
  const auto path = dir.path() / "lap.html";
  WriteLapReport(path, {.line = "centre", .laps = 2}, car, track, ExampleColumns(), stint);
  const std::string html = test::ReadTextFile(path);
  for (const char* part : {"hotlap lap: gen7 on darlington", "cars/gen7/car.yaml", "2.400", "495.0",
                           "0.01000", "Braking zones", "Track map coloured by speed",
                           "Accelerations", "Normal loads", "Grip factor", "Braking power"}) {
    EXPECT_TRUE(test::Contains(html, part)) << part;
  }
  EXPECT_TRUE(test::Contains(test::InputErrorOf([&] {
                               WriteLapReport(dir.path() / "no" / "lap.html", {}, car, track,
                                              ExampleColumns(), stint);
                             }),
                             "lap.html"));
}

}  // namespace
}  // namespace hotlap::sim
