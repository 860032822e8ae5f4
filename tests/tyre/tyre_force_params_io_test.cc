#include "hotlap/tyre/tyre_force_params_io.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "hotlap/common/field_cast.h"
#include "test_util.h"

namespace hotlap::tyre {
namespace {

namespace fs = std::filesystem;
using test::Contains;

fs::path BrushExample() { return test::SourcePath("data/tyres/brush_example.yaml"); }
fs::path UniTireExample() { return test::SourcePath("data/tyres/unitire_example.yaml"); }

// The InputError message of `load(path)`, or "" if it did not throw.
template <class Load>
std::string ErrorOf(Load load, const fs::path& path) {
  try {
    load(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(BrushUniTireParamsIoTest, LoadsTheShippedBrushExample) {
  const BrushParamsFile f = LoadBrushParams(BrushExample());
  EXPECT_EQ(f.name, "example-225-55-r17-brush");
  const BrushParams<double>& p = f.params;
  EXPECT_EQ(p.contact_half_length, 0.07);
  EXPECT_EQ(p.reference_load, 4000.0);
  EXPECT_EQ(p.rubber.modulus_amplitude, 8.0e5);
  EXPECT_NEAR(p.rubber.modulus_reference_temp, 293.15, 1e-12);  // degC in the file
  EXPECT_EQ(p.carcass_torsional_stiffness.scale, 2000.0);
  EXPECT_EQ(p.carcass_lateral_stiffness.decay, 0.0106);
  // The stated cornering stiffness: 70.56 kN/rad at 4 kN and 20 degC.
  EXPECT_NEAR(CalcCorneringStiffness(p, 4000.0, 293.15), 70560.0, 1e-6);
}

TEST(BrushUniTireParamsIoTest, LoadsTheShippedUniTireExample) {
  const UniTireParamsFile f = LoadUniTireParams(UniTireExample());
  EXPECT_EQ(f.name, "example-225-55-r17-unitire");
  const UniTireParams<double>& p = f.params;
  EXPECT_EQ(p.nominal_load, 6000.0);
  EXPECT_EQ(p.cornering_stiffness_per_load, 20.0);
  EXPECT_EQ(p.trail, 0.045);
  EXPECT_EQ(p.stiffness_temperature.decay, 0.008);
  EXPECT_NEAR(p.trail_temperature.reference_temp, 293.15, 1e-12);
  // The header comment's K_y values: 39, 74, 104, 180 kN/rad at 2, 4, 6, 12 kN.
  const double expected[] = {39e3, 74e3, 104e3, 180e3};
  const double loads[] = {2000.0, 4000.0, 6000.0, 12000.0};
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(CalcUniTireCorneringStiffness(p, loads[i], 0.0, 293.15), expected[i], 1e3);
  }
}

TEST(BrushUniTireParamsIoTest, UniTireRoundTrip) {
  test::TempDir dir;
  UniTireParamsFile f = LoadUniTireParams(UniTireExample());
  f.name = "fit: run 12";                             // needs quoting
  f.params.cornering_stiffness_per_load = 0.1 + 0.2;  // not a short decimal
  f.params.trail_offset = -1.0 / 3.0;
  f.params.stiffness_temperature.decay = 1.0 / 7.0 * 1e-2;
  f.params.friction_temperature.reference_temp = 301.123456789;
  const fs::path path = dir.path() / "fitted.yaml";
  WriteUniTireParams(path, f, "Fitted to rig data.\nSecond line.", "fitted 2026-05-01");
  const std::string text = test::ReadTextFile(path);
  EXPECT_TRUE(Contains(text, "# Fitted to rig data.\n# Second line.\n"));
  EXPECT_TRUE(Contains(text, "trail_m: 0.045  # fitted 2026-05-01\n"));
  const UniTireParamsFile g = LoadUniTireParams(path);
  EXPECT_EQ(g.name, f.name);
  UniTireParams<double> pa = f.params, pb = g.params;
  auto pointers = [](UniTireParams<double>& p) {
    return std::apply([](auto&... x) { return std::vector<double*>{&x...}; },
                      UniTireParams<double>::FieldsOf(p));
  };
  const std::vector<double*> xa = pointers(pa), xb = pointers(pb);
  ASSERT_EQ(xa.size(), kUniTireFieldNames.size());
  for (size_t i = 0; i < xa.size(); ++i) {
    EXPECT_NEAR(*xa[i], *xb[i], 1e-12 * std::max(1.0, std::abs(*xa[i]))) << kUniTireFieldNames[i];
  }
  // Everything but the degC round trip is exact.
  EXPECT_EQ(pa.cornering_stiffness_per_load, pb.cornering_stiffness_per_load);
  EXPECT_EQ(pa.trail_offset, pb.trail_offset);
  EXPECT_EQ(pa.stiffness_temperature.decay, pb.stiffness_temperature.decay);
}

TEST(BrushUniTireParamsIoTest, WriterRefusesOutOfRangeAndLeavesNoFile) {
  test::TempDir dir;
  UniTireParamsFile f = LoadUniTireParams(UniTireExample());
  f.params.friction_y = -1.0;
  const fs::path path = dir.path() / "bad.yaml";
  try {
    WriteUniTireParams(path, f, "x");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_TRUE(Contains(e.what(), "friction_y"));
    EXPECT_TRUE(Contains(e.what(), path.string()));
  }
  EXPECT_FALSE(fs::exists(path));
  f.params.friction_y = 1.0;
  EXPECT_THROW(WriteUniTireParams(dir.path() / "missing" / "x.yaml", f, "x"), InputError);
}

struct BadFileCase {
  const char* name;
  const char* file;  // "brush" or "unitire"
  const char* from;
  const char* to;
  std::vector<std::string> message_parts;
};

class BrushUniTireBadFileTest : public ::testing::TestWithParam<BadFileCase> {};

TEST_P(BrushUniTireBadFileTest, NamesFileAndField) {
  const BadFileCase& c = GetParam();
  const bool brush = std::string(c.file) == "brush";
  test::TempDir dir;
  const std::string text = test::ReadTextFile(brush ? BrushExample() : UniTireExample());
  const fs::path path = dir.Write("bad.yaml", test::ReplaceOnce(text, c.from, c.to));
  const std::string message = brush
                                  ? ErrorOf([](const fs::path& p) { LoadBrushParams(p); }, path)
                                  : ErrorOf([](const fs::path& p) { LoadUniTireParams(p); }, path);
  ASSERT_FALSE(message.empty()) << "no InputError";
  EXPECT_TRUE(Contains(message, path.string()));
  for (const std::string& part : c.message_parts) EXPECT_TRUE(Contains(message, part));
}

INSTANTIATE_TEST_SUITE_P(
    Cases, BrushUniTireBadFileTest,
    ::testing::Values(
        BadFileCase{
            "BrushMissingField", "brush", "friction: 1.0", "", {"missing field 'friction'"}},
        BadFileCase{"BrushWrongUnit",
                    "brush",
                    "contact_half_length_m:",
                    "contact_half_length_mm:",
                    {"missing field 'contact_half_length_m'", "contact_half_length_mm"}},
        BadFileCase{"BrushNegative",
                    "brush",
                    "value_Nm_per_rad: 2000",
                    "value_Nm_per_rad: -2000",
                    {"carcass_torsional_stiffness.value_Nm_per_rad", "-2000", "out of range"}},
        BadFileCase{"BrushNestedMissing",
                    "brush",
                    "  geometry_factor: 6.0",
                    "",
                    {"missing field 'rubber.geometry_factor'"}},
        BadFileCase{"BrushWrongModel", "brush", "model: brush", "model: unitire", {"'model'"}},
        BadFileCase{"UniTireMissingField", "unitire", "trail_m: 0.045", "", {"'trail_m'"}},
        BadFileCase{"UniTireWrongUnit",
                    "unitire",
                    "nominal_load_N: 6000",
                    "nominal_load_kN: 6",
                    {"missing field 'nominal_load_N'", "nominal_load_kN"}},
        BadFileCase{"UniTireNegative",
                    "unitire",
                    "friction_y: 1.0",
                    "friction_y: -1.0",
                    {"field 'friction_y'", "-1", "out of range"}},
        BadFileCase{"UniTireNestedMissing",
                    "unitire",
                    "  decay_per_K: 0.008",
                    "",
                    {"stiffness_temperature.decay_per_K"}},
        BadFileCase{"UniTireUnknownKey",
                    "unitire",
                    "curvature_x: -0.2",
                    "curvature_x: -0.2\ncurvature_z: 0.1",
                    {"unknown field 'curvature_z'"}}),
    [](const ::testing::TestParamInfo<BadFileCase>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace hotlap::tyre
