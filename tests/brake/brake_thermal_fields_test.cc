// The brake thermal field table: keys unique, every member (each convection entry) covered once,
// the shipped car's values in range, and the reader's messages naming file, field and range.

#include "hotlap/brake/brake_thermal_fields.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "field_table_checks.h"
#include "hotlap/brake/brake_params_io.h"
#include "hotlap/common/error.h"
#include "test_util.h"

namespace hotlap::brake {
namespace {

using test::Contains;

// Every value of the struct's FieldsOf (each member and polynomial entry once).
std::vector<double> MemberValues(const BrakeThermalParams<double>& p) {
  std::vector<double> out;
  std::apply([&](const auto&... v) { (out.push_back(v), ...); },
             BrakeThermalParams<double>::FieldsOf(p));
  return out;
}

// The entry's node in a brake file: at the top level, or inside its section's map.
YAML::Node NodeOf(YAML::Node root, const BrakeThermalField& f) {
  if (f.section.empty()) return root[std::string(f.key)];
  return root[std::string(f.section)][std::string(f.key)];
}

TEST(BrakeThermalFieldsTest, KeysAreUniqueWithinTheirSection) {
  std::set<std::string> paths;
  for (const BrakeThermalField& f : BrakeThermalFields()) {
    EXPECT_FALSE(f.key.empty());
    EXPECT_TRUE(paths.insert(f.Path()).second) << "twice: " << f.Path();
    // Exactly one way to the member: a top-level one, or a polynomial's entry.
    EXPECT_NE(f.member == nullptr, f.polynomial == nullptr && f.entry == nullptr) << f.Path();
    // The top level and the disc_bulk section hold numbers; the other sections are polynomials.
    EXPECT_EQ(f.member == nullptr, !f.section.empty() && f.section != kDiscBulkSection) << f.Path();
    EXPECT_EQ(FindBrakeThermalField(f.Path()), &f);
  }
  EXPECT_EQ(FindBrakeThermalField("disc_convection_cholesky_sqrtW_per_K.l12"), nullptr);
}

TEST(BrakeThermalFieldsTest, EveryMemberIsCoveredExactlyOnce) {
  test::ExpectEveryMemberCoveredOnce<BrakeThermalParams<double>>(
      BrakeThermalFields(), [](const BrakeThermalParams<double>& p) { return MemberValues(p); });
  BrakeThermalParams<double> p{};
  for (size_t i = 0; i < BrakeThermalFields().size(); ++i) {
    BrakeThermalFields()[i].Of(p) = 1.0 + static_cast<double>(i);
  }
  const BrakeThermalParams<double>& c = p;
  // The polynomial entries land in the polynomial they name.
  EXPECT_EQ(FindBrakeThermalField("disc_convection_cholesky_sqrtW_per_K.l33")->Of(c),
            p.disc_convection.l33);
  EXPECT_EQ(FindBrakeThermalField("calliper_convection_cholesky_sqrtW_per_K.l21")->Of(c),
            p.calliper_convection.l21);
}

TEST(BrakeThermalFieldsTest, FittedEntriesAreGammaXiAndTheCholeskyEntries) {
  const std::vector<const BrakeThermalField*> fitted = FittedBrakeThermalFields();
  ASSERT_EQ(fitted.size(), 14u);
  EXPECT_EQ(fitted[0]->Path(), "heat_partition");
  EXPECT_EQ(fitted[1]->Path(), "mass_participation");
  for (size_t i = 2; i < fitted.size(); ++i) {
    EXPECT_NE(fitted[i]->polynomial, nullptr) << fitted[i]->Path();
    // Diagonal entries of L are non-negative in the file and in the fit; the others are free.
    EXPECT_EQ(fitted[i]->range.min == 0.0, fitted[i]->fit->lower == 0.0) << fitted[i]->Path();
  }
  for (const BrakeThermalField* f : fitted) {
    EXPECT_LT(f->fit->lower, f->fit->upper) << f->Path();
    EXPECT_GE(f->fit->lower, f->range.min) << f->Path();
    EXPECT_EQ(f->to_si, nullptr) << "a fitted value is stored as the file gives it";
  }
}

TEST(BrakeThermalFieldsTest, ShippedBrakesAreInRangeAndLoadWhereTheTableSays) {
  for (const char* name : {"front", "front_left", "rear"}) {
    const std::string file = (test::Gen7Dir() / "brakes" / (std::string(name) + ".yaml")).string();
    const YAML::Node root = YAML::LoadFile(file);
    const BrakeFile loaded = LoadBrakeFile(file);
    for (const BrakeThermalField& f : BrakeThermalFields()) {
      const YAML::Node v = NodeOf(root, f);
      ASSERT_TRUE(v.IsScalar()) << file << ": no " << f.Path();
      const double x = v.as<double>();
      EXPECT_TRUE(f.range.Contains(x))
          << file << ": " << f.Path() << " = " << x << " not " << f.range.Describe();
      EXPECT_EQ(f.Of(loaded.params), f.to_si ? f.to_si(x) : x) << f.Path();
    }
  }
  EXPECT_EQ(FindBrakeThermalField("pad_area_mm2")->to_si(9472.0), 9472.0e-6);
}

// Each entry with a bound set out of its range in a copy of the shipped front brake: the reader's
// message names the file, the field and the allowed range.
TEST(BrakeThermalFieldsTest, ReaderErrorNamesFileFieldAndRangeForEveryBoundedEntry) {
  test::TempDir dir;
  const int checked = test::ExpectReaderErrorsNameFileFieldAndRange(
      BrakeThermalFields(), test::Gen7Dir() / "brakes" / "front.yaml", dir, "front.yaml",
      [](YAML::Node& root, const BrakeThermalField& f, double v) { NodeOf(root, f) = v; },
      [](const std::filesystem::path& path) { LoadBrakeFile(path); });
  // All but the six off-diagonal Cholesky entries, which take any value.
  EXPECT_EQ(checked, static_cast<int>(BrakeThermalFields().size()) - 6);
}

}  // namespace
}  // namespace hotlap::brake
