// What `hotlap replay` writes of a hand-made replay besides its channels: the statistics' text,
// the JSON summary (degC, wear, grip, brake energy) and the HTML report.

#include "hotlap/sim/replay_report.h"

#include <gtest/gtest.h>

#include "hotlap/common/units.h"
#include "test_util.h"

namespace hotlap::sim {
namespace {

// Three samples, 1 s apart; the rear right 10 K hotter than the others.
ReplayResult ExampleReplay() {
  ReplayResult r;
  r.time = {0.0, 1.0, 2.0};
  for (int k = 0; k < 4; ++k) {
    CornerHistory& h = r.corners[k];
    const double t0 = CelsiusToKelvin(80.0) + (k == 3 ? 10.0 : 0.0);
    h.tread_temp = {t0, t0 + 4.0, t0 + 2.0};
    h.carcass_temp = {t0, t0, t0};
    h.disc_temp = {t0 + 300.0, t0 + 400.0, t0 + 300.0};
    h.calliper_temp = {t0, t0 + 1.0, t0 + 2.0};
    h.wear = {0.0, 0.001, 0.002};
    h.grip_factor = {1.0, 0.95, 0.97};
    h.brake_power = {0.0, 2000.0, 0.0};
  }
  return r;
}

TEST(ReplayReport, TextAndJsonOfTheSummaries) {
  const ReplayResult r = ExampleReplay();
  const auto summaries = SummarizeReplay(r);
  EXPECT_EQ(TemperatureStatsText(summaries[3].tread), "94.0/92.5/92.0");
  vehicle::Car car;
  car.name = "gen7";
  const nlohmann::json j = ReplayJson(r, summaries, "log.csv", car, "out.csv");
  EXPECT_EQ(j["command"], "replay");
  EXPECT_EQ(j["telemetry"], "log.csv");
  EXPECT_EQ(j["car"], "gen7");
  EXPECT_EQ(j["overrides"], nlohmann::json::object());  // none given
  EXPECT_EQ(j["out"], "out.csv");
  EXPECT_EQ(j["samples"], 3);
  EXPECT_EQ(j["duration_s"], 2.0);
  EXPECT_EQ(j["corners"]["rr"]["tread_temp_C"]["peak"], 94.0);
  EXPECT_EQ(j["corners"]["rr"]["tread_temp_C"]["final"], 92.0);
  EXPECT_EQ(j["corners"]["fl"]["disc_temp_C"]["peak"], 480.0);
  EXPECT_EQ(j["corners"]["fl"]["wear_mm"], 0.002);
  EXPECT_EQ(j["corners"]["fl"]["min_grip_factor"], 0.95);
  EXPECT_EQ(j["corners"]["fl"]["brake_energy_J"], 2000.0);
}

TEST(ReplayReport, WritesThePage) {
  test::TempDir dir;
  const ReplayResult r = ExampleReplay();
  vehicle::Car car;
  car.name = "gen7";
  car.path = "cars/gen7/car.yaml";
  const auto path = dir.path() / "replay.html";
  WriteReplayReport(path, "logs/run1.csv", "out.csv", car, {{"track", "darlington"}}, r,
                    SummarizeReplay(r));
  const std::string html = test::ReadTextFile(path);
  for (const char* part :
       {"hotlap replay: run1.csv", "gen7 (cars/gen7/car.yaml)", "log track", "94.0/92.5/92.0",
        "2.0", "Tread temperature", "Calliper temperature", "Braking power"}) {
    EXPECT_TRUE(test::Contains(html, part)) << part;
  }
  EXPECT_TRUE(test::Contains(test::InputErrorOf([&] {
                               WriteReplayReport(dir.path() / "no" / "r.html", "l.csv", "o.csv",
                                                 car, {}, r, SummarizeReplay(r));
                             }),
                             "r.html"));
}

}  // namespace
}  // namespace hotlap::sim
