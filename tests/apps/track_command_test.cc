// End-to-end tests of `hotlap track info`: the documented JSON keys and CSV columns agree with the
// library, for a built-in name and for a file of each format; bad input gives one clear message,
// exit code 2 and no output file.

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "apps/run_hotlap.h"
#include "hotlap/common/csv.h"
#include "hotlap/common/units.h"
#include "hotlap/logs/telemetry.h"
#include "hotlap/track/track_io.h"
#include "test_util.h"

namespace hotlap {
namespace {

namespace fs = std::filesystem;

using test::RunResult;

class TrackCommandTest : public test::CommandTest {};

TEST_F(TrackCommandTest, DarlingtonInfoJsonAndRibbonCsv) {
  const fs::path json = dir() / "info.json", csv = dir() / "ribbon.csv";
  const RunResult r = Run("track info --track darlington --json " + json.string() + " --out " +
                          csv.string() + " --step-m 2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(test::Contains(r.out, "length          2198.000 m, anticlockwise"));
  EXPECT_TRUE(test::Contains(r.out, "minimum radius  160.000 m"));
  EXPECT_TRUE(test::Contains(r.out, "front_stretch_m"));

  const nlohmann::json j = Json(json);
  for (const char* key :
       {"command", "track", "file", "format", "length_m", "winding", "closure_error_m",
        "closure_error_rad", "min_radius_m", "min_radius_at_m", "bank_min_deg", "bank_max_deg",
        "width_min_m", "width_max_m", "turns", "segments", "solved", "out"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["command"], "track info");
  EXPECT_EQ(j["track"], "darlington");
  EXPECT_EQ(j["format"], "segments");
  EXPECT_NEAR(j["length_m"].get<double>(), 2198.0, 1e-6);
  EXPECT_LT(j["closure_error_m"].get<double>(), 0.01);
  EXPECT_LT(std::abs(j["closure_error_rad"].get<double>()), 1e-6);
  EXPECT_NEAR(j["min_radius_m"].get<double>(), 160.0, 1e-6);
  EXPECT_NEAR(j["bank_min_deg"].get<double>(), 2.0, 1e-9);
  EXPECT_NEAR(j["bank_max_deg"].get<double>(), 25.0, 1e-9);
  EXPECT_EQ(j["winding"], 1);
  ASSERT_EQ(j["turns"].size(), 2u);
  EXPECT_NEAR(j["turns"][0]["entry_m"].get<double>(), 200.0, 15.0);
  EXPECT_NEAR(j["turns"][1]["entry_m"].get<double>(), 1300.0, 15.0);
  EXPECT_EQ(j["turns"][0]["direction"], "left");
  EXPECT_EQ(j["segments"].size(), 8u);
  EXPECT_NEAR(j["segments"][2]["radius_m"].get<double>(), 183.0, 1e-6);
  EXPECT_NEAR(j["solved"]["front_stretch_m"].get<double>(), 375.0, 5.0);

  // The CSV is in the shared format, indexed by distance, and agrees with the library.
  const Telemetry ribbon = Telemetry::Read(csv, "distance");
  const track::Track t = track::LoadTrack("darlington");
  EXPECT_EQ(ribbon.size(), 1100u);  // 1099 steps of 2 m, plus the closing row
  EXPECT_NEAR(ribbon.index().back(), 2198.0, 1e-9);
  const CsvTable table = ReadCsv(csv);
  for (const char* c : {"x_m", "y_m", "z_m", "heading_rad", "curvature_per_m", "bank_deg",
                        "grade_deg", "width_left_m", "width_right_m", "geodesic_curvature_per_m",
                        "normal_curvature_per_m", "curvature_rate_per_m2"}) {
    ASSERT_GE(table.ColumnIndex(c), 0) << c;
  }
  const auto& s = table.values[table.ColumnIndex("distance_m")];
  const auto& bank = table.values[table.ColumnIndex("bank_deg")];
  const auto& y = table.values[table.ColumnIndex("y_m")];
  for (size_t i = 0; i < s.size(); i += 97) {
    EXPECT_NEAR(bank[i], RadToDeg(t.At(s[i]).bank_rad), 1e-9);
    EXPECT_NEAR(y[i], t.At(s[i]).y_m, 1e-9);
  }
  bool track_key = false;
  for (const auto& [k, v] : table.metadata)
    track_key = track_key || (k == "track" && v == "darlington");
  EXPECT_TRUE(track_key);
}

TEST_F(TrackCommandTest, AcceptsFilesOfEveryFormat) {
  for (const char* file :
       {"data/tracks/ims.csv", "data/tracks/catalunya-fl.xml", "data/tracks/darlington.yaml"}) {
    const fs::path json = dir() / "info.json";
    const RunResult r =
        Run("track info --track " + test::SourcePath(file).string() + " --json " + json.string());
    ASSERT_EQ(r.exit_code, 0) << file << ": " << r.err;
    const nlohmann::json j = Json(json);
    EXPECT_GT(j["length_m"].get<double>(), 2000.0) << file;
    EXPECT_GT(j["min_radius_m"].get<double>(), 10.0) << file;
    EXPECT_LT(j["closure_error_m"].get<double>(), 1.0) << file;
  }
}

TEST_F(TrackCommandTest, UnknownTrackIsACleanError) {
  const fs::path json = dir() / "info.json";
  const RunResult r = Run("track info --track nowhere --json " + json.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err.rfind("hotlap: error: no track 'nowhere'", 0), 0u) << r.err;
  EXPECT_TRUE(test::Contains(r.err, "'darlington'"));
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(json));
}

TEST_F(TrackCommandTest, BadTrackFileIsACleanError) {
  const fs::path bad = dir() / "bad.yaml", json = dir() / "info.json";
  test::WriteTextFile(bad,
                      "name: bad\nmodel: segments\nwidth_left_m: 5\nwidth_right_m: 5\n"
                      "segments:\n  - {type: straight, length_m: 100, bank_deg: 0}\n");
  const RunResult r = Run("track info --track " + bad.string() + " --json " + json.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(test::Contains(r.err, "the loop does not close")) << r.err;
  EXPECT_FALSE(fs::exists(json));
}

TEST_F(TrackCommandTest, MissingOutputFolderFailsBeforeWork) {
  const RunResult r =
      Run("track info --track darlington --json " + (dir() / "no" / "such" / "info.json").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(test::Contains(r.err, "--json")) << r.err;
}

}  // namespace
}  // namespace hotlap
