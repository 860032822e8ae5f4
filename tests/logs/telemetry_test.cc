#include "hotlap/logs/telemetry.h"

#include <cmath>
#include <filesystem>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/csv.h"
#include "hotlap/common/error.h"
#include "test_util.h"

namespace hotlap {
namespace {

namespace fs = std::filesystem;

constexpr double kTol = 1e-12;

using test::Contains;
using test::InputErrorOf;

// A fresh folder per test, removed with everything in it at the end.
class TelemetryTest : public ::testing::Test {
 protected:
  const test::TempDir tmp_;
  const fs::path dir_ = tmp_.path();
};

// ---- Column names ----

TEST(ChannelNameTest, ParsesQuantityCornerAndUnit) {
  struct Case {
    std::string column, quantity;
    std::optional<Corner> corner;
    std::string unit;
  };
  const std::vector<Case> cases = {
      {"time_s", "time", std::nullopt, "s"},
      {"distance_m", "distance", std::nullopt, "m"},
      {"speed_kph", "speed", std::nullopt, "kph"},
      {"speed_rl_mph", "speed", Corner::kRearLeft, "mph"},
      {"fx_fl_N", "fx", Corner::kFrontLeft, "N"},
      {"fz_rr_kN", "fz", Corner::kRearRight, "kN"},
      {"slip_angle_rr_deg", "slip_angle", Corner::kRearRight, "deg"},
      {"slip_ratio_fr", "slip_ratio", Corner::kFrontRight, "1"},
      {"slip_ratio", "slip_ratio", std::nullopt, "1"},
      {"grip_factor_fl_1", "grip_factor", Corner::kFrontLeft, "1"},
      {"tread_temp_fl_C", "tread_temp", Corner::kFrontLeft, "C"},
      {"ambient_temp_K", "ambient_temp", std::nullopt, "K"},
      {"calliper_temp_rl_C", "calliper_temp", Corner::kRearLeft, "C"},
      {"wear_rr_mm", "wear", Corner::kRearRight, "mm"},
      {"rolling_radius_fl_mm", "rolling_radius", Corner::kFrontLeft, "mm"},
      {"brake_power_fr_kW", "brake_power", Corner::kFrontRight, "kW"},
      {"q7_rr_W", "q7", Corner::kRearRight, "W"},
  };
  for (const Case& c : cases) {
    const std::optional<ChannelName> name = ParseChannelName(c.column, "log.csv");
    ASSERT_TRUE(name.has_value()) << c.column;
    EXPECT_EQ(name->quantity, c.quantity) << c.column;
    EXPECT_EQ(name->corner, c.corner) << c.column;
    EXPECT_EQ(name->unit, c.unit) << c.column;
  }
}

TEST(ChannelNameTest, UnknownOrOffPatternNamesAreCarriedThrough) {
  for (const char* column : {"throttle_pct", "speedometer", "time_of_day", "tread_temp_fl_inner_C",
                             "q10_W", "q8_fl_W", "fx_front_N", "Speed_kph", "brake_pressure_bar"}) {
    EXPECT_FALSE(ParseChannelName(column, "log.csv").has_value()) << column;
  }
}

TEST(ChannelNameTest, KnownQuantityWithBadUnitIsAnError) {
  std::string message = InputErrorOf([] { ParseChannelName("fx_fl_lbf", "log.csv"); });
  EXPECT_TRUE(Contains(message, "log.csv: column 'fx_fl_lbf'"));
  EXPECT_TRUE(Contains(message, "unit 'lbf'"));
  EXPECT_TRUE(Contains(message, "'N' or 'kN'"));

  message = InputErrorOf([] { ParseChannelName("tread_temp_fl_c", "log.csv"); });
  EXPECT_TRUE(Contains(message, "unit 'c'"));
  EXPECT_TRUE(Contains(message, "'C' or 'K'"));

  message = InputErrorOf([] { ParseChannelName("time_ms", "log.csv"); });
  EXPECT_TRUE(Contains(message, "unit 'ms'"));
  EXPECT_TRUE(Contains(message, "'s'"));

  message = InputErrorOf([] { ParseChannelName("slip_ratio_fl_pct", "log.csv"); });
  EXPECT_TRUE(Contains(message, "unit 'pct'"));
  EXPECT_TRUE(Contains(message, "no unit suffix"));

  message = InputErrorOf([] { ParseChannelName("speed", "log.csv"); });
  EXPECT_TRUE(Contains(message, "log.csv: column 'speed' has no unit"));
  EXPECT_TRUE(Contains(message, "'speed_mps', 'speed_kph' or 'speed_mph'"));

  message = InputErrorOf([] { ParseChannelName("fx_fl", "log.csv"); });
  EXPECT_TRUE(Contains(message, "'fx_fl_N' or 'fx_fl_kN'"));

  message = InputErrorOf([] { ParseChannelName("time_fl_s", "log.csv"); });
  EXPECT_TRUE(Contains(message, "takes no corner"));
  EXPECT_TRUE(Contains(message, "'time_s'"));
}

TEST(ChannelNameTest, ChannelColumnIsCanonical) {
  EXPECT_EQ(ChannelColumn("tread_temp", Corner::kFrontLeft, "C"), "tread_temp_fl_C");
  EXPECT_EQ(ChannelColumn("slip_ratio", Corner::kFrontRight, "1"), "slip_ratio_fr");
  EXPECT_EQ(ChannelColumn("grip_factor", Corner::kFrontLeft, ""), "grip_factor_fl");
  EXPECT_EQ(ChannelColumn("time", std::nullopt, "s"), "time_s");
  EXPECT_EQ(ChannelColumn("q3", Corner::kRearRight, "W"), "q3_rr_W");
  // What ChannelColumn writes, ParseChannelName reads back.
  const auto name = ParseChannelName(ChannelColumn("disc_temp", Corner::kRearLeft, "K"), "");
  ASSERT_TRUE(name.has_value());
  EXPECT_EQ(name->quantity, "disc_temp");
  EXPECT_EQ(name->corner, Corner::kRearLeft);
  EXPECT_EQ(name->unit, "K");
}

TEST(ChannelNameTest, UnitTablesAndCanonicalConversion) {
  EXPECT_EQ(AcceptedUnits("speed"), (std::vector<std::string_view>{"mps", "kph", "mph"}));
  EXPECT_EQ(AcceptedUnits("slip_ratio"), (std::vector<std::string_view>{"1"}));
  EXPECT_EQ(CanonicalUnit("tread_temp"), "C");
  EXPECT_EQ(CanonicalUnit("rolling_radius"), "m");
  EXPECT_NEAR(ConvertSiToCanonical("tread_temp", 373.15), 100.0, kTol);
  EXPECT_EQ(ConvertSiToCanonical("fx", 1234.5), 1234.5);
  EXPECT_EQ(ConvertSiToCanonical("wear", 0.25), 0.25);
  EXPECT_TRUE(std::isnan(ConvertSiToCanonical("disc_temp", std::nan(""))));
  EXPECT_THROW(AcceptedUnits("throttle"), std::invalid_argument);
}

// ---- Reading ----

TEST_F(TelemetryTest, ConvertsEveryUnitToSi) {
  const fs::path path = tmp_.Write(
      "units.csv",
      "# track: darlington\n"
      "time_s,speed_kph,speed_fl_mph,fx_fl_kN,fy_fl_N,slip_angle_fl_deg,slip_angle_fr_rad,"
      "tread_temp_fl_C,disc_temp_fr_K,brake_power_fl_kW,rolling_radius_fl_mm,rolling_radius_fr_m,"
      "wear_fl_mm,grip_factor_fl,slip_ratio_fl,q1_fl_W\n"
      "0,36,10,1.5,-200,2,0.01,85,500,12.5,310,0.3,0.2,0.95,-0.05,100\n"
      "1,72,,,,,,,,,,,,,,\n");
  const Telemetry log = Telemetry::Read(path);
  ASSERT_EQ(log.size(), 2u);
  EXPECT_EQ(log.path(), path);
  EXPECT_EQ(log.metadata(),
            (std::vector<std::pair<std::string, std::string>>{{"track", "darlington"}}));
  EXPECT_EQ(log.index(), (std::vector<double>{0.0, 1.0}));
  EXPECT_NEAR(log.Channel("speed")[0], 10.0, kTol);
  EXPECT_NEAR(log.Channel("speed")[1], 20.0, kTol);
  EXPECT_NEAR(log.Channel("speed", Corner::kFrontLeft)[0], 4.4704, kTol);
  EXPECT_TRUE(std::isnan(log.Channel("speed", Corner::kFrontLeft)[1]));
  EXPECT_NEAR(log.Channel("fx", Corner::kFrontLeft)[0], 1500.0, kTol);
  EXPECT_NEAR(log.Channel("fy", Corner::kFrontLeft)[0], -200.0, kTol);
  EXPECT_NEAR(log.Channel("slip_angle", Corner::kFrontLeft)[0], 2.0 * std::numbers::pi / 180.0,
              kTol);
  EXPECT_NEAR(log.Channel("slip_angle", Corner::kFrontRight)[0], 0.01, kTol);
  EXPECT_NEAR(log.Channel("tread_temp", Corner::kFrontLeft)[0], 358.15, kTol);
  EXPECT_NEAR(log.Channel("disc_temp", Corner::kFrontRight)[0], 500.0, kTol);
  EXPECT_NEAR(log.Channel("brake_power", Corner::kFrontLeft)[0], 12500.0, kTol);
  EXPECT_NEAR(log.Channel("rolling_radius", Corner::kFrontLeft)[0], 0.31, kTol);
  EXPECT_NEAR(log.Channel("rolling_radius", Corner::kFrontRight)[0], 0.3, kTol);
  EXPECT_NEAR(log.Channel("wear", Corner::kFrontLeft)[0], 0.2, kTol);  // kept in mm
  EXPECT_NEAR(log.Channel("grip_factor", Corner::kFrontLeft)[0], 0.95, kTol);
  EXPECT_NEAR(log.Channel("slip_ratio", Corner::kFrontLeft)[0], -0.05, kTol);
  EXPECT_NEAR(log.Channel("q1", Corner::kFrontLeft)[0], 100.0, kTol);
  EXPECT_EQ(log.ColumnOf("fx", Corner::kFrontLeft), "fx_fl_kN");
  EXPECT_TRUE(log.unknown_columns().empty());
}

TEST_F(TelemetryTest, TpmsChannelsReadInPaAndKelvinAndRefusedWithoutAUnit) {
  const fs::path path = tmp_.Write("tpms.csv",
                                   "time_s,pressure_fl_psi,pressure_fr_kPa,pressure_rl_bar,"
                                   "gas_temp_fl_C,gas_temp_fr_K,rim_temp_fl_C\n"
                                   "0,20,330.95,1.5,60,350,45\n");
  const Telemetry log = Telemetry::Read(path);
  EXPECT_NEAR(log.Channel("pressure", Corner::kFrontLeft)[0], 20 * 6894.757293168361, 1e-6);
  EXPECT_NEAR(log.Channel("pressure", Corner::kFrontRight)[0], 330950.0, 1e-6);
  EXPECT_NEAR(log.Channel("pressure", Corner::kRearLeft)[0], 150000.0, 1e-6);
  EXPECT_NEAR(log.Channel("gas_temp", Corner::kFrontLeft)[0], 333.15, kTol);
  EXPECT_NEAR(log.Channel("gas_temp", Corner::kFrontRight)[0], 350.0, kTol);
  EXPECT_NEAR(log.Channel("rim_temp", Corner::kFrontLeft)[0], 318.15, kTol);
  EXPECT_EQ(ConvertSiToCanonical("pressure", 137895.14586336722), 137.89514586336722);
  // A TPMS column without its unit: which unit is meant (psi or kPa differ by 6.9) is not
  // guessed.
  const fs::path bare = tmp_.Write("bare.csv", "time_s,pressure_fl\n0,20\n");
  try {
    (void)Telemetry::Read(bare);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_TRUE(std::string(e.what()).find("bare.csv") != std::string::npos) << e.what();
    EXPECT_TRUE(std::string(e.what()).find("'pressure_fl_kPa'") != std::string::npos) << e.what();
  }
  const fs::path mbar = tmp_.Write("mbar.csv", "time_s,pressure_fl_mbar\n0,20\n");
  EXPECT_THROW((void)Telemetry::Read(mbar), InputError);
  // A pressure no tyre holds (a sensor's fault code, 3000 psi): refused with its value.
  const fs::path fault = tmp_.Write("fault.csv", "time_s,pressure_rr_psi\n0,44\n1,3000\n");
  try {
    (void)Telemetry::Read(fault);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_TRUE(std::string(e.what()).find("3000") != std::string::npos) << e.what();
  }
}

TEST_F(TelemetryTest, UnknownColumnsAreCarriedThroughRaw) {
  const Telemetry log = Telemetry::Read(
      tmp_.Write("log.csv", "throttle_pct,time_s,time_of_day,fx_fl_kN\n50,0,3600,1\n,1,3601,2\n"));
  ASSERT_EQ(log.unknown_columns().size(), 2u);
  EXPECT_EQ(log.unknown_columns()[0].first, "throttle_pct");
  EXPECT_EQ(log.unknown_columns()[0].second[0], 50.0);
  EXPECT_TRUE(std::isnan(log.unknown_columns()[0].second[1]));
  EXPECT_EQ(log.unknown_columns()[1].first, "time_of_day");
  EXPECT_EQ(log.unknown_columns()[1].second, (std::vector<double>{3600.0, 3601.0}));
  EXPECT_FALSE(log.Has("speed"));
  EXPECT_TRUE(log.Has("fx", Corner::kFrontLeft));
}

TEST_F(TelemetryTest, BadUnitInTheFileNamesTheFile) {
  const fs::path path = tmp_.Write("lbf.csv", "time_s,fx_fl_lbf\n0,1\n");
  const std::string message = InputErrorOf([&] { Telemetry::Read(path); });
  EXPECT_TRUE(Contains(message, path.string() + ": column 'fx_fl_lbf'"));
  EXPECT_TRUE(Contains(message, "'N' or 'kN'"));
}

TEST_F(TelemetryTest, ReadsADistanceIndexedFile) {
  const Telemetry log = Telemetry::Read(
      tmp_.Write("lap.csv", "distance_m,speed_mps,time_s\n0,50,0\n10,51,0.2\n20,52,0.39\n"),
      "distance");
  EXPECT_EQ(log.index_quantity(), "distance");
  EXPECT_EQ(log.index(), (std::vector<double>{0.0, 10.0, 20.0}));
  EXPECT_THROW(Telemetry::Read(dir_ / "lap.csv", "speed"), std::invalid_argument);
}

TEST_F(TelemetryTest, IndexMustBeStrictlyIncreasing) {
  const fs::path path = tmp_.Write("order.csv", "# a: b\ntime_s,x\n0,1\n0.5,2\n\n0.5,3\n");
  std::string message = InputErrorOf([&] { Telemetry::Read(path); });
  EXPECT_TRUE(Contains(message, path.string() + ":6:"));
  EXPECT_TRUE(Contains(message, "'time_s' must be strictly increasing"));
  EXPECT_TRUE(Contains(message, "0.5 follows 0.5 (line 4)"));

  const fs::path back = tmp_.Write("back.csv", "time_s,x\n0,1\n2,2\n1.5,3\n");
  message = InputErrorOf([&] { Telemetry::Read(back); });
  EXPECT_TRUE(Contains(message, back.string() + ":4:"));
  EXPECT_TRUE(Contains(message, "1.5 follows 2 (line 3)"));

  const fs::path gap = tmp_.Write("gap.csv", "time_s,x\n0,1\n,2\n");
  message = InputErrorOf([&] { Telemetry::Read(gap); });
  EXPECT_TRUE(Contains(message, gap.string() + ":3: 'time_s' is empty"));

  // A distance-indexed read checks distance, not time.
  const fs::path by_distance = tmp_.Write("d.csv", "distance_m,time_s\n0,5\n1,4\n1,3\n");
  message = InputErrorOf([&] { Telemetry::Read(by_distance, "distance"); });
  EXPECT_TRUE(Contains(message, by_distance.string() + ":4: 'distance_m'"));
}

TEST_F(TelemetryTest, MissingIndexListsWhatWasExpected) {
  const fs::path path = tmp_.Write("noindex.csv", "tme_s,x\n0,1\n");
  const std::string message = InputErrorOf([&] { Telemetry::Read(path); });
  EXPECT_TRUE(Contains(message, path.string() + ": missing column 'time_s'"));
  EXPECT_TRUE(Contains(message, "closest columns in the file: 'tme_s'"));
}

TEST_F(TelemetryTest, MissingChannelSuggestsTheClosestColumns) {
  const Telemetry log = Telemetry::Read(
      tmp_.Write("log.csv", "time_s,fx_fr_N,fy_rr_N,throttle_pct\n0,1,2,3\n1,1,2,3\n"));
  std::string message = InputErrorOf([&] { log.Channel("fx", Corner::kFrontLeft); });
  EXPECT_TRUE(Contains(message, "log.csv: missing column 'fx_fl_N' or 'fx_fl_kN'"));
  EXPECT_TRUE(Contains(message, "closest columns in the file: 'fx_fr_N'"));
  EXPECT_FALSE(Contains(message, "throttle_pct"));

  message = InputErrorOf([&] { log.Channel("tread_temp", Corner::kRearLeft); });
  EXPECT_TRUE(Contains(message, "'tread_temp_rl_C' or 'tread_temp_rl_K'"));
  EXPECT_TRUE(Contains(message, "no similar column in the file"));

  message = InputErrorOf([&] { log.FilledChannel("slip_ratio", Corner::kRearLeft); });
  EXPECT_TRUE(Contains(message, "missing column 'slip_ratio_rl'"));
  message = InputErrorOf([&] { log.ColumnOf("fz", Corner::kFrontRight); });
  EXPECT_TRUE(Contains(message, "'fz_fr_N' or 'fz_fr_kN'"));
}

TEST_F(TelemetryTest, TwoColumnsForOneChannelAreAnError) {
  const fs::path path = tmp_.Write("dup.csv", "time_s,speed_mps,fx_fl_N,speed_kph\n0,1,2,3\n");
  std::string message = InputErrorOf([&] { Telemetry::Read(path); });
  EXPECT_TRUE(Contains(message, path.string() + ": columns 'speed_mps' (column 2) and "
                                                "'speed_kph' (column 4)"));
  // Corner channels too, and a dimensionless one written both ways.
  message = InputErrorOf(
      [&] { Telemetry::Read(tmp_.Write("dup2.csv", "time_s,fx_fl_N,fx_fl_kN\n0,1,2\n")); });
  EXPECT_TRUE(Contains(message, "'fx_fl_N' (column 2) and 'fx_fl_kN' (column 3)"));
  message = InputErrorOf([&] {
    Telemetry::Read(tmp_.Write("dup3.csv", "time_s,slip_ratio_fl,slip_ratio_fl_1\n0,1,2\n"));
  });
  EXPECT_TRUE(Contains(message, "'slip_ratio_fl' (column 2) and 'slip_ratio_fl_1' (column 3)"));
}

TEST_F(TelemetryTest, FilledChannelInterpolatesInTheIndex) {
  // Uneven time steps: interpolation must follow time, not the row number.
  const Telemetry log = Telemetry::Read(tmp_.Write(
      "gaps.csv", "time_s,tread_temp_fl_C,fz_fl_N\n0,,1\n1,,\n2,80,\n3,,\n6,,\n7,90,\n8,,\n9,,\n"));
  const std::vector<double>& raw = log.Channel("tread_temp", Corner::kFrontLeft);
  EXPECT_TRUE(std::isnan(raw[0]));
  const std::vector<double> filled = log.FilledChannel("tread_temp", Corner::kFrontLeft);
  const std::vector<double> expected_c = {80, 80, 80, 82, 88, 90, 90, 90};
  ASSERT_EQ(filled.size(), expected_c.size());
  for (size_t i = 0; i < filled.size(); ++i) {
    EXPECT_NEAR(filled[i], expected_c[i] + 273.15, 1e-9) << "row " << i;
  }
  // A single measured value is held everywhere.
  EXPECT_EQ(log.FilledChannel("fz", Corner::kFrontLeft), std::vector<double>(8, 1.0));
}

TEST_F(TelemetryTest, FilledChannelWithNoValueIsAnError) {
  const fs::path path = tmp_.Write("empty.csv", "time_s,wear_fl_mm\n0,\n1,\n");
  const Telemetry log = Telemetry::Read(path);
  const std::string message = InputErrorOf([&] { log.FilledChannel("wear", Corner::kFrontLeft); });
  EXPECT_TRUE(Contains(message, path.string() + ": column 'wear_fl_mm' has no value on any row"));
  EXPECT_FALSE(log.FirstValue("wear", Corner::kFrontLeft).has_value());
}

TEST_F(TelemetryTest, CornerSpeedPrefersTheCornerChannel) {
  const Telemetry log = Telemetry::Read(
      tmp_.Write("speed.csv", "time_s,speed_kph,speed_fl_mps\n0,36,11\n1,72,\n2,108,13\n"));
  EXPECT_EQ(log.CornerSpeed(Corner::kFrontLeft), (std::vector<double>{11.0, 12.0, 13.0}));
  const std::vector<double> rear = log.CornerSpeed(Corner::kRearRight);
  ASSERT_EQ(rear.size(), 3u);
  EXPECT_NEAR(rear[0], 10.0, kTol);
  EXPECT_NEAR(rear[2], 30.0, kTol);
  EXPECT_TRUE(log.Has("speed", Corner::kFrontLeft));
  EXPECT_FALSE(log.Has("speed", Corner::kRearRight));  // the whole-car channel does not count
}

TEST_F(TelemetryTest, CornerSpeedWithNoSpeedListsBothNames) {
  const Telemetry log = Telemetry::Read(tmp_.Write("nospeed.csv", "time_s,sped_mps\n0,1\n1,2\n"));
  const std::string message = InputErrorOf([&] { log.CornerSpeed(Corner::kRearLeft); });
  EXPECT_TRUE(Contains(message, "'speed_rl_mps', 'speed_rl_kph' or 'speed_rl_mph'"));
  EXPECT_TRUE(Contains(message, "'speed_mps', 'speed_kph' or 'speed_mph'"));
  EXPECT_TRUE(Contains(message, "closest columns in the file: 'sped_mps'"));
}

TEST_F(TelemetryTest, FirstValueSkipsEmptyCellsAndIsInSi) {
  const Telemetry log = Telemetry::Read(
      tmp_.Write("first.csv", "time_s,ambient_temp_C,fx_fl_kN\n0,,\n1,25,\n2,26,\n"));
  ASSERT_TRUE(log.FirstValue("ambient_temp").has_value());
  EXPECT_NEAR(*log.FirstValue("ambient_temp"), 298.15, kTol);
  EXPECT_FALSE(log.FirstValue("fx", Corner::kFrontLeft).has_value());
  EXPECT_FALSE(log.FirstValue("track_temp").has_value());
}

TEST_F(TelemetryTest, LineOfCountsMetadataAndBlankLines) {
  const Telemetry log =
      Telemetry::Read(tmp_.Write("lines.csv", "# a: 1\n\ntime_s,x\n0,1\n\n\n1,2\n"));
  EXPECT_EQ(log.LineOf(0), 4);
  EXPECT_EQ(log.LineOf(1), 7);
  EXPECT_THROW(log.LineOf(2), std::out_of_range);
}

TEST_F(TelemetryTest, AskingForAnUnknownQuantityIsAProgrammingError) {
  const Telemetry log = Telemetry::Read(tmp_.Write("log.csv", "time_s\n0\n"));
  EXPECT_THROW(log.Channel("throttle"), std::invalid_argument);
  EXPECT_THROW(log.Has("fxx", Corner::kFrontLeft), std::invalid_argument);
  EXPECT_THROW(log.Channel("time", Corner::kFrontLeft), std::invalid_argument);
}

TEST_F(TelemetryTest, RewriteInCanonicalUnitsReadsBackTheSame) {
  const Telemetry log = Telemetry::Read(tmp_.Write(
      "in.csv", "# car: gt3\ntime_s,tread_temp_fr_K,speed_kph,lap_flag\n0,350,100,1\n0.1,,101,\n"));
  // Write canonical units, as a result writer would, then read again.
  std::vector<std::string> columns;
  std::vector<std::vector<double>> values;
  for (const auto& [quantity, corner] : std::vector<std::pair<std::string, std::optional<Corner>>>{
           {"time", std::nullopt}, {"tread_temp", Corner::kFrontRight}, {"speed", std::nullopt}}) {
    columns.push_back(ChannelColumn(quantity, corner, CanonicalUnit(quantity)));
    std::vector<double> column = log.Channel(quantity, corner);
    for (double& v : column) v = ConvertSiToCanonical(quantity, v);
    values.push_back(std::move(column));
  }
  for (const auto& [name, raw] : log.unknown_columns()) {
    columns.push_back(name);
    values.push_back(raw);
  }
  const fs::path out = dir_ / "out.csv";
  WriteCsv(out, log.metadata(), columns, values);
  EXPECT_EQ(ReadCsv(out).columns,
            (std::vector<std::string>{"time_s", "tread_temp_fr_C", "speed_mps", "lap_flag"}));

  const Telemetry again = Telemetry::Read(out);
  EXPECT_EQ(again.metadata(), log.metadata());
  for (const char* quantity : {"time", "speed"}) {
    for (size_t i = 0; i < 2; ++i) {
      EXPECT_NEAR(again.Channel(quantity)[i], log.Channel(quantity)[i],
                  1e-12 * std::abs(log.Channel(quantity)[i]));
    }
  }
  EXPECT_NEAR(again.Channel("tread_temp", Corner::kFrontRight)[0], 350.0, 1e-9);
  EXPECT_TRUE(std::isnan(again.Channel("tread_temp", Corner::kFrontRight)[1]));
  EXPECT_EQ(again.unknown_columns()[0].first, "lap_flag");
}

// ---- Columns in memory (the Python module's logs) ----

TEST_F(TelemetryTest, FromTableReadsColumnsAsReadReadsTheSameFile) {
  const fs::path path = tmp_.Write("log.csv",
                                   "time_s,speed_kph,slip_angle_fl_deg,lap_flag\n"
                                   "0,180,1.5,0\n0.1,,2,1\n0.2,190,2.5,1\n");
  const Telemetry from_file = Telemetry::Read(path);
  CsvTable table;
  table.path = "<columns>";
  table.columns = {"time_s", "speed_kph", "slip_angle_fl_deg", "lap_flag"};
  table.values = {{0.0, 0.1, 0.2},
                  {180.0, std::numeric_limits<double>::quiet_NaN(), 190.0},
                  {1.5, 2.0, 2.5},
                  {0.0, 1.0, 1.0}};
  const Telemetry in_memory = Telemetry::FromTable(table);
  ASSERT_EQ(in_memory.size(), 3u);
  EXPECT_EQ(in_memory.path(), fs::path("<columns>"));
  for (const auto& [quantity, corner] :
       {std::pair<const char*, std::optional<Corner>>{"time", std::nullopt},
        {"speed", std::nullopt},
        {"slip_angle", Corner::kFrontLeft}}) {
    const std::vector<double> a = from_file.FilledChannel(quantity, corner);
    const std::vector<double> b = in_memory.FilledChannel(quantity, corner);
    ASSERT_EQ(a.size(), b.size());
    for (size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i], b[i]) << quantity << " row " << i;
  }
  EXPECT_NEAR(in_memory.Channel("speed")[2], 190.0 / 3.6, kTol);
  ASSERT_EQ(in_memory.unknown_columns().size(), 1u);
  EXPECT_EQ(in_memory.unknown_columns()[0].first, "lap_flag");
}

TEST_F(TelemetryTest, FromTableRefusesRaggedRepeatedInfiniteAndUnorderedColumns) {
  CsvTable table;
  table.path = "<python dict>";
  table.columns = {"time_s", "speed_mps"};
  table.values = {{0.0, 1.0}, {50.0}};
  EXPECT_TRUE(Contains(InputErrorOf([&] { Telemetry::FromTable(table); }),
                       "<python dict>: column 'speed_mps' has 1 values"));
  table.columns = {"time_s", "time_s"};
  table.values = {{0.0, 1.0}, {0.0, 1.0}};
  EXPECT_TRUE(Contains(InputErrorOf([&] { Telemetry::FromTable(table); }), "given twice"));
  table.columns = {"time_s", "speed_mps"};
  table.values = {{0.0, 1.0}, {50.0, std::numeric_limits<double>::infinity()}};
  EXPECT_TRUE(Contains(InputErrorOf([&] { Telemetry::FromTable(table); }),
                       "column 'speed_mps', row 2: inf is not a finite number"));
  table.values = {{0.0, 0.0}, {50.0, 51.0}};
  // Rows numbered as lines under a header: the second row is line 3.
  EXPECT_TRUE(Contains(InputErrorOf([&] { Telemetry::FromTable(table); }),
                       "<python dict>:3: 'time_s' must be strictly increasing"));
  table.values = {{}, {}};
  EXPECT_TRUE(Contains(InputErrorOf([&] { Telemetry::FromTable(table); }), "no data rows"));
}

}  // namespace
}  // namespace hotlap
