// The MoTeC i2 CSV reader: the fixture laid out as i2 exports it reads to the same channels as
// the hotlap CSV of the same numbers; laps split at the beacons; --lap; bad files refused with
// FILE:LINE messages; the channel map's unit conversions against hand-computed values.

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "hotlap/logs/lap_select.h"
#include "hotlap/logs/motec_channel_map.h"
#include "hotlap/logs/motec_csv.h"
#include "hotlap/logs/telemetry.h"
#include "test_util.h"

namespace hotlap {
namespace {

namespace fs = std::filesystem;
using test::Contains;
using test::ReadTextFile;
using test::ReplaceOnce;
using test::WriteTextFile;

const fs::path kMotec = test::SourcePath("tests/data/motec/darlington_i2.csv");
const fs::path kEquivalent = test::SourcePath("tests/data/motec/darlington_i2_equivalent.csv");
const fs::path kMap = test::SourcePath("data/motec_channels.yaml");

std::string Value(const Telemetry& log, const std::string& key) {
  for (const auto& [k, v] : log.metadata()) {
    if (k == key) return v;
  }
  return "<absent>";
}

TEST(MotecCsvTest, RecognisedByItsFirstRecord) {
  EXPECT_TRUE(IsMotecCsv(kMotec));
  EXPECT_FALSE(IsMotecCsv(kEquivalent));
  EXPECT_FALSE(IsMotecCsv("/no/such/file.csv"));
}

TEST(MotecCsvTest, MetadataFromBothKeyColumnsAndTheBeacons) {
  const Telemetry log = Telemetry::Read(kMotec, "time", {kMap, std::nullopt});
  EXPECT_EQ(Value(log, "Format"), "MoTeC CSV File");
  EXPECT_EQ(Value(log, "Workbook"), "hotlap.mtc");
  EXPECT_EQ(Value(log, "Venue"), "Darlington");
  EXPECT_EQ(Value(log, "Vehicle"), "Gen7 #48");
  EXPECT_EQ(Value(log, "Driver"), "A. Driver");
  EXPECT_EQ(Value(log, "Device"), "M150");
  EXPECT_EQ(Value(log, "Comment"), "");
  EXPECT_EQ(Value(log, "Session"), "Practice 1");
  EXPECT_EQ(Value(log, "Log Date"), "14/03/2026");
  EXPECT_EQ(Value(log, "Log Time"), "10:32:05");
  EXPECT_EQ(Value(log, "Origin Time"), "0.000 s");
  EXPECT_EQ(Value(log, "Sample Rate"), "10.000 Hz");
  EXPECT_EQ(Value(log, "End Time"), "29.000 s");
  EXPECT_EQ(Value(log, "Duration"), "29.000 s");
  EXPECT_EQ(Value(log, "Beacon Markers"), "9.650 19.350");
  EXPECT_EQ(Value(log, "laps"), "3");
  EXPECT_EQ(Value(log, "unmapped channels"), "G Force Lat, Engine RPM");
  EXPECT_EQ(log.size(), 291u);
  EXPECT_EQ(log.LineOf(0), 18);  // the first data row, after the blank line under the units
}

TEST(MotecCsvTest, SameChannelsAsTheHotlapCsvOfTheSameNumbers) {
  const Telemetry motec = Telemetry::Read(kMotec);
  const Telemetry csv = Telemetry::Read(kEquivalent);
  ASSERT_EQ(motec.size(), csv.size());
  EXPECT_EQ(motec.index(), csv.index());
  EXPECT_EQ(motec.Channel("distance"), csv.Channel("distance"));
  EXPECT_EQ(motec.Channel("speed"), csv.Channel("speed"));
  EXPECT_EQ(motec.Channel("ambient_temp"), csv.Channel("ambient_temp"));
  EXPECT_EQ(motec.Channel("track_temp"), csv.Channel("track_temp"));
  for (Corner c : kAllCorners) {
    for (const char* q : {"fx", "fy", "fz", "slip_angle", "slip_ratio", "disc_temp"}) {
      EXPECT_EQ(motec.Channel(q, c), csv.Channel(q, c)) << q << "_" << CornerName(c);
    }
  }
  ASSERT_EQ(motec.unknown_columns().size(), csv.unknown_columns().size());
  for (size_t i = 0; i < csv.unknown_columns().size(); ++i) {
    EXPECT_EQ(motec.unknown_columns()[i].first, csv.unknown_columns()[i].first);
    EXPECT_EQ(motec.unknown_columns()[i].second, csv.unknown_columns()[i].second);
  }
}

TEST(MotecCsvTest, LapsSplitAtTheBeacons) {
  EXPECT_EQ(MotecLapAt(0.0, {9.65, 19.35}), 1);
  EXPECT_EQ(MotecLapAt(9.6, {9.65, 19.35}), 1);
  EXPECT_EQ(MotecLapAt(9.65, {9.65, 19.35}), 2);
  EXPECT_EQ(MotecLapAt(19.35, {9.65, 19.35}), 3);
  EXPECT_EQ(MotecLapAt(5.0, {}), 1);

  const Telemetry lap2 = Telemetry::Read(kMotec, "time", {.lap = 2});
  EXPECT_NEAR(lap2.index().front(), 9.7, 1e-12);
  EXPECT_NEAR(lap2.index().back(), 19.3, 1e-12);
  EXPECT_EQ(lap2.size(), 97u);
  const Telemetry lap1 = Telemetry::Read(kMotec, "time", {.lap = 1});
  const Telemetry lap3 = Telemetry::Read(kMotec, "time", {.lap = 3});
  EXPECT_NEAR(lap1.index().back(), 9.6, 1e-12);
  EXPECT_NEAR(lap3.index().front(), 19.4, 1e-12);
  EXPECT_EQ(lap1.size() + lap2.size() + lap3.size(), 291u);
  EXPECT_EQ(lap2.LineOf(0), 18 + 97);  // the file's own line numbers

  // The same from the hotlap CSV's lap column.
  EXPECT_EQ(Telemetry::Read(kEquivalent, "time", {.lap = 2}).index(), lap2.index());
}

TEST(MotecCsvTest, LapOutOfRangeNamesTheLapsThereAre) {
  const std::string m = test::InputErrorOf([] { Telemetry::Read(kMotec, "time", {.lap = 4}); });
  EXPECT_TRUE(Contains(m, "darlington_i2.csv: lap 4: no such lap; the log has laps 1 to 3"));
  const std::string none = test::InputErrorOf([] {
    Telemetry::Read(test::SourcePath("data/telemetry/darlington_example.csv"), "time", {.lap = 1});
  });
  EXPECT_TRUE(Contains(none, "no 'lap' column"));
}

TEST(MotecCsvTest, MissingChannelNamesTheMotecChannelsThatMapToIt) {
  test::TempDir dir;
  std::string text = ReadTextFile(kMotec);
  text = ReplaceOnce(text, "\"Tyre Load FL\"", "\"Load FL\"");
  const Telemetry log = Telemetry::Read(WriteTextFile(dir.path() / "m.csv", text));
  const std::string m = test::InputErrorOf([&] { log.Channel("fz", Corner::kFrontLeft); });
  EXPECT_TRUE(Contains(m, "missing column 'fz_fl_N' or 'fz_fl_kN'"));
  EXPECT_TRUE(Contains(m, "'Tyre Load FL'"));
  EXPECT_TRUE(Contains(m, "motec_channels.yaml"));
  EXPECT_TRUE(Contains(Value(log, "unmapped channels"), "Load FL"));
}

// A copy of the fixture with one edit, read; the InputError's message.
std::string ErrorOfEdited(const std::string& from, const std::string& to) {
  test::TempDir dir;
  const fs::path file =
      WriteTextFile(dir.path() / "bad.csv", ReplaceOnce(ReadTextFile(kMotec), from, to));
  return test::InputErrorOf([&] { Telemetry::Read(file); });
}

// An unmapped channel with text in it (a gear shown as "N") is left out and said so in the
// metadata (the whole log was refused); text in a mapped channel is still an error.
TEST(MotecCsvTest, AnUnmappedChannelWithTextIsLeftOut) {
  test::TempDir dir;
  const std::string text = ReadTextFile(kMotec);
  const fs::path file = WriteTextFile(dir.path() / "gear.csv",
                                      ReplaceOnce(text, "\"1.250\",\"8000\"", "\"N\",\"8000\""));
  const Telemetry log = Telemetry::Read(file);
  EXPECT_EQ(Value(log, "unmapped channels"), "Engine RPM");
  EXPECT_EQ(Value(log, "channels left out (text, not numbers)"), "G Force Lat");
  EXPECT_EQ(log.size(), 291u);
  for (const auto& [name, values] : log.unknown_columns()) EXPECT_NE(name, "G Force Lat");
  EXPECT_TRUE(
      Contains(ErrorOfEdited("\"0.300\",\"22.70\",\"273.015\"", "\"0.300\",\"22.70\",\"fast\""),
               "is not a number"));
}

TEST(MotecCsvTest, BadFilesRefusedWithFileAndLine) {
  // A ragged row (line 20: the third data row).
  EXPECT_TRUE(
      Contains(ErrorOfEdited("\"0.200\",", "\"0.200\",\"1\","),
               "bad.csv:20: this row has 32 cells, but the channel names row (line 15) 31"));
  // Text in a number cell.
  EXPECT_TRUE(
      Contains(ErrorOfEdited("\"0.300\",\"22.70\",\"273.015\"", "\"0.300\",\"22.70\",\"fast\""),
               "bad.csv:21: channel 'Ground Speed' (column 3): 'fast' is not a number"));
  // No units row.
  const std::string units = "\"s\",\"m\",\"km/h\"";
  const std::string text = ReadTextFile(kMotec);
  const size_t begin = text.find(units);
  const size_t end = text.find('\n', begin);
  EXPECT_TRUE(Contains(ErrorOfEdited(text.substr(begin, end - begin + 1), ""),
                       "bad.csv:17: expected the units row"));
  // No data.
  EXPECT_TRUE(Contains(ErrorOfEdited(text.substr(end + 1), ""),
                       "bad.csv:16: no data rows under the units row"));
  // No channel names row.
  EXPECT_TRUE(
      Contains(ErrorOfEdited(text.substr(text.find("\"Time\",")), ""), "no channel names row"));
  // A mapped channel with an unknown unit, and with a unit of another kind.
  EXPECT_TRUE(Contains(ErrorOfEdited("\"s\",\"m\",\"km/h\"", "\"s\",\"m\",\"knots\""),
                       "bad.csv:16: channel 'Ground Speed' (column 3): unknown unit 'knots'"));
  EXPECT_TRUE(Contains(ErrorOfEdited("\"s\",\"m\",\"km/h\"", "\"s\",\"m\",\"bar\""),
                       "unit 'bar' is not a unit of speed"));
  // Beacons not numbers.
  EXPECT_TRUE(Contains(ErrorOfEdited("\"9.650\"", "\"x\""),
                       "bad.csv:12: Beacon Markers (column 2): 'x' is not a number"));
  // An unclosed quote.
  EXPECT_TRUE(Contains(ErrorOfEdited("\"0.400\"", "\"0.400"),
                       "bad.csv:22: text after the closing quote of cell 1"));
}

// An export with the ';' list separator and ',' decimals of a European Windows locale is named for
// what it is (it was read as a hotlap CSV and failed on its second line's "not a number").
TEST(MotecCsvTest, ASemicolonSeparatedExportIsNamed) {
  test::TempDir dir;
  const fs::path path =
      dir.Write("eu.csv",
                "\"Format\";\"MoTeC CSV File\";;;\"Workbook\";\"x.mtc\"\r\n"
                "\"Venue\";\"Spa\"\r\n\r\n\"Time\";\"Ground Speed\"\r\n\"s\";\"km/h\"\r\n"
                "\"0,000\";\"100,5\"\r\n");
  try {
    Telemetry::Read(path);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_TRUE(Contains(e.what(), "eu.csv:1: a MoTeC CSV export with ';' between its cells"))
        << e.what();
  }
}

TEST(MotecChannelMapTest, UnitConversionsAgainstHandComputedValues) {
  const auto convert = [](double v, const char* unit, const char* quantity) {
    return MotecConversionFor(unit, quantity, "test").Apply(v);
  };
  EXPECT_NEAR(convert(180.0, "km/h", "speed"), 50.0, 1e-12);   // 180 / 3.6
  EXPECT_NEAR(convert(100.0, "mph", "speed"), 44.704, 1e-12);  // 1609.344 m / 3600 s
  EXPECT_NEAR(convert(12.5, "m/s", "speed"), 12.5, 0.0);
  EXPECT_NEAR(convert(212.0, "degF", "disc_temp"), 100.0, 1e-12);  // (212 - 32) * 5 / 9
  EXPECT_NEAR(convert(-40.0, "degF", "tread_temp"), -40.0, 1e-12);
  EXPECT_NEAR(convert(104.0, "F", "track_temp"), 40.0, 1e-12);
  // The degree sign in UTF-8 and as a Windows export's single Latin-1 byte 0xB0.
  EXPECT_NEAR(convert(212.0, "\u00B0F", "disc_temp"), 100.0, 1e-12);
  EXPECT_NEAR(convert(212.0,
                      "\xB0"
                      "F",
                      "disc_temp"),
              100.0, 1e-12);
  EXPECT_NEAR(convert(300.0,
                      "\xB0"
                      "C",
                      "disc_temp"),
              300.0, 0.0);
  EXPECT_NEAR(convert(773.15, "K", "disc_temp"), 500.0, 1e-12);  // degC
  EXPECT_NEAR(convert(85.0, "degC", "ambient_temp"), 85.0, 0.0);
  EXPECT_NEAR(convert(2.5, "kN", "fz"), 2500.0, 0.0);
  EXPECT_NEAR(convert(-300.0, "N", "fx"), -300.0, 0.0);
  EXPECT_NEAR(convert(90.0, "deg", "slip_angle"), std::numbers::pi / 2, 1e-15);
  EXPECT_NEAR(convert(5.0, "%", "slip_ratio"), 0.05, 1e-15);
  EXPECT_NEAR(convert(330.0, "mm", "rolling_radius"), 0.33, 1e-15);
  EXPECT_NEAR(convert(1.5, "mm", "wear"), 1.5, 1e-15);  // wear is in mm
  EXPECT_NEAR(convert(2.0, "kW", "brake_power"), 2000.0, 0.0);
  // TPMS: the inflation pressure to kPa, the gas temperature to degC.
  EXPECT_NEAR(convert(48.0, "psi", "pressure"), 330.948350072, 1e-9);  // 48 x 6.894757293
  EXPECT_NEAR(convert(2.2, "bar", "pressure"), 220.0, 1e-12);
  EXPECT_NEAR(convert(185.0, "degF", "gas_temp"), 85.0, 1e-12);
  EXPECT_FALSE(test::InputErrorOf([] {
                 MotecConversionFor("degC", "pressure", "ch 'Tyre Pres FL'");
               }).empty());
  // Units of kinds hotlap has no channel for are known, and refused for a channel of another kind.
  for (const char* unit : {"bar", "psi", "kPa", "g", "rpm", "rad"}) EXPECT_TRUE(IsMotecUnit(unit));
  EXPECT_TRUE(Contains(test::InputErrorOf([] { MotecConversionFor("g", "speed", "ch 'Lat G'"); }),
                       "ch 'Lat G': unit 'g' is not a unit of speed (it takes 'km/h', 'mph' or "
                       "'m/s')"));
  EXPECT_TRUE(Contains(test::InputErrorOf([] { MotecConversionFor("furlong", "fx", "ch 'X'"); }),
                       "ch 'X': unknown unit 'furlong'"));
}

TEST(MotecChannelMapTest, ShippedMapAndBadMaps) {
  const MotecChannelMap map = LoadMotecChannelMap(kMap);
  ASSERT_NE(map.Find("Wheel Speed FL"), nullptr);
  EXPECT_EQ(map.Find("Wheel Speed FL")->quantity, "speed");
  EXPECT_EQ(map.Find("Wheel Speed FL")->corner, Corner::kFrontLeft);
  EXPECT_EQ(map.Find("Brake Disc Temp RR")->quantity, "disc_temp");
  EXPECT_EQ(map.Find("Track Temp")->corner, std::nullopt);
  EXPECT_EQ(map.Find("Tyre Pres RF"), nullptr);  // MoTeC's corner order is FL FR RL RR
  EXPECT_EQ(map.Find("Tyre Pres FR")->quantity, "pressure");
  EXPECT_EQ(map.Find("Tyre Pres FR")->corner, Corner::kFrontRight);
  EXPECT_EQ(map.Find("TPMS Temp RL")->quantity, "gas_temp");
  EXPECT_EQ(map.NamesFor("speed", std::nullopt),
            (std::vector<std::string>{"Ground Speed", "Corr Speed", "Vehicle Speed"}));

  test::TempDir dir;
  const auto error_of_map = [&](const std::string& text) {
    const fs::path file = WriteTextFile(dir.path() / "map.yaml", text);
    return test::InputErrorOf([&] { LoadMotecChannelMap(file); });
  };
  EXPECT_TRUE(Contains(error_of_map("channels:\n  Speed: velocity\n"),
                       "map.yaml:2: 'Speed': 'velocity' is not a hotlap channel"));
  EXPECT_TRUE(Contains(error_of_map("channels:\n  T: time_fl\n"), "'time_fl' is not a hotlap"));
  EXPECT_TRUE(Contains(error_of_map("chanels:\n  T: time\n"), "a channel map is a mapping"));
  EXPECT_TRUE(Contains(error_of_map("channels: [a\n"), "map.yaml:"));
}

TEST(MotecChannelMapTest, ACustomMapAndTheFirstOfTwoNamesForOneChannel) {
  test::TempDir dir;
  std::string text = ReadTextFile(kMotec);
  text = ReplaceOnce(text, "\"g\",\"rpm\"", "\"g\",\"m/s\"");
  const fs::path log_path = WriteTextFile(dir.path() / "m.csv", text);
  // Engine RPM (the file's last column) comes first in the map, so it is the speed: 8000 "m/s",
  // which the physical limits refuse, naming the value.
  const fs::path rpm_first = WriteTextFile(
      dir.path() / "rpm_first.yaml", "channels:\n  Engine RPM: speed\n  Ground Speed: speed\n");
  try {
    Telemetry::Read(log_path, "time", {rpm_first, std::nullopt});
    ADD_FAILURE() << "8000 m/s read as a speed";
  } catch (const InputError& e) {
    EXPECT_TRUE(Contains(e.what(), "'speed_mps' is 8000")) << e.what();
  }
  // Map only the speed; Distance gives distance without an entry, like Time.
  const fs::path map = WriteTextFile(dir.path() / "map.yaml",
                                     "channels:\n  Ground Speed: speed\n  Engine RPM: speed\n");
  const Telemetry log = Telemetry::Read(log_path, "time", {map, std::nullopt});
  EXPECT_EQ(log.ColumnOf("speed"), "speed_mps");
  EXPECT_LT(log.Channel("speed").front(), 150.0);  // Ground Speed, in km/h, converted
  EXPECT_TRUE(log.Has("distance"));
  EXPECT_FALSE(log.Has("fz", Corner::kFrontLeft));
  EXPECT_TRUE(Contains(Value(log, "unmapped channels"), "Engine RPM"));
}

}  // namespace
}  // namespace hotlap
