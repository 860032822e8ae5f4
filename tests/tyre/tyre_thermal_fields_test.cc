// The tyre thermal field table: keys unique, every member covered once, the shipped car's values
// in range, and the reader's messages naming file, field and range for every entry.

#include "hotlap/tyre/tyre_thermal_fields.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "field_table_checks.h"
#include "hotlap/common/error.h"
#include "hotlap/tyre/tyre_params_io.h"
#include "test_util.h"

namespace hotlap::tyre {
namespace {

using test::Contains;

// Every value of the struct's FieldsOf (each member once), in declaration order, but the cold
// pressure: the car's tyre_forces.<c>.pressure_kPa, not a tyre file's field (vehicle::LoadCar).
std::vector<double> MemberValues(const TyreThermalParams<double>& p) {
  std::vector<double> out;
  std::apply([&](const auto&... v) { ((&v == &p.cold_pressure ? void() : out.push_back(v)), ...); },
             TyreThermalParams<double>::FieldsOf(p));
  return out;
}

TEST(TyreThermalFieldsTest, KeysAreUniqueWithinTheirSection) {
  std::set<std::string> paths;
  for (const TyreThermalField& f : TyreThermalFields()) {
    EXPECT_FALSE(f.key.empty());
    EXPECT_TRUE(paths.insert(f.Path()).second) << "twice: " << f.Path();
    const auto sections = TyreThermalSections();
    EXPECT_NE(std::find(sections.begin(), sections.end(), f.section), sections.end()) << f.Path();
    EXPECT_EQ(FindTyreThermalField(f.Path()), &f);
  }
  EXPECT_EQ(FindTyreThermalField("heat_generation.no_such_key"), nullptr);
}

TEST(TyreThermalFieldsTest, EveryMemberIsCoveredExactlyOnce) {
  test::ExpectEveryMemberCoveredOnce<TyreThermalParams<double>>(
      TyreThermalFields(), [](const TyreThermalParams<double>& p) { return MemberValues(p); });
}

TEST(TyreThermalFieldsTest, SectionsListTheirEntriesInTableOrder) {
  size_t count = 0;
  for (std::string_view section : TyreThermalSections()) {
    const std::vector<const TyreThermalField*> in = TyreThermalFieldsIn(section);
    EXPECT_FALSE(in.empty()) << section;
    for (const TyreThermalField* f : in) {
      EXPECT_EQ(f, &TyreThermalFields()[count]) << "table not grouped by section: " << f->Path();
      ++count;
    }
  }
  EXPECT_EQ(count, TyreThermalFields().size());
}

// The paper's three fitted sections, and the gas path's conductances the TPMS stage fits.
TEST(TyreThermalFieldsTest, FittedEntriesAreTheThreeFittedSections) {
  std::vector<std::string> fitted;
  for (const TyreThermalField* f : FittedTyreThermalFields()) {
    fitted.push_back(f->Path());
    EXPECT_LT(f->fit->lower, f->fit->upper) << f->Path();
    EXPECT_GT(f->fit->scale_floor, 0.0) << f->Path();
    EXPECT_EQ(f->to_si, nullptr) << "a fitted value is stored as the file gives it";
  }
  EXPECT_EQ(fitted, (std::vector<std::string>{
                        "heat_generation.p1", "heat_generation.p2_J_per_kgN",
                        "heat_generation.p3_J_per_kgN", "heat_generation.p4_J_per_kgN",
                        "heat_generation.p5_W_per_m2K", "wear.wp1_mm_per_s", "wear.wp2",
                        "contact_length.p_cp1", "contact_length.p_cp2", "gas.carcass_gas_W_per_K",
                        "gas.gas_rim_W_per_K", "rim.rim_air_W_per_K"}));
  EXPECT_EQ(FittedTyreThermalFields("wear").size(), 2u);
  EXPECT_TRUE(FittedTyreThermalFields("construction").empty());
}

TEST(TyreThermalFieldsTest, ShippedTyresAreInRangeAndHoldExactlyTheTableKeys) {
  for (const char* corner : {"fl", "fr", "rl", "rr"}) {
    const std::string file = (test::Gen7Dir() / "tyres" / (std::string(corner) + ".yaml")).string();
    const YAML::Node root = YAML::LoadFile(file);
    size_t keys = 0;
    for (std::string_view section : TyreThermalSections()) {
      const YAML::Node s = root[std::string(section)];
      ASSERT_TRUE(s.IsMap()) << file << " " << section;
      keys += s.size();
    }
    EXPECT_EQ(keys, TyreThermalFields().size()) << file;
    for (const TyreThermalField& f : TyreThermalFields()) {
      const YAML::Node v = root[std::string(f.section)][std::string(f.key)];
      ASSERT_TRUE(v.IsScalar()) << file << ": no " << f.Path();
      EXPECT_TRUE(f.range.Contains(v.as<double>()))
          << file << ": " << f.Path() << " = " << v.as<double>() << " not " << f.range.Describe();
    }
    // The loader puts each file value where the table says, converted to SI.
    const TyreFile loaded = LoadTyreFile(file);
    for (const TyreThermalField& f : TyreThermalFields()) {
      const double v = root[std::string(f.section)][std::string(f.key)].as<double>();
      EXPECT_EQ(f.Of(loaded.params), f.to_si ? f.to_si(v) : v) << f.Path();
    }
  }
  const TyreThermalField* slip = FindTyreThermalField("construction.reference_slip_angle_deg");
  ASSERT_NE(slip, nullptr);
  ASSERT_NE(slip->to_si, nullptr);
  EXPECT_NEAR(slip->to_si(180.0), M_PI, 1e-15);
}

// Each entry set out of its range in a copy of the shipped rear-right tyre: the reader's message
// names the file, the field and the allowed range.
TEST(TyreThermalFieldsTest, ReaderErrorNamesFileFieldAndRangeForEveryEntry) {
  test::TempDir dir;
  dir.Write("compound.yaml", test::ReadTextFile(test::Gen7Dir() / "tyres" / "compound.yaml"));
  const int checked = test::ExpectReaderErrorsNameFileFieldAndRange(
      TyreThermalFields(), test::Gen7Dir() / "tyres" / "rr.yaml", dir, "rr.yaml",
      [](YAML::Node& root, const TyreThermalField& f, double v) {
        root[std::string(f.section)][std::string(f.key)] = v;
      },
      [](const std::filesystem::path& path) { LoadTyreFile(path); });
  EXPECT_EQ(checked, static_cast<int>(TyreThermalFields().size()));
}

}  // namespace
}  // namespace hotlap::tyre
