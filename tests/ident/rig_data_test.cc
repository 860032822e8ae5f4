#include "hotlap/ident/rig_data.h"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "test_util.h"

namespace hotlap::ident {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

std::string ErrorOf(const std::filesystem::path& path) {
  try {
    ReadRigCsv(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(RigDataTest, ReadsCanonicalAndOtherUnits) {
  const test::TempDir dir;
  const auto path = dir.Write("rig.csv",
                              "# rig: test\n"
                              "slip_angle_rad,fz_kN,fy_N,mz_kNm,tread_temp_K,fx_N,speed_kph\n"
                              "0.05,4,-3000,0.05,300,,36\n"
                              "-0.05,4.5,3100,-0.06,310,120,36\n");
  const auto s = ReadRigCsv(path);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_DOUBLE_EQ(s[0].slip_angle, 0.05);
  EXPECT_DOUBLE_EQ(s[0].fz, 4000.0);
  EXPECT_DOUBLE_EQ(s[0].mz, 50.0);
  EXPECT_DOUBLE_EQ(s[0].tread_temp, 300.0);
  EXPECT_DOUBLE_EQ(s[0].speed, 10.0);
  EXPECT_FALSE(s[0].fx.has_value());
  EXPECT_DOUBLE_EQ(*s[1].fx, 120.0);
  EXPECT_DOUBLE_EQ(s[1].slip_ratio, 0.0);  // optional column absent
  EXPECT_DOUBLE_EQ(s[1].camber, 0.0);
}

TEST(RigDataTest, WriteThenReadGivesTheSamples) {
  const test::TempDir dir;
  std::vector<RigSample> in(2);
  in[0] = {2 * kDeg, 0.01, 4000, 1 * kDeg, 1.5, 320.0, -2500, 40, std::nullopt};
  in[1] = {-3 * kDeg, 0.0, 6000, 0.0, 1.5, 290.0, 3900, -55, 12.5};
  WriteRigCsv(dir.path() / "r.csv", {{"source", "test"}}, in);
  const auto out = ReadRigCsv(dir.path() / "r.csv");
  ASSERT_EQ(out.size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    EXPECT_NEAR(out[i].slip_angle, in[i].slip_angle, 1e-15);
    EXPECT_NEAR(out[i].camber, in[i].camber, 1e-15);
    EXPECT_NEAR(out[i].tread_temp, in[i].tread_temp, 1e-12);
    EXPECT_EQ(out[i].fy, in[i].fy);
    EXPECT_EQ(out[i].fx.has_value(), in[i].fx.has_value());
  }
}

TEST(RigDataTest, BadFilesNameTheProblem) {
  const test::TempDir dir;
  const std::string good_header = "slip_angle_deg,fz_N,fy_N,mz_Nm,tread_temp_C\n";
  EXPECT_TRUE(test::Contains(
      ErrorOf(dir.Write("a.csv", "slip_angle_deg,fz_N,fy_N,tread_temp_C\n1,4000,-100,25\n")),
      "required rig column 'mz_Nm' is missing"));
  EXPECT_TRUE(
      test::Contains(ErrorOf(dir.Write("b.csv", good_header.substr(0, good_header.size() - 1) +
                                                    ",camber_dg\n1,4000,-100,2,25,0\n")),
                     "unknown rig column 'camber_dg' (did you mean 'camber_deg'"));
  EXPECT_TRUE(test::Contains(ErrorOf(dir.Write("c.csv", good_header + "1,0,-100,2,25\n")),
                             "c.csv:2: column 'fz_N': load 0 N must be > 0"));
  EXPECT_TRUE(test::Contains(ErrorOf(dir.Write("d.csv", good_header + "1,4000,,2,25\n")),
                             "d.csv:2: column 'fy_N' is empty"));
  EXPECT_TRUE(test::Contains(
      ErrorOf(dir.Write("e.csv",
                        "slip_angle_deg,slip_angle_rad,fz_N,fy_N,mz_Nm,tread_temp_C\n"
                        "1,0.01,4000,-100,2,25\n")),
      "are both slip_angle"));
  // Physically impossible values, as a log's (common/telemetry_limits.h), in the column's unit.
  EXPECT_TRUE(test::Contains(ErrorOf(dir.Write("f.csv", good_header + "100,4000,-100,2,25\n")),
                             "f.csv:2: 'slip_angle_deg' is 100 deg: impossible"));
  EXPECT_TRUE(test::Contains(ErrorOf(dir.Write("g.csv", good_header + "1,2e5,-100,2,25\n")),
                             "'fz_N' is 200000 N: impossible"));
  EXPECT_TRUE(test::Contains(ErrorOf(dir.Write("h.csv", good_header + "1,4000,-100,2,2500\n")),
                             "'tread_temp_C' is 2500 C: impossible"));
}

}  // namespace
}  // namespace hotlap::ident
