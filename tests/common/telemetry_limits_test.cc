#include "hotlap/common/telemetry_limits.h"

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "hotlap/logs/telemetry.h"
#include "test_util.h"

namespace hotlap {
namespace {

namespace fs = std::filesystem;
using test::Contains;

// A three-row log with `column` holding `values` (three cells, comma-separated).
fs::path LogWith(const fs::path& dir, const std::string& column, const std::string& values) {
  std::string text = "time_s," + column + "\n";
  std::string rest = values + ",";
  for (int row = 0; row < 3; ++row) {
    const size_t comma = rest.find(',');
    text += std::to_string(0.1 * row) + "," + rest.substr(0, comma) + "\n";
    rest.erase(0, comma + 1);
  }
  return test::WriteTextFile(dir / "log.csv", text);
}

class TelemetryLimitsTest : public ::testing::Test {
 protected:
  // The InputError message of reading the log, or "" if it read.
  std::string Refusal(const std::string& column, const std::string& values) {
    try {
      Telemetry::Read(LogWith(tmp_.path(), column, values));
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
  Telemetry Read(const std::string& column, const std::string& values) {
    return Telemetry::Read(LogWith(tmp_.path(), column, values));
  }
  const test::TempDir tmp_;
};

TEST_F(TelemetryLimitsTest, ImpossibleValuesAreRefusedWithFileLineColumnAndValue) {
  const std::string negative_speed = Refusal("speed_mps", "20,-50,20");
  EXPECT_TRUE(Contains(negative_speed, "log.csv:3: 'speed_mps' is -50 mps")) << negative_speed;
  EXPECT_TRUE(Contains(negative_speed, "not negative")) << negative_speed;
  // The limit applies in SI whatever the unit: 600 km/h is above 150 m/s, 500 km/h is not.
  EXPECT_TRUE(Contains(Refusal("speed_kph", "100,600,100"), "'speed_kph' is 600 kph"));
  EXPECT_EQ(Refusal("speed_kph", "100,500,100"), "");
  EXPECT_TRUE(Contains(Refusal("speed_mps", "1,1e308,1"), "'speed_mps' is 1e+308"));
  EXPECT_TRUE(Contains(Refusal("fz_fl_N", "3000,-3000,3000"), "'fz_fl_N' is -3000 N"));
  EXPECT_TRUE(Contains(Refusal("fz_fl_kN", "3,3,120"), "log.csv:4: 'fz_fl_kN' is 120 kN"));
  EXPECT_TRUE(Contains(Refusal("tread_temp_fl_C", "80,-300,80"), "is -300 C"));
  EXPECT_TRUE(Contains(Refusal("disc_temp_fl_K", "500,-1,500"), "is -1 K"));
  EXPECT_TRUE(Contains(Refusal("disc_temp_fl_C", "500,2100,500"), "2000 degC"));
  EXPECT_TRUE(Contains(Refusal("slip_angle_fl_deg", "1,95,1"), "+-90 degrees"));
  EXPECT_TRUE(Contains(Refusal("slip_angle_fl_rad", "0,-1.6,0"), "is -1.6 rad"));
  EXPECT_TRUE(Contains(Refusal("slip_ratio_fl", "0,-1.5,0"), "not below -1"));
  EXPECT_TRUE(Contains(Refusal("rolling_radius_fl_mm", "300,0,300"), "is 0 mm"));
  EXPECT_TRUE(Contains(Refusal("brake_power_fl_kW", "0,-2,0"), "is -2 kW"));
  // Within range, nothing is refused, including the ends of the ranges and empty cells.
  EXPECT_EQ(Refusal("slip_angle_fl_deg", "-90,,90"), "");
  EXPECT_EQ(Refusal("disc_temp_fl_C", "-273.15,2000,"), "");
}

TEST_F(TelemetryLimitsTest, ValuesALoggerDoesProduceAreTreatedWithOneWarningPerColumn) {
  // A wheel in the air: a load cell reads a little below zero; taken as no load.
  const Telemetry air = Read("fz_fl_N", "2000,-120,-40");
  EXPECT_EQ(air.Channel("fz", Corner::kFrontLeft)[0], 2000.0);
  EXPECT_EQ(air.Channel("fz", Corner::kFrontLeft)[1], 0.0);
  EXPECT_EQ(air.Channel("fz", Corner::kFrontLeft)[2], 0.0);
  ASSERT_EQ(air.warnings().size(), 1u);
  EXPECT_TRUE(Contains(air.warnings()[0], "'fz_fl_N': 2 values")) << air.warnings()[0];
  EXPECT_TRUE(Contains(air.warnings()[0], "(lines 3-4) taken as 0 N: a wheel in the air"))
      << air.warnings()[0];
  // A speed signal's noise at standstill, in the column's unit.
  const Telemetry still = Read("speed_kph", "-1,0,10");
  EXPECT_EQ(still.Channel("speed")[0], 0.0);
  ASSERT_EQ(still.warnings().size(), 1u);
  EXPECT_TRUE(Contains(still.warnings()[0], "from -1.8 to below 0 kph")) << still.warnings()[0];
  // A locked wheel's slip ratio just past -1.
  const Telemetry locked = Read("slip_ratio_fl", "-0.5,-1.04,-1");
  EXPECT_EQ(locked.Channel("slip_ratio", Corner::kFrontLeft)[1], -1.0);
  EXPECT_EQ(locked.warnings().size(), 1u);
  // Nothing treated, no warning.
  EXPECT_TRUE(Read("fz_fl_N", "2000,0,3000").warnings().empty());
}

TEST(TelemetryLimitsTableTest, EveryLimitedQuantityHasAReasonAndAnOrderedRange) {
  for (const char* q :
       {"speed", "fz", "slip_angle", "slip_ratio", "tread_temp", "carcass_temp", "disc_temp",
        "calliper_temp", "ambient_temp", "track_temp", "rolling_radius", "brake_power"}) {
    const auto limits = LimitsOf(q);
    ASSERT_TRUE(limits.has_value()) << q;
    EXPECT_LE(limits->refuse_below, limits->physical_min) << q;
    EXPECT_LT(limits->physical_min, limits->refuse_above) << q;
    EXPECT_FALSE(limits->reason.empty()) << q;
    EXPECT_EQ(limits->physical_min > limits->refuse_below, !limits->treated_as.empty()) << q;
  }
  for (const char* q : {"time", "distance", "fx", "fy", "wear", "grip_factor", "q1"}) {
    EXPECT_FALSE(LimitsOf(q).has_value()) << q;
  }
}

}  // namespace
}  // namespace hotlap
