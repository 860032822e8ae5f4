// `hotlap log info` and `hotlap log convert` on the three formats (hotlap CSV, MoTeC i2 CSV,
// MoTeC .ld): what they print and write, `--lap`, broken .ld files refused with exit 2 and the
// byte offset, and a converted .ld replaying to the equivalent hotlap CSV's result.

#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "apps/run_hotlap.h"
#include "hotlap/common/csv.h"
#include "hotlap/logs/telemetry.h"
#include "motec_ld_fixture.h"
#include "test_util.h"

namespace {

namespace fs = std::filesystem;
using hotlap::test::Contains;

const fs::path kMotec = hotlap::test::SourcePath("tests/data/motec/darlington_i2.csv");
const fs::path kEquivalent =
    hotlap::test::SourcePath("tests/data/motec/darlington_i2_equivalent.csv");

class LogCommandTest : public hotlap::test::CommandTest {};

TEST_F(LogCommandTest, InfoOfALdLogListsChannelsRatesAndLaps) {
  const fs::path ld = hotlap::test::WriteDarlingtonLd(dir());
  const fs::path json = dir() / "info.json";
  const auto r = Run("log info " + ld.string() + " --json " + json.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(Contains(r.out, "(MoTeC .ld)"));
  EXPECT_TRUE(Contains(r.out, "Venue: Darlington"));
  EXPECT_TRUE(Contains(r.out, "laps: 3"));
  const nlohmann::json j = Json(json);
  EXPECT_EQ(j["command"], "log info");
  EXPECT_EQ(j["format"], "MoTeC .ld");
  EXPECT_EQ(j["rows"], 291);
  EXPECT_DOUBLE_EQ(j["duration_s"].get<double>(), 29.0);
  EXPECT_DOUBLE_EQ(j["rate_hz"].get<double>(), 10.0);
  ASSERT_EQ(j["laps"].size(), 3u);
  EXPECT_EQ(j["laps"][1]["lap"], 2);
  EXPECT_EQ(j["laps"][1]["rows"], 97);
  EXPECT_NEAR(j["laps"][1]["start_s"].get<double>(), 9.7, 1e-9);
  bool air = false, speed = false, rpm = false;
  for (const nlohmann::json& c : j["channels"]) {
    if (c["name"] == "Air Temp") {
      air = true;
      EXPECT_EQ(c["rate_hz"], 1.0);
      EXPECT_EQ(c["samples"], 30);
      EXPECT_EQ(c["unit"], "degC");
      EXPECT_EQ(c["column"], "ambient_temp_C");
      EXPECT_EQ(c["known"], true);
    }
    if (c["name"] == "Ground Speed") {
      speed = true;
      EXPECT_EQ(c["column"], "speed_mps");
      EXPECT_EQ(c["samples"], 291);
    }
    if (c["name"] == "Engine RPM") {
      rpm = true;
      EXPECT_EQ(c["known"], false);
    }
  }
  EXPECT_TRUE(air && speed && rpm);
  EXPECT_TRUE(Contains(j["channel_map"].get<std::string>(), "motec_channels.yaml"));
}

TEST_F(LogCommandTest, InfoOfBothCsvFormats) {
  const fs::path json = dir() / "info.json";
  auto r = Run("log info " + kMotec.string() + " --json " + json.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  nlohmann::json j = Json(json);
  EXPECT_EQ(j["format"], "MoTeC i2 CSV");
  EXPECT_EQ(j["laps"].size(), 3u);
  EXPECT_EQ(j["channels"][2]["name"], "Ground Speed");
  EXPECT_EQ(j["channels"][2]["unit"], "km/h");
  EXPECT_EQ(j["channels"][2]["rate_hz"], 10.0);

  r = Run("log info " + kEquivalent.string() + " --json " + json.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  j = Json(json);
  EXPECT_EQ(j["format"], "hotlap CSV");
  EXPECT_EQ(j["channel_map"], nullptr);
  EXPECT_EQ(j["channels"][2]["name"], "speed_kph");
  EXPECT_EQ(j["channels"][2]["unit"], "kph");
  EXPECT_EQ(j["laps"].size(), 3u);
}

// info refuses what convert (and every command reading the log) refuses: a time that repeats
// (info described such a MoTeC export that convert then refused).
TEST_F(LogCommandTest, InfoRefusesARepeatedTimeAsConvertDoes) {
  const fs::path bad = hotlap::test::WriteTextFile(
      dir() / "repeat.csv",
      hotlap::test::ReplaceOnce(hotlap::test::ReadTextFile(kMotec), "\"0.100\",", "\"0.000\","));
  for (const char* command : {"log info ", "log convert "}) {
    const auto r =
        Run(command + bad.string() +
            (std::string(command) == "log convert " ? " --out " + (dir() / "o.csv").string()
                                                    : std::string()));
    EXPECT_EQ(r.exit_code, 2) << command;
    EXPECT_TRUE(Contains(r.err, "must be strictly increasing")) << command << r.err;
  }
}

TEST_F(LogCommandTest, ConvertALdLapToHotlapCsv) {
  const fs::path ld = hotlap::test::WriteDarlingtonLd(dir());
  const fs::path out = dir() / "lap2.csv";
  const auto r = Run("log convert " + ld.string() + " --lap 2 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(Contains(r.out, "wrote " + out.string()));
  const hotlap::CsvTable t = hotlap::ReadCsv(out);
  EXPECT_EQ(t.RowCount(), 97u);
  EXPECT_NEAR(t.Column("time_s").front(), 9.7, 1e-12);
  EXPECT_NEAR(t.Column("speed_mps").front() * 3.6, 285.002, 1e-9);  // the export's 9.7 s row
  EXPECT_EQ(t.Column("lap").front(), 2.0);
  bool source = false;
  for (const auto& [k, v] : t.metadata)
    source = source || (k == "source" && Contains(v, "(MoTeC .ld)"));
  EXPECT_TRUE(source);
  // It reads back as a log.
  EXPECT_EQ(hotlap::Telemetry::Read(out).size(), 97u);
}

TEST_F(LogCommandTest, ConvertAHotlapCsvKeepsItsNumbers) {
  const fs::path out = dir() / "same.csv";
  const auto r = Run("log convert " + kEquivalent.string() + " --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const hotlap::CsvTable in = hotlap::ReadCsv(kEquivalent);
  const hotlap::CsvTable got = hotlap::ReadCsv(out);
  EXPECT_EQ(got.columns, in.columns);
  EXPECT_EQ(got.values, in.values);
}

TEST_F(LogCommandTest, ABrokenLdIsExit2WithTheByteAndNoOutput) {
  const fs::path ld = hotlap::test::WriteDarlingtonLd(dir());
  const std::string bytes = hotlap::test::ReadTextFile(ld);
  const fs::path cut = hotlap::test::WriteTextFile(dir() / "cut.ld", bytes.substr(0, 5000));
  const fs::path out = dir() / "out.csv";
  auto r = Run("log convert " + cut.string() + " --out " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(Contains(r.err, cut.string() + ": byte ")) << r.err;
  EXPECT_TRUE(Contains(r.err, "truncated or corrupted")) << r.err;
  EXPECT_FALSE(fs::exists(out));
  r = Run("log info " + cut.string());
  EXPECT_EQ(r.exit_code, 2);
  r = Run("replay --telemetry " + cut.string() + " --out " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(Contains(r.err, ": byte ")) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(LogCommandTest, AConvertedLdReplaysAsTheEquivalentCsv) {
  const fs::path ld = hotlap::test::WriteDarlingtonLd(dir());
  const fs::path converted = dir() / "converted.csv";
  ASSERT_EQ(Run("log convert " + ld.string() + " --out " + converted.string()).exit_code, 0);
  const fs::path a = dir() / "a.json", b = dir() / "b.json";
  auto r = Run("replay --telemetry " + converted.string() + " --out " + (dir() / "a.csv").string() +
               " --json " + a.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = Run("replay --telemetry " + kEquivalent.string() + " --out " + (dir() / "b.csv").string() +
          " --json " + b.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // And the .ld straight into replay.
  const fs::path c = dir() / "c.json";
  r = Run("replay --telemetry " + ld.string() + " --out " + (dir() / "c.csv").string() +
          " --json " + c.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(Contains(r.out, "MoTeC channels not mapped (kept): G Force Lat, Engine RPM"));
  const nlohmann::json ja = Json(a)["corners"], jb = Json(b)["corners"], jc = Json(c)["corners"];
  for (const char* corner : {"fl", "fr", "rl", "rr"}) {
    for (const char* q : {"tread_temp_C", "carcass_temp_C", "disc_temp_C", "calliper_temp_C"}) {
      for (const char* s : {"peak", "mean", "final"}) {
        const double want = jb[corner][q][s].get<double>();
        EXPECT_NEAR(ja[corner][q][s].get<double>(), want, 1e-3) << corner << " " << q << " " << s;
        EXPECT_NEAR(jc[corner][q][s].get<double>(), want, 1e-3) << corner << " " << q << " " << s;
      }
    }
    const double wear = jb[corner]["wear_mm"].get<double>();
    EXPECT_NEAR(ja[corner]["wear_mm"].get<double>(), wear, 1e-6 * std::abs(wear) + 1e-12);
  }
}

}  // namespace
