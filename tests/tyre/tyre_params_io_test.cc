#include "hotlap/tyre/tyre_params_io.h"

#include <array>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "test_util.h"

namespace hotlap::tyre {
namespace {

namespace fs = std::filesystem;
using test::Contains;

// 000 Tables 2 and 4 as printed in spec section 2, and the wear rate the shipped car has instead
// of the table's wp1: tuned to the fall-off at Darlington (docs/race.md).
struct Table4Row {
  const char* corner;
  double p1, p2, p3, p4, p5, wp1, wp2, p_cp1, p_cp2, tuned_wp1;
};
constexpr std::array<Table4Row, 4> kTable4 = {{
    {"fr", 0.284, 7.44e-05, 1.345e-05, 0.0013, 150.7, 1.225e-06, 1.031, 0.0004437, 0.681758,
     1.84e-04},
    {"fl", 0.243, 1.37e-05, 6.977e-06, 0.0039, 111.8, 2.655e-06, 1.288, 0.0099999, 0.379096,
     1.54e-04},
    {"rr", 0.328, 0.0042, 1.641e-05, 1.797e-05, 427.5, 5.506e-06, 1.785, 0.0001508, 0.795321,
     6.06e-05},
    {"rl", 0.173, 0.0038, 0.0004, 0.0013, 166.5, 4.051e-06, 1.551, 0.0099996, 0.374554, 2.63e-04},
}};

class ShippedTyreTest : public ::testing::TestWithParam<Table4Row> {};

// Decimal text parses to the same double as the literal: exact equality.
TEST_P(ShippedTyreTest, MatchesTables2To4) {
  const Table4Row& row = GetParam();
  const TyreFile f = LoadTyreFile(test::Gen7Dir() / "tyres" / (std::string(row.corner) + ".yaml"));
  EXPECT_EQ(f.name, std::string("gen7-") + row.corner);
  const TyreThermalParams<double>& p = f.params;
  EXPECT_EQ(p.p1, row.p1);
  EXPECT_EQ(p.p2, row.p2);
  EXPECT_EQ(p.p3, row.p3);
  EXPECT_EQ(p.p4, row.p4);
  EXPECT_EQ(p.p5, row.p5);
  EXPECT_EQ(p.wear_coeff, row.tuned_wp1);
  EXPECT_GT(p.wear_coeff, 10.0 * row.wp1);  // the lap-15 fits wear the tyres far too little
  EXPECT_EQ(p.wear_exponent, row.wp2);
  EXPECT_EQ(p.contact_length_coeff, row.p_cp1);
  EXPECT_EQ(p.contact_length_exponent, row.p_cp2);
  // Table 3, the same at every corner.
  EXPECT_EQ(p.tread_mass, 0.9);
  EXPECT_EQ(p.carcass_mass, 11.0);
  EXPECT_EQ(p.tread_heat_capacity, 900.0);
  EXPECT_EQ(p.carcass_heat_capacity, 1600.0);
  EXPECT_EQ(p.track_conductance, 1200.0);
  EXPECT_EQ(p.contact_width, 0.2286);
  EXPECT_NEAR(p.reference_slip_angle, 8.0 * 3.14159265358979323846 / 180.0, 1e-15);  // deg->rad
  EXPECT_EQ(p.non_sliding_fraction_low, 0.3);
  EXPECT_EQ(p.non_sliding_fraction_high, 0.8);
  EXPECT_EQ(p.unloaded_radius, 0.3613);
  EXPECT_EQ(p.rim_radius, 0.229);
  EXPECT_EQ(p.diameter, 0.4572);
  EXPECT_EQ(p.width, 0.2921);
  EXPECT_EQ(p.emissivity, 0.93);
  ASSERT_NE(f.compound, nullptr);
  EXPECT_EQ(f.compound_path.filename(), "compound.yaml");
}

INSTANTIATE_TEST_SUITE_P(Corners, ShippedTyreTest, ::testing::ValuesIn(kTable4),
                         [](const ::testing::TestParamInfo<Table4Row>& info) {
                           return std::string(info.param.corner);
                         });

TEST(TyreParamsIoTest, ShippedCompoundHoldsItsTunedTable) {
  const TyreCompound c = LoadTyreCompound(test::Gen7Dir() / "tyres" / "compound.yaml");
  EXPECT_EQ(c.name, "gen7-speedway-compound");
  EXPECT_EQ(c.wear_reference_power, 1000.0);
  // The grip against wear tuned to the fall-off at Darlington (docs/race.md), not the spec's.
  EXPECT_EQ(c.grip_vs_wear.wear_mm, (std::vector<double>{0, 1, 2, 4, 6}));
  EXPECT_EQ(c.grip_vs_wear.factor, (std::vector<double>{1.0, 0.88, 0.78, 0.64, 0.56}));
  // degC in the file, kelvin inside; the cubics meet their conditions (1e-12: rounding only).
  EXPECT_NEAR(c.grip.spec().optimal_temp, 371.15, 1e-12);
  EXPECT_NEAR(c.grip.Evaluate(371.15), 1.0, 1e-12);
  EXPECT_NEAR(c.wear_rate.Evaluate(333.15), 1.5, 1e-12);
  // h(wear) interpolates linearly and clamps: halfway between 2 mm (0.78) and 4 mm (0.64).
  EXPECT_NEAR(c.grip_vs_wear.Evaluate(3.0), 0.71, 1e-15);
  EXPECT_EQ(c.grip_vs_wear.Evaluate(10.0), 0.56);
  // Below a new tyre the first segment carries on (no kink at wear 0 for a solver's iterates).
  EXPECT_NEAR(c.grip_vs_wear.Evaluate(-0.5), 1.06, 1e-15);
  EXPECT_NEAR(c.GripFactor(371.15, 3.0), 0.71, 1e-12);
}

// A copy of the shipped rear-right tyre and its compound in a fresh folder, edited one line at a
// time; every failure must be an InputError naming the edited file and the field.
class BadTyreFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    tyre_text_ = test::ReadTextFile(test::Gen7Dir() / "tyres" / "rr.yaml");
    compound_text_ = test::ReadTextFile(test::Gen7Dir() / "tyres" / "compound.yaml");
  }
  // Writes both files (with `edit` applied to one of them), loads the tyre and returns the
  // InputError's message.
  std::string LoadError(bool edit_compound, const std::string& from, const std::string& to) {
    const std::string tyre = edit_compound ? tyre_text_ : test::ReplaceOnce(tyre_text_, from, to);
    const std::string compound =
        edit_compound ? test::ReplaceOnce(compound_text_, from, to) : compound_text_;
    tyre_path_ = dir_.Write("rr.yaml", tyre);
    compound_path_ = dir_.Write("compound.yaml", compound);
    try {
      LoadTyreFile(tyre_path_);
    } catch (const InputError& e) {
      return e.what();
    }
    ADD_FAILURE() << "no InputError for '" << from << "' -> '" << to << "'";
    return "";
  }
  std::string TyreError(const std::string& from, const std::string& to) {
    return LoadError(false, from, to);
  }
  std::string CompoundError(const std::string& from, const std::string& to) {
    return LoadError(true, from, to);
  }

