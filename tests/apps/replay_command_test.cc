// End-to-end tests of `hotlap replay`: a good run writes the documented columns and a JSON
// summary that agrees with them; every kind of bad input gives one clear message, a non-zero
// exit and no output file.

#include <cstdlib>
#include <filesystem>
#include <regex>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "apps/run_hotlap.h"
#include "hotlap/common/csv.h"
#include "hotlap/common/units.h"
#include "test_util.h"

namespace {

namespace fs = std::filesystem;

const fs::path kSource = HOTLAP_SOURCE_DIR;
const fs::path kExample = kSource / "data/telemetry/darlington_example.csv";

using hotlap::test::RunResult;

using hotlap::test::ReadTextFile;
using hotlap::test::WriteTextFile;

// A fresh folder per test, removed with everything in it at the end.
class ReplayCommandTest : public ::testing::Test {
 protected:
  RunResult Run(const std::string& args) { return hotlap::test::RunHotlap(args, dir_); }

  // A copy of the example log with one edit applied to its text.
  fs::path EditedLog(const std::function<std::string(std::string)>& edit) {
    return WriteTextFile(dir_ / "edited.csv", edit(ReadTextFile(kExample)));
  }

  // A copy of the gen7 car folder whose file `relative` has `from` replaced by `to`.
  fs::path EditedCar(const std::string& relative, const std::string& from, const std::string& to) {
    const fs::path car = dir_ / "gen7";
    fs::copy(kSource / "data/cars/gen7", car, fs::copy_options::recursive);
    std::string text = ReadTextFile(car / relative);
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
    WriteTextFile(car / relative, text);
    return car / "car.yaml";
  }

  // Runs with bad input and checks: exit code 2, a single "hotlap: error:" line mentioning
  // every `needles`, and no output file.
  void ExpectCleanFailure(const std::string& args, const std::vector<std::string>& needles) {
    const fs::path out = dir_ / "out.csv", json = dir_ / "out.json", report = dir_ / "out.html";
    const RunResult r = Run(args + " --out " + out.string() + " --json " + json.string() +
                            " --report " + report.string());
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(r.err.rfind("hotlap: error: ", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    for (const std::string& n : needles) EXPECT_NE(r.err.find(n), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out));
    EXPECT_FALSE(fs::exists(json));
    EXPECT_FALSE(fs::exists(report));
    for (const auto& entry : fs::directory_iterator(dir_)) {  // no temporary left behind either
      EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();
    }
  }

  const hotlap::test::TempDir tmp_;
  const fs::path dir_ = tmp_.path();
};

TEST_F(ReplayCommandTest, WritesDocumentedColumnsAndMatchingJson) {
  const fs::path out = dir_ / "out.csv", json = dir_ / "out.json";
  const RunResult r = Run("replay --telemetry " + kExample.string() + " --out " + out.string() +
                          " --json " + json.string() + " --heat-flows");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("corner"), std::string::npos);

