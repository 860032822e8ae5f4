// TrackInfoJson on the shipped Darlington: the figures in m and deg, its turns, segments and
// solved unknowns, and the ribbon file only when given.

#include "hotlap/track/track_info_json.h"

#include <gtest/gtest.h>

#include "hotlap/common/units.h"

namespace hotlap::track {
namespace {

TEST(TrackInfoJson, HoldsTheFiguresTurnsAndSegments) {
  const TrackFile file = LoadTrackByName("darlington");
  const SummaryOptions options;
  const TrackSummary s = Summarize(file.track, options);
  nlohmann::json j = TrackInfoJson(file, s, options);
  EXPECT_EQ(j["command"], "track info");
  EXPECT_EQ(j["track"], "darlington");
  EXPECT_EQ(j["format"], "segments");
  EXPECT_NEAR(j["length_m"].get<double>(), s.length_m, 1e-6);
  EXPECT_EQ(j["winding"], s.winding);
  EXPECT_NEAR(j["bank_max_deg"].get<double>(), RadToDeg(s.bank_max_rad), 1e-6);
  EXPECT_EQ(j["turn_radius_m"], 500.0);
  ASSERT_EQ(j["turns"].size(), s.turns.size());
  EXPECT_EQ(j["turns"][0]["direction"], s.turns[0].direction > 0 ? "left" : "right");
  ASSERT_EQ(j["segments"].size(), file.segments.size());
  for (size_t i = 0; i < file.segments.size(); ++i) {
    EXPECT_EQ(j["segments"][i].contains("radius_m"), file.segments[i].type == SegmentType::kArc);
  }
  EXPECT_EQ(j["solved"].size(), file.solved.size());
  EXPECT_FALSE(j.contains("out"));
  j = TrackInfoJson(file, s, options, "ribbon.csv");
  EXPECT_EQ(j["out"], "ribbon.csv");
  EXPECT_STREQ(TurnDirectionName(1), "left");
  EXPECT_STREQ(TurnDirectionName(-1), "right");
}

}  // namespace
}  // namespace hotlap::track