  test::TempDir dir_;
  std::string tyre_text_, compound_text_;
  fs::path tyre_path_, compound_path_;
};

TEST_F(BadTyreFileTest, UneditedCopyLoads) {
  tyre_path_ = dir_.Write("rr.yaml", tyre_text_);
  dir_.Write("compound.yaml", compound_text_);
  EXPECT_EQ(LoadTyreFile(tyre_path_).params.p5, 427.5);
}

TEST_F(BadTyreFileTest, NegativeMass) {
  const std::string m = TyreError("tread_mass_kg: 0.9", "tread_mass_kg: -0.9");
  EXPECT_TRUE(Contains(m, tyre_path_.string()));
  EXPECT_TRUE(Contains(m, "field 'construction.tread_mass_kg'"));
  EXPECT_TRUE(Contains(m, "-0.9"));
  EXPECT_TRUE(Contains(m, "> 0 kg"));
}

TEST_F(BadTyreFileTest, MissingField) {
  const std::string m = TyreError("p5_W_per_m2K: 427.5", "# p5 left out");
  EXPECT_TRUE(Contains(m, tyre_path_.string()));
  EXPECT_TRUE(Contains(m, "missing field 'heat_generation.p5_W_per_m2K'"));
}

// The unit is part of the key: grams where kilograms are expected is a missing field, and the
// message points at the key that was found instead.
TEST_F(BadTyreFileTest, WrongUnitSuffix) {
  const std::string m = TyreError("tread_mass_kg: 0.9", "tread_mass_g: 900");
  EXPECT_TRUE(Contains(m, tyre_path_.string()));
  EXPECT_TRUE(Contains(m, "missing field 'construction.tread_mass_kg'"));
  EXPECT_TRUE(Contains(m, "'tread_mass_g'"));
}