  const hotlap::CsvTable table = hotlap::ReadCsv(out);
  const hotlap::CsvTable input = hotlap::ReadCsv(kExample);
  EXPECT_EQ(table.RowCount(), input.RowCount());  // one row per input row
  EXPECT_EQ(table.columns.front(), "time_s");
  for (const char* c : {"fl", "fr", "rl", "rr"}) {
    for (const std::string q : {"tread_temp_", "carcass_temp_", "disc_temp_", "calliper_temp_"}) {
      EXPECT_GE(table.ColumnIndex(q + c + "_C"), 0) << q << c;
    }
    EXPECT_GE(table.ColumnIndex(std::string("wear_") + c + "_mm"), 0);
    EXPECT_GE(table.ColumnIndex(std::string("grip_factor_") + c), 0);
    EXPECT_GE(table.ColumnIndex(std::string("brake_power_") + c + "_W"), 0);
    for (int q = 1; q <= 7; ++q) {
      EXPECT_GE(table.ColumnIndex("q" + std::to_string(q) + "_" + c + "_W"), 0);
    }
  }
  const nlohmann::json j = nlohmann::json::parse(ReadTextFile(json));
  EXPECT_EQ(j["samples"].get<size_t>(), table.RowCount());
  for (const char* c : {"fl", "fr", "rl", "rr"}) {
    const auto& tread = table.values[table.ColumnIndex(std::string("tread_temp_") + c + "_C")];
    const double peak = *std::max_element(tread.begin(), tread.end());
    EXPECT_NEAR(j["corners"][c]["tread_temp_C"]["peak"].get<double>(), peak, 1e-6);
    EXPECT_NEAR(j["corners"][c]["tread_temp_C"]["final"].get<double>(), tread.back(), 1e-6);
    const auto& wear = table.values[table.ColumnIndex(std::string("wear_") + c + "_mm")];
    EXPECT_NEAR(j["corners"][c]["wear_mm"].get<double>(), wear.back(),
                1e-8 * wear.back());  // 9 digits
    EXPECT_GT(wear.back(), 0.0);
  }
  // The outside (right) tyres work harder than the inside ones on an anticlockwise oval.
  EXPECT_GT(j["corners"]["fr"]["tread_temp_C"]["peak"].get<double>(),
            j["corners"]["fl"]["tread_temp_C"]["peak"].get<double>());
  EXPECT_GT(j["corners"]["rr"]["wear_mm"].get<double>(),
            j["corners"]["rl"]["wear_mm"].get<double>());
}

// --set replays the log with the car changed: half the front-left duct, a hotter front-left disc
// and the other discs as they were; the summary records the override.
TEST_F(ReplayCommandTest, SetOverridesTheCar) {
  const fs::path a = dir_ / "a.json", b = dir_ / "b.json";
  ASSERT_EQ(Run("replay --telemetry " + kExample.string() + " --out " + (dir_ / "a.csv").string() +
                " --json " + a.string())
                .exit_code,
            0);
  const RunResult r =
      Run("replay --telemetry " + kExample.string() + " --out " + (dir_ / "b.csv").string() +
          " --json " + b.string() + " --set brakes.fl.duct_factor=0.5");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json ja = nlohmann::json::parse(ReadTextFile(a));
  const nlohmann::json jb = nlohmann::json::parse(ReadTextFile(b));
  EXPECT_EQ(ja["overrides"], nlohmann::json::object());
  EXPECT_EQ(jb["overrides"], nlohmann::json({{"brakes.fl.duct_factor", 0.5}}));
  EXPECT_GT(jb["corners"]["fl"]["disc_temp_C"]["final"].get<double>(),
            ja["corners"]["fl"]["disc_temp_C"]["final"].get<double>() + 1.0);
  for (const char* c : {"fr", "rl", "rr"}) EXPECT_EQ(jb["corners"][c], ja["corners"][c]) << c;
}

TEST_F(ReplayCommandTest, OverrideOutOfRangeIsNamed) {
  ExpectCleanFailure(
      "replay --telemetry " + kExample.string() + " --set brakes.rr.mass_participation=0",
      {"override 'brakes.rr.mass_participation=0'", "brakes/rear.yaml",
       "field 'mass_participation'", "out of range"});
}

TEST_F(ReplayCommandTest, MissingColumnIsNamed) {
  const fs::path log = EditedLog([](std::string s) {
    return std::regex_replace(s, std::regex("fz_rl_N"), "fz_rl_unknown_thing");
  });
  ExpectCleanFailure("replay --telemetry " + log.string(), {"fz_rl", log.filename().string()});
}

TEST_F(ReplayCommandTest, UnknownUnitIsNamed) {
  const fs::path log = EditedLog(
      [](std::string s) { return std::regex_replace(s, std::regex("fx_fr_N"), "fx_fr_lbf"); });
  ExpectCleanFailure("replay --telemetry " + log.string(), {"fx_fr_lbf", "lbf"});
}

TEST_F(ReplayCommandTest, NanCellIsNamedWithLineAndColumn) {
  const fs::path log = EditedLog([](std::string s) {
    // Replace the first value of the 10th data line's second column with nan.
    size_t pos = 0;
    for (int i = 0; i < 15; ++i) pos = s.find('\n', pos) + 1;
    const size_t comma = s.find(',', pos);
    const size_t next = s.find(',', comma + 1);
    return s.substr(0, comma + 1) + "nan" + s.substr(next);
  });
  ExpectCleanFailure("replay --telemetry " + log.string(), {"edited.csv:16", "distance_m", "nan"});
}

TEST_F(ReplayCommandTest, TimeNotIncreasingIsNamed) {
  const fs::path log = EditedLog([](std::string s) {
    return std::regex_replace(s, std::regex("\n0\\.1,"), "\n0,",
                              std::regex_constants::format_first_only);
  });
  ExpectCleanFailure("replay --telemetry " + log.string(), {"time_s", "increasing"});
}

TEST_F(ReplayCommandTest, NegativeMassIsNamed) {
  const fs::path car = EditedCar("tyres/rr.yaml", "tread_mass_kg: 0.9", "tread_mass_kg: -0.9");
  ExpectCleanFailure("replay --telemetry " + kExample.string() + " --car " + car.string(),
                     {"rr.yaml", "construction.tread_mass_kg", "-0.9", "> 0 kg"});
}

TEST_F(ReplayCommandTest, CubicThatGoesNegativeIsRejected) {
  const fs::path car = EditedCar("tyres/compound.yaml", "low_value: 0.90", "low_value: 0.05");
  ExpectCleanFailure("replay --telemetry " + kExample.string() + " --car " + car.string(),
                     {"compound.yaml", "grip_cubic", "not positive"});
}

TEST_F(ReplayCommandTest, UnreadableFileIsNamed) {
  ExpectCleanFailure("replay --telemetry " + (dir_ / "no_such.csv").string(), {"no_such.csv"});
}

TEST_F(ReplayCommandTest, WrongUnitInParameterKeyIsNamed) {
  const fs::path car = EditedCar("brakes/front.yaml", "disc_mass_kg: 8.8", "disc_mass_lb: 19.4");
  ExpectCleanFailure("replay --telemetry " + kExample.string() + " --car " + car.string(),
                     {"front.yaml", "disc_mass_kg", "disc_mass_lb"});
}

TEST_F(ReplayCommandTest, MissingOutputFolderFailsBeforeWork) {
  const RunResult r = Run("replay --telemetry " + kExample.string() + " --out " +
                          (dir_ / "nope" / "out.csv").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("does not exist"), std::string::npos) << r.err;
}

// The shipped example log is exactly what the documented generator writes.
TEST(ExampleLogTest, ShippedLogIsReproducedByItsGenerator) {
  const hotlap::test::TempDir dir;
  const fs::path out = dir.path() / "example.csv";
  const std::string command =
      std::string(HOTLAP_MAKE_EXAMPLE_LOG) + " " + out.string() + " >/dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0);
  EXPECT_EQ(ReadTextFile(out), ReadTextFile(kExample));
}

}  // namespace
