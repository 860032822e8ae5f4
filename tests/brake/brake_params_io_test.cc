#include "hotlap/brake/brake_params_io.h"

#include <array>
#include <string>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "test_util.h"

namespace hotlap::brake {
namespace {

using test::Contains;
using Matrix3 = std::array<std::array<double, 3>, 3>;

// Recovers P of hA = z' P z from the conductance alone, at chosen z:
// z = [1, s, t] with s = u/100, t = (T - 273.15)/1000 taking the values 0, 1, 2.
Matrix3 RecoverP(const ConvectionPolynomial<double>& l) {
  const auto f = [&](double s, double t) { return l.Conductance(100.0 * s, 273.15 + 1000.0 * t); };
  Matrix3 p{};
  p[0][0] = f(0, 0);
  p[1][1] = (f(2, 0) - 2 * f(1, 0) + f(0, 0)) / 2;  // P11 + 2s P12 + s^2 P22 in s
  p[0][1] = p[1][0] = (f(1, 0) - f(0, 0) - p[1][1]) / 2;
  p[2][2] = (f(0, 2) - 2 * f(0, 1) + f(0, 0)) / 2;
  p[0][2] = p[2][0] = (f(0, 1) - f(0, 0) - p[2][2]) / 2;
  p[1][2] = p[2][1] = (f(1, 1) - p[0][0] - p[1][1] - p[2][2] - 2 * p[0][1] - 2 * p[0][2]) / 2;
  return p;
}

void ExpectMatrixNear(const Matrix3& got, const Matrix3& want, double tol) {
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(got[i][j], want[i][j], tol) << "P(" << i << j << ")";
  }
}

// The shipped assumed matrices (docs/vehicle.md: temperature-led, the shape of 000 Figure 12).
constexpr Matrix3 kPDisc = {{{4, 1, 2}, {1, 3, 1.5}, {2, 1.5, 40}}};
constexpr Matrix3 kPCal = {{{1.5, .3, .6}, {.3, 1.5, .5}, {.6, .5, 20}}};

TEST(BrakeParamsIoTest, FrontFileMatchesTable5AndConvertsUnits) {
  const BrakeFile f = LoadBrakeFile(test::Gen7Dir() / "brakes" / "front.yaml");
  const BrakeThermalParams<double>& p = f.params;
  EXPECT_EQ(f.name, "gen7-front-brake");
  EXPECT_EQ(p.heat_partition, 0.95);
  EXPECT_EQ(p.mass_participation, 0.1);
  EXPECT_EQ(p.disc_mass, 8.8);
  EXPECT_EQ(p.disc_heat_capacity, 480.0);
  EXPECT_EQ(p.calliper_mass, 5.0312);
  EXPECT_EQ(p.calliper_heat_capacity, 921.1);
  EXPECT_EQ(p.pad_conductivity, 0.5);
  EXPECT_EQ(p.disc_emissivity, 0.48);
  EXPECT_EQ(p.calliper_emissivity, 0.25);
  EXPECT_EQ(p.disc_radiating_area, 0.6302);
  // mm^2, cm^2 and mm to SI: one rounded multiplication each, within DOUBLE_EQ's 4 ulps.
  EXPECT_DOUBLE_EQ(p.pad_area, 9472e-6);                  // 9472 mm^2
  EXPECT_DOUBLE_EQ(p.pad_thickness, 0.025);               // 25 mm
  EXPECT_DOUBLE_EQ(p.calliper_radiating_area, 12.81e-4);  // 12.81 cm^2
  EXPECT_DOUBLE_EQ(f.geometry.disc_diameter, 0.380);
  EXPECT_DOUBLE_EQ(f.geometry.mounting_hole_diameter, 0.180);
  EXPECT_DOUBLE_EQ(f.geometry.disc_thickness, 0.036);
}

TEST(BrakeParamsIoTest, RearFileMatchesTable5AndConvertsUnits) {
  const BrakeFile f = LoadBrakeFile(test::Gen7Dir() / "brakes" / "rear.yaml");
  const BrakeThermalParams<double>& p = f.params;
  EXPECT_EQ(p.disc_mass, 4.9);
  EXPECT_EQ(p.calliper_mass, 3.274);
  EXPECT_EQ(p.disc_radiating_area, 0.5883);
  EXPECT_DOUBLE_EQ(p.pad_area, 6164e-6);
  EXPECT_DOUBLE_EQ(p.pad_thickness, 0.025);
  EXPECT_DOUBLE_EQ(p.calliper_radiating_area, 7.87e-4);
  EXPECT_DOUBLE_EQ(f.geometry.disc_diameter, 0.355);
  EXPECT_DOUBLE_EQ(f.geometry.mounting_hole_diameter, 0.210);
  EXPECT_DOUBLE_EQ(f.geometry.disc_thickness, 0.028);
}

// The shipped factors are printed to 9 significant digits, so P is reproduced to about 1e-8 of
// its entries; the acceptance bound is 1e-6.
TEST(BrakeParamsIoTest, CholeskyFactorsReproduceTheAssumedP) {
  for (const char* name : {"front.yaml", "rear.yaml"}) {
    SCOPED_TRACE(name);
    const BrakeFile f = LoadBrakeFile(test::Gen7Dir() / "brakes" / name);
    ExpectMatrixNear(RecoverP(f.params.disc_convection), kPDisc, 1e-6);
    ExpectMatrixNear(RecoverP(f.params.calliper_convection), kPCal, 1e-6);
    // And the conductance at a running point is z' P z directly: u = 50 m/s, T = 773.15 K.
    const double z[3] = {1.0, 0.5, 0.5};
    double want = 0.0;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) want += z[i] * kPDisc[i][j] * z[j];
    }
    EXPECT_NEAR(f.params.disc_convection.Conductance(50.0, 773.15), want, 1e-6);
  }
}