TEST_F(BadTyreFileTest, UnknownExtraKey) {
  const std::string m = TyreError("model: two_mass_thermal", "model: two_mass_thermal\ncolour: 1");
  EXPECT_TRUE(Contains(m, tyre_path_.string()));
  EXPECT_TRUE(Contains(m, "unknown field 'colour'"));
  const std::string nested =
      TyreError("  emissivity: 0.93", "  emissivity: 0.93\n  emisivity: 0.9");
  EXPECT_TRUE(Contains(nested, "unknown field 'construction.emisivity'"));
  EXPECT_TRUE(Contains(nested, "did you mean 'emissivity'"));
}

TEST_F(BadTyreFileTest, NotANumber) {
  const std::string m = TyreError("p1: 0.328", "p1: 0.3x");
  EXPECT_TRUE(Contains(m, tyre_path_.string()));
  EXPECT_TRUE(Contains(m, "field 'heat_generation.p1'"));
  EXPECT_TRUE(Contains(m, "'0.3x' is not a number"));
}

TEST_F(BadTyreFileTest, EmissivityAboveOne) {
  const std::string m = TyreError("emissivity: 0.93", "emissivity: 1.5");
  EXPECT_TRUE(Contains(m, tyre_path_.string()));
  EXPECT_TRUE(Contains(m, "field 'construction.emissivity'"));
  EXPECT_TRUE(Contains(m, "1.5"));
  EXPECT_TRUE(Contains(m, "in [0, 1]"));
}

TEST_F(BadTyreFileTest, MissingReferencedFile) {
  const std::string m = TyreError("compound: compound.yaml", "compound: soft.yaml");
  EXPECT_TRUE(Contains(m, tyre_path_.string()));
  EXPECT_TRUE(Contains(m, "field 'compound'"));
  EXPECT_TRUE(Contains(m, "'soft.yaml'"));
  EXPECT_TRUE(Contains(m, "does not exist"));
}

TEST_F(BadTyreFileTest, YamlSyntaxError) {
  const std::string m = TyreError("p1: 0.328", "p1: [0.328");
  EXPECT_TRUE(Contains(m, tyre_path_.string() + ":"));  // followed by line:column
  EXPECT_TRUE(Contains(m, "YAML syntax error"));
}

TEST_F(BadTyreFileTest, WrongModel) {
  const std::string m = TyreError("model: two_mass_thermal", "model: three_mass_thermal");
  EXPECT_TRUE(Contains(m, "field 'model'"));
  EXPECT_TRUE(Contains(m, "'three_mass_thermal' is not allowed"));
}

TEST_F(BadTyreFileTest, RimLargerThanTyre) {
  const std::string m = TyreError("rim_radius_m: 0.229", "rim_radius_m: 0.4");
  EXPECT_TRUE(Contains(m, "field 'construction.rim_radius_m'"));
}

// The compound's errors name the compound file, not the tyre file that refers to it.
TEST_F(BadTyreFileTest, NonPositiveCubic) {
  const std::string m = CompoundError("low_value: 0.90", "low_value: 0.10");
  EXPECT_TRUE(Contains(m, compound_path_.string()));
  EXPECT_TRUE(Contains(m, "field 'grip_cubic'"));
  EXPECT_TRUE(Contains(m, "not positive"));
}

TEST_F(BadTyreFileTest, GripCubicWithOptimumNotAMaximum) {
  // g(60 degC) = 0.99, g(140 degC) = 0.90: both below 1, yet the cubic climbs to about 1.29 at
  // 0 degC (and stays positive), so 98 degC is only a local maximum.
  const std::string m = CompoundError("low_value: 0.90", "low_value: 0.99");
  EXPECT_TRUE(Contains(m, compound_path_.string()));
  EXPECT_TRUE(Contains(m, "field 'grip_cubic'"));
  EXPECT_TRUE(Contains(m, "not the grip maximum"));
}

TEST_F(BadTyreFileTest, CubicTemperaturesOutOfOrder) {
  const std::string m = CompoundError("low_temp_C: 60 ", "low_temp_C: 120 ");
  EXPECT_TRUE(Contains(m, "field 'grip_cubic'"));
  EXPECT_TRUE(Contains(m, "distinct and ordered"));
}

