// A .ld log as a hotlap table: resampling onto one time base against hand values, the channel
// map and units, the .ldx beacons as laps, and the metadata.

#include "hotlap/logs/motec_ld_table.h"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/logs/lap_select.h"
#include "hotlap/logs/motec_ld_writer.h"
#include "test_util.h"

namespace hotlap {
namespace {

using test::Contains;
using test::InputErrorOf;

LdChannel Channel(const std::string& name, const std::string& unit, int rate_hz,
                  std::vector<double> values) {
  LdChannel c;
  c.name = name;
  c.unit = unit;
  c.rate_hz = rate_hz;
  c.values = std::move(values);
  return c;
}

MotecChannelMap Map() {
  MotecChannelMap map;
  map.path = "map.yaml";
  map.entries = {{"Ground Speed", "speed", std::nullopt},
                 {"Brake Temp FL", "disc_temp", Corner::kFrontLeft}};
  return map;
}

size_t Column(const CsvTable& t, const std::string& name) {
  const int c = t.ColumnIndex(name);
  if (c < 0) throw std::runtime_error("no column " + name);
  return static_cast<size_t>(c);
}

TEST(ResampleLinearTest, HandValues) {
  // 4 Hz onto 10 Hz: samples at 0, 0.25, 0.5, 0.75 s; times 0, 0.1, ..., 0.7 s.
  const std::vector<double> v = ResampleLinear({0.0, 10.0, 30.0, 20.0}, 4.0, 10.0, 10);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> want = {0.0, 4.0, 8.0, 14.0, 22.0, 30.0, 26.0, 22.0, nan, nan};
  ASSERT_EQ(v.size(), want.size());
  for (size_t k = 0; k < want.size(); ++k) {
    if (std::isnan(want[k])) {
      EXPECT_TRUE(std::isnan(v[k])) << k;
    } else {
      EXPECT_NEAR(v[k], want[k], 1e-12) << k;
    }
  }
  // A rate that divides the base: the samples themselves, exactly, on their times.
  const std::vector<double> same = ResampleLinear({1.0 / 3.0, 2.0 / 3.0}, 5.0, 20.0, 5);
  EXPECT_EQ(same[0], 1.0 / 3.0);
  EXPECT_EQ(same[4], 2.0 / 3.0);
  EXPECT_NEAR(same[1], 1.0 / 3.0 + 0.25 / 3.0, 1e-15);
  // A NaN neighbour gives NaN, the other side of it does not.
  const std::vector<double> gap = ResampleLinear({1.0, std::nan(""), 3.0, 4.0}, 1.0, 2.0, 7);
  EXPECT_EQ(gap[0], 1.0);
  EXPECT_TRUE(std::isnan(gap[1]));
  EXPECT_TRUE(std::isnan(gap[2]));
  EXPECT_TRUE(std::isnan(gap[3]));
  EXPECT_EQ(gap[4], 3.0);
  EXPECT_EQ(gap[5], 3.5);
  EXPECT_EQ(gap[6], 4.0);
  // Faster than the base: every other sample.
  EXPECT_EQ(ResampleLinear({0, 1, 2, 3, 4}, 20.0, 10.0, 3), (std::vector<double>{0, 2, 4}));
}

TEST(MotecLdTableTest, ChannelsAtTheirOwnRatesOnTheFastestRate) {
  LdLog log;
  log.path = "multi.ld";
  log.metadata.venue = "Darlington";
  log.metadata.driver = "A. Driver";
  // Speed 10 Hz in km/h over 0.5 s; brake temperature 2 Hz in degF over 0.5 s; rpm 4 Hz over
  // 0.25 s (unmapped, ends early).
  log.channels = {Channel("Ground Speed", "km/h", 10, {36, 72, 108, 144, 180, 216}),
                  Channel("Brake Temp FL", "degF", 2, {212, 32}),
                  Channel("Engine RPM", "rpm", 4, {1000, 2000})};
  const MotecTable t = MotecLdTable(log, Map(), std::nullopt);
  const CsvTable& table = t.table;
  EXPECT_EQ(table.columns, (std::vector<std::string>{"time_s", "speed_mps", "disc_temp_fl_C",
                                                     "Engine RPM", "lap"}));
  ASSERT_EQ(table.RowCount(), 6u);
  const auto& time = table.values[Column(table, "time_s")];
  const auto& speed = table.values[Column(table, "speed_mps")];
  const auto& disc = table.values[Column(table, "disc_temp_fl_C")];
  const auto& rpm = table.values[Column(table, "Engine RPM")];
  for (size_t k = 0; k < 6; ++k) {
    EXPECT_NEAR(time[k], 0.1 * k, 1e-15);
    EXPECT_NEAR(speed[k], 10.0 * (k + 1), 1e-12);  // km/h / 3.6
    // 100 degC at 0 s to 0 degC at 0.5 s, linear.
    EXPECT_NEAR(disc[k], 100.0 - 200.0 * k * 0.1, 1e-9) << k;
  }
  // rpm: 1000 at 0, 2000 at 0.25 s; 1400 at 0.1 s, 1800 at 0.2 s; nothing after 0.25 s.
  EXPECT_EQ(rpm[0], 1000.0);
  EXPECT_NEAR(rpm[1], 1400.0, 1e-9);
  EXPECT_NEAR(rpm[2], 1800.0, 1e-9);
  EXPECT_TRUE(std::isnan(rpm[3]));
  EXPECT_TRUE(std::isnan(rpm[5]));
  EXPECT_EQ(table.values.back(), std::vector<double>(6, 1.0));  // one lap without an .ldx

  // The logged channels with their own rates, and the metadata.
  ASSERT_EQ(t.channels.size(), 4u);
  EXPECT_EQ(t.channels[2].name, "Brake Temp FL");
  EXPECT_EQ(t.channels[2].unit, "degF");
  EXPECT_EQ(t.channels[2].rate_hz, 2.0);
  EXPECT_EQ(t.channels[2].samples, 2u);
  auto meta = [&](const std::string& key) {
    for (const auto& [k, v] : table.metadata) {
      if (k == key) return v;
    }
    return std::string("(absent)");
  };
  EXPECT_EQ(meta("Format"), "MoTeC .ld");
  EXPECT_EQ(meta("Venue"), "Darlington");
  EXPECT_EQ(meta("Driver"), "A. Driver");
  EXPECT_EQ(meta("Vehicle"), "(absent)");  // empty fields are left out
  EXPECT_EQ(meta("Sample Rate"), "10 Hz");
  EXPECT_EQ(meta("laps"), "1");
  EXPECT_EQ(meta("unmapped channels"), "Engine RPM");
  EXPECT_EQ(meta("channel map"), "map.yaml");
  EXPECT_EQ(t.sources.at("disc_temp_fl"), std::vector<std::string>{"Brake Temp FL"});
}

TEST(MotecLdTableTest, AChosenRate) {
  LdLog log;
  log.path = "r.ld";
  log.channels = {Channel("Ground Speed", "m/s", 10, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10})};
  const MotecTable t = MotecLdTable(log, Map(), std::nullopt, {.rate_hz = 4.0});
  // 0 .. 1 s at 4 Hz: 0, 0.25, 0.5, 0.75, 1.
  EXPECT_EQ(t.table.values[1], (std::vector<double>{0, 2.5, 5, 7.5, 10}));
  // A slow channel logged for long and a fast one: too many rows is refused, not allocated.
  LdLog huge = log;
  huge.channels.push_back(Channel("Engine RPM", "rpm", 1, std::vector<double>(200000, 1.0)));
  huge.channels.push_back(Channel("Oil Temp", "degC", 65535, {1.0}));
  EXPECT_TRUE(Contains(InputErrorOf([&] { MotecLdTable(huge, Map(), std::nullopt); }),
                       "r.ld: 199999 s at 65535 Hz would be 1.311e+10 rows on the time base"));
  EXPECT_TRUE(
      Contains(InputErrorOf([&] { MotecLdTable(log, Map(), std::nullopt, {.rate_hz = 0.0}); }),
               "r.ld: time base rate 0 Hz"));
}

TEST(MotecLdTableTest, UnitsAndNamesAreChecked) {
  LdLog log;
  log.path = "u.ld";
  log.channels = {Channel("Ground Speed", "bar", 10, {1.0})};
  log.channels[0].descriptor_at = 2916;
  EXPECT_TRUE(Contains(InputErrorOf([&] { MotecLdTable(log, Map(), std::nullopt); }),
                       "u.ld: channel 'Ground Speed' (descriptor at byte 2916): unit 'bar' is "
                       "not a unit of speed"));
  log.channels = {Channel("Time", "s", 10, {1.0})};
  EXPECT_TRUE(Contains(InputErrorOf([&] { MotecLdTable(log, Map(), std::nullopt); }),
                       "channel 'Time': hotlap names the time base so"));
  log.channels = {Channel("Ground Speed", "km/h", 10, {})};
  EXPECT_TRUE(Contains(InputErrorOf([&] { MotecLdTable(log, Map(), std::nullopt); }),
                       "u.ld: no channel has any samples"));
  // The degree sign as loggers write it is a temperature unit.
  log.channels = {Channel("Brake Temp FL", "\u00B0C", 1, {300.0, 310.0})};
  EXPECT_EQ(MotecLdTable(log, Map(), std::nullopt).table.values[1],
            (std::vector<double>{300.0, 310.0}));
}

TEST(MotecLdTableTest, LapsFromTheLdxBeacons) {
  const test::TempDir tmp;
  LdChannel speed = Channel("Ground Speed", "m/s", 10, std::vector<double>(51, 50.0));
  WriteMotecLd(tmp.path() / "run.ld", {}, {speed});
  // Beacons at 1.0 s and 3.05 s (microseconds), in the Beacons group; other groups ignored.
  tmp.Write("run.ldx",
            "<?xml version=\"1.0\"?>\n<LDXFile Version=\"1.6\">\n <Layers>\n  <Layer>\n"
            "   <MarkerBlock>\n    <MarkerGroup Name=\"Beacons\" Index=\"3\">\n"
            "     <Marker Version=\"100\" ClassName=\"BCN\" Name=\"Manual.1\" Time=\"1000000\"/>\n"
            "     <Marker Version=\"100\" ClassName=\"BCN\" Name=\"Manual.2\" Time=\"3.05e+06\"/>\n"
            "    </MarkerGroup>\n    <MarkerGroup Name=\"Other\">\n"
            "     <Marker Time=\"2000000\"/>\n    </MarkerGroup>\n   </MarkerBlock>\n"
            "  </Layer>\n </Layers>\n</LDXFile>\n");
  MotecTable t = ReadMotecLdTable(tmp.path() / "run.ld", Map());
  const std::vector<double>& lap = t.table.values.back();
  ASSERT_EQ(lap.size(), 51u);
  EXPECT_EQ(lap[9], 1.0);   // 0.9 s
  EXPECT_EQ(lap[10], 2.0);  // 1.0 s: at the beacon
  EXPECT_EQ(lap[30], 2.0);  // 3.0 s
  EXPECT_EQ(lap[31], 3.0);  // 3.1 s
  SelectLap(t.table, 2);
  EXPECT_EQ(t.table.RowCount(), 21u);
  EXPECT_NEAR(t.table.values[0].front(), 1.0, 1e-12);

  // Beacons out of order are refused with the .ldx line.
  tmp.Write("run.ldx",
            "<LDXFile>\n<MarkerGroup Name=\"Beacons\">\n<Marker Time=\"2000000\"/>\n"
            "<Marker Time=\"1000000\"/>\n</MarkerGroup>\n</LDXFile>\n");
  EXPECT_TRUE(Contains(InputErrorOf([&] { ReadMotecLdTable(tmp.path() / "run.ld", Map()); }),
                       "run.ldx:4: Marker Time 1 s must follow 2 s"));
  tmp.Write("run.ldx", "<LDXFile><Marker Time=\"soon\"/></LDXFile>\n");
  EXPECT_TRUE(Contains(InputErrorOf([&] { ReadMotecLdTable(tmp.path() / "run.ld", Map()); }),
                       "Marker Time 'soon' is not a number"));
}

}  // namespace
}  // namespace hotlap