// The shape the paper's fitted conductances have (000 Figure 12): rising strongly with the disc
// temperature, less with speed. Over a lap's range (200 to 700 degC, 40 to 80 m/s) the shipped
// front disc's conductance at least triples with temperature and changes by under a fifth with
// speed; the front-left's is 75% of it everywhere (its restricted duct).
TEST(BrakeParamsIoTest, DiscConductanceRisesMostWithTemperature) {
  const BrakeFile front = LoadBrakeFile(test::Gen7Dir() / "brakes" / "front.yaml");
  const BrakeFile left = LoadBrakeFile(test::Gen7Dir() / "brakes" / "front_left.yaml");
  const auto& h = front.params.disc_convection;
  const double k200 = 473.15, k500 = 773.15, k700 = 973.15;
  EXPECT_GT(h.Conductance(70.0, k700), 3.0 * h.Conductance(70.0, k200));
  EXPECT_LT(h.Conductance(80.0, k500), 1.2 * h.Conductance(40.0, k500));
  EXPECT_GT(h.Conductance(80.0, k500), h.Conductance(40.0, k500));
  for (const double t : {k200, k500, k700}) {
    EXPECT_NEAR(left.params.disc_convection.Conductance(70.0, t), 0.75 * h.Conductance(70.0, t),
                1e-6 * h.Conductance(70.0, t));
  }
}

// Copies of the shipped front brake file, edited one line at a time.
class BadBrakeFileTest : public ::testing::Test {
 protected:
  std::string LoadError(const std::string& from, const std::string& to) {
    path_ = dir_.Write("front.yaml", test::ReplaceOnce(text_, from, to));
    try {
      LoadBrakeFile(path_);
    } catch (const InputError& e) {
      return e.what();
    }
    ADD_FAILURE() << "no InputError for '" << from << "' -> '" << to << "'";
    return "";
  }
  test::TempDir dir_;
  const std::string text_ = test::ReadTextFile(test::Gen7Dir() / "brakes" / "front.yaml");
  std::filesystem::path path_;
};

TEST_F(BadBrakeFileTest, UneditedCopyLoads) {
  path_ = dir_.Write("front.yaml", text_);
  EXPECT_EQ(LoadBrakeFile(path_).params.disc_mass, 8.8);
}

TEST_F(BadBrakeFileTest, NegativeMass) {
  const std::string m = LoadError("disc_mass_kg: 8.8", "disc_mass_kg: -8.8");
  EXPECT_TRUE(Contains(m, path_.string()));
  EXPECT_TRUE(Contains(m, "field 'disc_mass_kg'"));
  EXPECT_TRUE(Contains(m, "-8.8"));
  EXPECT_TRUE(Contains(m, "> 0 kg"));
}

TEST_F(BadBrakeFileTest, MissingField) {
  const std::string m = LoadError("pad_thickness_mm: 25", "# no pad thickness");
  EXPECT_TRUE(Contains(m, path_.string()));
  EXPECT_TRUE(Contains(m, "missing field 'pad_thickness_mm'"));
}

TEST_F(BadBrakeFileTest, WrongUnitSuffix) {
  const std::string m = LoadError("pad_area_mm2: 9472", "pad_area_m2: 0.009472");
  EXPECT_TRUE(Contains(m, path_.string()));
  EXPECT_TRUE(Contains(m, "missing field 'pad_area_mm2'"));
  EXPECT_TRUE(Contains(m, "'pad_area_m2'"));
}