TEST_F(BadTyreFileTest, GripVsWearNotIncreasing) {
  const std::string m = CompoundError("{wear_mm: 4, factor: 0.64}", "{wear_mm: 0.5, factor: 0.64}");
  EXPECT_TRUE(Contains(m, compound_path_.string()));
  EXPECT_TRUE(Contains(m, "field 'grip_vs_wear'"));
  EXPECT_TRUE(Contains(m, "strictly increasing"));
}

TEST_F(BadTyreFileTest, GripRisingWithWear) {
  const std::string m = CompoundError("{wear_mm: 6, factor: 0.56}", "{wear_mm: 6, factor: 0.95}");
  EXPECT_TRUE(Contains(m, "field 'grip_vs_wear'"));
  EXPECT_TRUE(Contains(m, "must not rise"));
}

TEST_F(BadTyreFileTest, GripVsWearRowWithUnknownKey) {
  const std::string m =
      CompoundError("{wear_mm: 1, factor: 0.88}", "{wear_mm: 1, factor: 0.88, note: 2}");
  EXPECT_TRUE(Contains(m, compound_path_.string()));
  EXPECT_TRUE(Contains(m, "unknown field 'grip_vs_wear[1].note'"));
}

TEST_F(BadTyreFileTest, MissingCompoundField) {
  const std::string m = CompoundError("wear_reference_power_W: 1000", "wear_reference_power_kW: 1");
  EXPECT_TRUE(Contains(m, compound_path_.string()));
  EXPECT_TRUE(Contains(m, "missing field 'wear_reference_power_W'"));
  EXPECT_TRUE(Contains(m, "'wear_reference_power_kW'"));
}

// What fuzz/compound_yaml_fuzz found (tests/data/fuzz_regressions/compound_yaml): each file is
// refused with an InputError (a mapping as a key escaped as yaml-cpp's TypedBadConversion).
TEST(TyreParamsIoTest, FuzzRegressionsAreInputErrors) {
  for (const fs::path& file : test::FuzzRegressions("compound_yaml")) {
    EXPECT_THROW(LoadTyreCompound(file), InputError) << file;
  }
}

// The gas-and-rim model's sections: needed with thermal_model gas_rim (the message names the
// missing section), kept and unused by the paper's model, and checked in both.
TEST_F(BadTyreFileTest, GasRimSectionsAreNeededByThatModelAlone) {
  tyre_path_ = dir_.Write(
      "rr.yaml", test::ReplaceOnce(tyre_text_, "thermal_model: gas_rim", "thermal_model: paper"));
  dir_.Write("compound.yaml", compound_text_);
  const TyreFile paper = LoadTyreFile(tyre_path_);
  EXPECT_EQ(paper.params.model, TyreThermalModel::kPaper);
  EXPECT_EQ(paper.params.rim_mass, 11.3);  // read and checked, not used
  const std::string without_gas = tyre_text_.substr(0, tyre_text_.find("\ngas:")) +
                                  tyre_text_.substr(tyre_text_.find("\nrim:"));
  tyre_path_ = dir_.Write("rr.yaml", without_gas);
  std::string m;
  try {
    LoadTyreFile(tyre_path_);
  } catch (const InputError& e) {
    m = e.what();
  }
  EXPECT_TRUE(Contains(m, tyre_path_.string())) << m;
  EXPECT_TRUE(Contains(m, "gas")) << m;
  // Without the gas-and-rim sections a paper-model file loads as it always has.
  const std::string bare =
      test::ReplaceOnce(tyre_text_.substr(0, tyre_text_.find("\n# The gas-and-rim model")),
                        "thermal_model: gas_rim", "thermal_model: paper");
  tyre_path_ = dir_.Write("rr.yaml", bare + "\n");
  EXPECT_EQ(LoadTyreFile(tyre_path_).params.model, TyreThermalModel::kPaper);
}

TEST_F(BadTyreFileTest, GasRimValuesOutOfRangeAreRefused) {
  const std::string m = TyreError("rim_mass_kg: 11.3", "rim_mass_kg: -1");
  EXPECT_TRUE(Contains(m, "field 'rim.rim_mass_kg'"));
  const std::string liner = TyreError("liner_rim_W_per_K: 20", "liner_rim_W_per_K: 0");
  EXPECT_TRUE(Contains(liner, "liner_rim_W_per_K")) << liner;
  EXPECT_TRUE(Contains(liner, "no other way out")) << liner;
  const std::string model = TyreError("thermal_model: gas_rim", "thermal_model: three_node");
  EXPECT_TRUE(Contains(model, "thermal_model")) << model;
}

}  // namespace
}  // namespace hotlap::tyre
