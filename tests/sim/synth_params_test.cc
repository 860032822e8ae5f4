// Parameter override files: strict loading (unknown keys and out-of-range values name the file
// and key) and applying them to each corner of a car.

#include "hotlap/sim/synth_params.h"

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "test_util.h"

namespace hotlap::sim {
namespace {

const char* kFile =
    "name: truth\n"
    "model: parameter_overrides\n"
    "corners:\n"
    "  fr:\n"
    "    tyre:\n"
    "      heat_generation: {p1: 0.426, p5_W_per_m2K: 226.05}   # x 1.5\n"
    "      wear: {wp2: 1.5}              # assumed\n"
    "      contact_length: {p_cp1: 0.0005}  # assumed\n"
    "    brake:\n"
    "      heat_partition: 0.475         # assumed\n"
    "      disc_convection_cholesky_sqrtW_per_K: {l22: 4.0}   # assumed\n";

TEST(SynthParamsTest, LoadsAndAppliesPerCorner) {
  const test::TempDir dir;
  const ParameterOverrides o = LoadParameterOverrides(dir.Write("t.yaml", kFile));
  EXPECT_EQ(o.name, "truth");
  vehicle::Car car = vehicle::LoadCar(test::Gen7Dir() / "car.yaml");
  const vehicle::Car before = car;
  ApplyParameterOverrides(o, car);
  const auto& fr = car.tyre(Corner::kFrontRight).params;
  EXPECT_DOUBLE_EQ(fr.p1, 0.426);
  EXPECT_DOUBLE_EQ(fr.p5, 226.05);
  EXPECT_DOUBLE_EQ(fr.p2, before.tyre(Corner::kFrontRight).params.p2);
  EXPECT_DOUBLE_EQ(fr.wear_exponent, 1.5);
  EXPECT_DOUBLE_EQ(fr.contact_length_coeff, 0.0005);
  EXPECT_DOUBLE_EQ(car.brake(Corner::kFrontRight).params.heat_partition, 0.475);
  EXPECT_DOUBLE_EQ(car.brake(Corner::kFrontRight).params.disc_convection.l22, 4.0);
  // fl shares the front brake file but keeps its values.
  EXPECT_DOUBLE_EQ(car.brake(Corner::kFrontLeft).params.heat_partition,
                   before.brake(Corner::kFrontLeft).params.heat_partition);
  EXPECT_DOUBLE_EQ(car.tyre(Corner::kRearRight).params.p1,
                   before.tyre(Corner::kRearRight).params.p1);
}

TEST(SynthParamsTest, StrictLoading) {
  const test::TempDir dir;
  const auto expect_error = [&](const std::string& from, const std::string& to,
                                const std::string& part) {
    const auto path = dir.Write("bad.yaml", test::ReplaceOnce(kFile, from, to));
    try {
      LoadParameterOverrides(path);
      ADD_FAILURE() << "no error for " << to;
    } catch (const InputError& e) {
      EXPECT_TRUE(test::Contains(e.what(), part)) << e.what();
      EXPECT_TRUE(test::Contains(e.what(), "bad.yaml"));
    }
  };
  expect_error("p1: 0.426", "p1: 1.5", "corners.fr.tyre.heat_generation.p1");
  expect_error("p5_W_per_m2K", "p5_W_per_m2", "p5_W_per_m2");
  expect_error("heat_partition", "gamma", "gamma");
  expect_error("model: parameter_overrides", "model: stock_car", "model");
  expect_error("  fr:", "  xx:", "xx");
}

}  // namespace
}  // namespace hotlap::sim