TEST_F(BadBrakeFileTest, UnknownExtraKey) {
  const std::string m =
      LoadError("  disc_thickness_mm: 36", "  disc_thickness_mm: 36\n  vanes: 48");
  EXPECT_TRUE(Contains(m, path_.string()));
  EXPECT_TRUE(Contains(m, "unknown field 'geometry.vanes'"));
}

TEST_F(BadBrakeFileTest, NotANumber) {
  const std::string m = LoadError("heat_partition: 0.95", "heat_partition: most");
  EXPECT_TRUE(Contains(m, "field 'heat_partition'"));
  EXPECT_TRUE(Contains(m, "'most' is not a number"));
}

TEST_F(BadBrakeFileTest, EmissivityAboveOne) {
  const std::string m = LoadError("disc_emissivity: 0.48", "disc_emissivity: 1.2");
  EXPECT_TRUE(Contains(m, path_.string()));
  EXPECT_TRUE(Contains(m, "field 'disc_emissivity'"));
  EXPECT_TRUE(Contains(m, "in [0, 1]"));
}

TEST_F(BadBrakeFileTest, NegativeCholeskyDiagonal) {
  const std::string m = LoadError("l22: 1.6583124", "l22: -1.6583124");
  EXPECT_TRUE(Contains(m, "field 'disc_convection_cholesky_sqrtW_per_K.l22'"));
  EXPECT_TRUE(Contains(m, ">= 0"));
}

TEST_F(BadBrakeFileTest, MountingHoleLargerThanDisc) {
  const std::string m =
      LoadError("mounting_hole_diameter_mm: 180", "mounting_hole_diameter_mm: 400");
  EXPECT_TRUE(Contains(m, "field 'geometry.mounting_hole_diameter_mm'"));
}

TEST_F(BadBrakeFileTest, ZeroMassParticipation) {
  // xi = 0 would divide by zero in (000:24): the range is (0, 1].
  const std::string m = LoadError("mass_participation: 0.1", "mass_participation: 0");
  EXPECT_TRUE(Contains(m, "field 'mass_participation'"));
  EXPECT_TRUE(Contains(m, "(0, 1]"));
}

TEST_F(BadBrakeFileTest, YamlSyntaxError) {
  const std::string m = LoadError("geometry:", "geometry: {");
  EXPECT_TRUE(Contains(m, path_.string() + ":"));
  EXPECT_TRUE(Contains(m, "YAML syntax error"));
}

// What fuzz/brake_yaml_fuzz found (tests/data/fuzz_regressions/brake_yaml): each file is refused
// with an InputError (a mapping as a key escaped as yaml-cpp's TypedBadConversion).
// The disc's bulk: needed with disc_model surface_bulk, kept (and checked) by a lumped disc's
// file, and its whole mass cannot be the surface layer.
TEST_F(BadBrakeFileTest, TheBulkSectionIsNeededByTheBulkDiscAlone) {
  path_ = dir_.Write("front.yaml",
                     test::ReplaceOnce(text_, "disc_model: surface_bulk", "disc_model: lumped"));
  const BrakeFile lumped = LoadBrakeFile(path_);
  EXPECT_FALSE(lumped.params.HasBulk());
  EXPECT_EQ(lumped.params.hub_conductance, 1.5);
  const std::string without = text_.substr(0, text_.find("\ndisc_bulk:")) + "\n";
  path_ = dir_.Write("front.yaml", without);
  std::string missing;
  try {
    LoadBrakeFile(path_);
  } catch (const InputError& e) {
    missing = e.what();
  }
  EXPECT_TRUE(Contains(missing, "disc_bulk")) << missing;
  const std::string all_surface = LoadError("mass_participation: 0.1", "mass_participation: 1");
  EXPECT_TRUE(Contains(all_surface, "rest of the disc is its bulk")) << all_surface;
  const std::string view = LoadError("rim_view_fraction: 0.15", "rim_view_fraction: 1.5");
  EXPECT_TRUE(Contains(view, "field 'disc_bulk.rim_view_fraction'")) << view;
}

TEST(BrakeParamsIoTest, FuzzRegressionsAreInputErrors) {
  for (const auto& file : test::FuzzRegressions("brake_yaml")) {
    EXPECT_THROW(LoadBrakeFile(file), InputError) << file;
  }
}

}  // namespace
}  // namespace hotlap::brake
