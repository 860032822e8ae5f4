// A tyre model at one point and over a grid of swept inputs (tyre/tyre_grid.h): the inputs'
// units, the grid's order, its agreement with one-by-one evaluation, and bad input.

#include "hotlap/tyre/tyre_grid.h"

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/tyre/tyre_params_io.h"
#include "test_util.h"

namespace hotlap::tyre {
namespace {

const std::filesystem::path kGridTir =
    test::SourcePath("tests/data/tir/mfeval/MagicFormula61_Parameters.tir");

TEST(OperatingPointFromTest, ConvertsEveryInputToSi) {
  // fz 3000 N, 5 deg slip angle, slip ratio 0.1, -2 deg camber, 30 m/s, 180 kPa, 60 degC.
  const TyreOperatingPoint<double> op =
      OperatingPointFrom({3000.0, 5.0, 0.1, -2.0, 30.0, 180.0, 60.0});
  EXPECT_DOUBLE_EQ(op.fz, 3000.0);
  EXPECT_NEAR(op.slip_angle, 5.0 * M_PI / 180.0, 1e-15);
  EXPECT_DOUBLE_EQ(op.slip_ratio, 0.1);
  EXPECT_NEAR(op.camber, -2.0 * M_PI / 180.0, 1e-15);
  EXPECT_DOUBLE_EQ(op.speed, 30.0);
  EXPECT_DOUBLE_EQ(op.pressure, 180e3);
  EXPECT_DOUBLE_EQ(op.tread_temp, 333.15);
  EXPECT_EQ(DefaultOperatingPointValues().size(), OperatingPointInputs().size());
  EXPECT_THROW(OperatingPointFrom({1.0, 2.0}), InputError);
  // Points no tyre is at are refused, naming the input (UniTire at -300 degC had 48% more grip).
  const auto error_of = [](std::vector<double> v) {
    return test::InputErrorOf([&] { OperatingPointFrom(v); });
  };
  EXPECT_TRUE(test::Contains(error_of({3000, 5, 0, 0, 30, 180, -300}),
                             "tread_temp_C = -300: a tread is above absolute zero"));
  EXPECT_TRUE(test::Contains(error_of({3000, 5, 0, 0, 30, 180, 2500}), "below 2000 degC"));
  EXPECT_TRUE(test::Contains(error_of({3000, 5, 0, 0, 30, -50, 60}),
                             "pressure_kPa = -50: a pressure is not negative"));
  EXPECT_TRUE(test::Contains(error_of({3000, 95, 0, 0, 30, 180, 60}),
                             "slip_angle_deg = 95: a slip angle is within +-90 deg"));
  EXPECT_TRUE(test::Contains(error_of({3000, 5, 0, 0, NAN, 180, 60}), "speed_mps is not a finite"));
  EXPECT_NO_THROW(OperatingPointFrom({3000, -90, -1, 0, -5, 0, -40}));  // reversing, cold: fine
}

TEST(ParseGridAxisTest, ReadsNameAndRange) {
  const GridAxis a = ParseGridAxis("slip-angle-deg=-1:1:0.5");
  EXPECT_EQ(std::string(OperatingPointInputs()[a.input].name), "slip-angle-deg");
  EXPECT_EQ(a.values, (std::vector<double>{-1.0, -0.5, 0.0, 0.5, 1.0}));
  // A step that does not divide the range stops at the last value within it.
  EXPECT_EQ(ParseGridAxis("fz-N=1000:2500:1000").values, (std::vector<double>{1000.0, 2000.0}));
  EXPECT_EQ(ParseGridAxis("speed-mps=10:10:1").values, (std::vector<double>{10.0}));
}

TEST(ParseGridAxisTest, RefusesBadTextWithTheReason) {
  const auto message = [](const std::string& text) {
    return test::InputErrorOf([&] { ParseGridAxis(text); });
  };
  EXPECT_PRED2(test::Contains, message("slip-angle-deg"), "no '='");
  EXPECT_PRED2(test::Contains, message("slip=0:1:0.1"), "unknown input 'slip'");
  EXPECT_PRED2(test::Contains, message("slip=0:1:0.1"), "slip-angle-deg");  // lists the names
  EXPECT_PRED2(test::Contains, message("fz-N=0:1"), "not FROM:TO:STEP");
  EXPECT_PRED2(test::Contains, message("fz-N=0:1:0.1x"), "not FROM:TO:STEP");
  EXPECT_PRED2(test::Contains, message("fz-N=0:1:0"), "STEP > 0");
  EXPECT_PRED2(test::Contains, message("fz-N=0:inf:1"), "finite");
  EXPECT_PRED2(test::Contains, message("fz-N=5:1:1"), "TO is below FROM");
  EXPECT_PRED2(test::Contains, message("fz-N=0:1e7:1"), "more than a million");
}

class TyreGridTest : public ::testing::Test {
 protected:
  const TyreForceModel<double> model_ = LoadTyreForceModel(kGridTir);
};

TEST_F(TyreGridTest, LastAxisFastestAndEqualToOneByOne) {
  const std::vector<double> base = DefaultOperatingPointValues();
  const GridAxis loads = ParseGridAxis("fz-N=2000:6000:2000");
  const GridAxis angles = ParseGridAxis("slip-angle-deg=-6:6:3");
  const TyreGrid g = EvaluateTyreGrid(model_, nullptr, 0.0, base, {loads, angles});
  ASSERT_EQ(g.points, 15u);
  ASSERT_EQ(g.names.size(), OperatingPointInputs().size() + 5);
  EXPECT_EQ(g.names[0], "fz_N");
  EXPECT_EQ(g.names[OperatingPointInputs().size() + 1], "fy_N");
  double peak_fy = 0.0;
  for (size_t i = 0; i < g.points; ++i) {
    const double fz = loads.values[i / 5], alpha = angles.values[i % 5];
    EXPECT_EQ(g.columns[0][i], fz) << i;
    EXPECT_EQ(g.columns[1][i], alpha) << i;
    EXPECT_EQ(g.columns[4][i], base[4]) << i;  // the speed, not swept
    std::vector<double> point = base;
    point[0] = fz;
    point[1] = alpha;
    const TyreForces<double> f = EvaluateTyrePoint(model_, nullptr, 0.0, point);
    const size_t k = OperatingPointInputs().size();
    EXPECT_NEAR(g.columns[k][i], f.fx, 1e-9 * (1.0 + std::abs(f.fx))) << i;
    EXPECT_NEAR(g.columns[k + 1][i], f.fy, 1e-9 * (1.0 + std::abs(f.fy))) << i;
    EXPECT_NEAR(g.columns[k + 2][i], f.mz, 1e-9 * (1.0 + std::abs(f.mz))) << i;
    peak_fy = std::max(peak_fy, std::abs(f.fy));
  }
  EXPECT_NEAR(g.peak_abs_fy, peak_fy, 1e-9 * peak_fy);
  EXPECT_GT(peak_fy, 1000.0);  // 6 deg at 6 kN slides nothing like a stationary tyre
}

TEST_F(TyreGridTest, CompoundScalesTheForcesByItsGripFactor) {
  const TyreCompound compound =
      LoadTyreCompound(test::SourcePath("data/cars/gen7/tyres/compound.yaml"));
  std::vector<double> point = DefaultOperatingPointValues();
  point[1] = 4.0;    // deg
  point[6] = 140.0;  // degC
  const TyreForces<double> plain = EvaluateTyrePoint(model_, nullptr, 0.0, point);
  const TyreForces<double> scaled = EvaluateTyrePoint(model_, &compound, 2.0, point);
  const double g = compound.GripFactor(CelsiusToKelvin(140.0), 2.0);
  EXPECT_NE(g, 1.0);
  EXPECT_NEAR(scaled.fy, g * plain.fy, 1e-9 * std::abs(plain.fy));
  const TyreGrid grid =
      EvaluateTyreGrid(model_, &compound, 2.0, point, {ParseGridAxis("slip-ratio=0:0.1:0.05")});
  const size_t k = OperatingPointInputs().size();
  EXPECT_NEAR(grid.columns[k + 1][0], scaled.fy, 1e-9 * std::abs(plain.fy));
}

TEST_F(TyreGridTest, RefusesBadGrids) {
  const std::vector<double> base = DefaultOperatingPointValues();
  const GridAxis a = ParseGridAxis("slip-ratio=0:0.1:0.05");
  EXPECT_THROW(EvaluateTyreGrid(model_, nullptr, 0.0, base, {}), InputError);
  EXPECT_THROW(EvaluateTyreGrid(model_, nullptr, 0.0, base, {a, a}), InputError);
  EXPECT_THROW(EvaluateTyreGrid(model_, nullptr, 0.0, base,
                                {a, ParseGridAxis("fz-N=1:2:1"), ParseGridAxis("speed-mps=1:2:1"),
                                 ParseGridAxis("camber-deg=1:2:1")}),
               InputError);
  // 1e6 x 3 points.
  EXPECT_THROW(EvaluateTyreGrid(model_, nullptr, 0.0, base,
                                {ParseGridAxis("slip-ratio=0:0.999999:1e-6"),
                                 ParseGridAxis("fz-N=1000:3000:1000")}),
               InputError);
  // Loads reaching zero: refused, and so is a single point at zero load.
  EXPECT_THROW(EvaluateTyreGrid(model_, nullptr, 0.0, base, {ParseGridAxis("fz-N=-1000:1000:500")}),
               InputError);
  std::vector<double> zero = base;
  zero[0] = 0.0;
  EXPECT_THROW(EvaluateTyrePoint(model_, nullptr, 0.0, zero), InputError);
  EXPECT_THROW(EvaluateTyreGrid(model_, nullptr, 0.0, {1.0}, {a}), InputError);
}

}  // namespace
}  // namespace hotlap::tyre
