// The ABS configuration file: the shipped paper's case loads with the values the issue names,
// and every kind of mistake is an InputError naming the file and the field.

#include "hotlap/abs/abs_config.h"

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "test_util.h"

namespace {

using hotlap::InputError;
using hotlap::sim::AbsConfig;
using hotlap::sim::LoadAbsConfig;
using hotlap::test::Contains;
using hotlap::test::ReadTextFile;
using hotlap::test::ReplaceOnce;

const std::filesystem::path kPaper = hotlap::test::SourcePath("data/abs/paper.yaml");

TEST(AbsConfigTest, TheShippedFileIsThePapersCase) {
  const AbsConfig c = LoadAbsConfig(kPaper);
  EXPECT_EQ(hotlap::sim::DefaultAbsConfigPath().filename(), "paper.yaml");
  EXPECT_DOUBLE_EQ(c.event.initial_speed_mps, 11.165);
  EXPECT_DOUBLE_EQ(c.event.duration_s, 1.5);
  EXPECT_EQ(c.event.surface, "paper");
  EXPECT_DOUBLE_EQ(c.plant.wheel.vertical_load, 4314.0);
  EXPECT_DOUBLE_EQ(c.plant.wheel.mass, 4314.0 / hotlap::kGravity);
  const auto& paper = c.SurfaceNamed("paper").segments.at(0).law;
  EXPECT_DOUBLE_EQ(paper.static_friction, 0.90);
  EXPECT_DOUBLE_EQ(paper.kinetic_friction, 0.45);
  EXPECT_DOUBLE_EQ(paper.decay, 0.5);
  EXPECT_EQ(c.plant.tyre.kind(), "brush");
  EXPECT_DOUBLE_EQ(c.controller.period_s, 0.005);
  EXPECT_DOUBLE_EQ(c.controller.decel_threshold_mps2, 1.6 * hotlap::kGravity);
  EXPECT_DOUBLE_EQ(c.controller.wheel_radius_m, c.plant.wheel.radius);
  EXPECT_DOUBLE_EQ(c.plant.hydraulics.max_pressure, 13e6);
  EXPECT_EQ(c.DelayTicks(), 2);
  // Laws are uniform surfaces; split is dry then wet.
  ASSERT_EQ(c.surfaces.size(), 4u);
  EXPECT_EQ(c.SurfaceNamed("split").segments.size(), 2u);
  EXPECT_EQ(c.SurfaceNamed("split").segments[1].law_name, "wet");
  EXPECT_EQ(c.brake.name, "abs-wheel-brake-280mm");
}

class AbsConfigErrorTest : public ::testing::Test {
 protected:
  // A copy of the shipped folder with one edit to paper.yaml; returns the error message.
  std::string Error(const std::string& from, const std::string& to) {
    for (const char* f : {"brake.yaml", "tyre_235_75r15_brush.yaml"}) {
      dir_.Write(f, ReadTextFile(hotlap::test::SourcePath(std::string("data/abs/") + f)));
    }
    const auto path = dir_.Write("paper.yaml", ReplaceOnce(ReadTextFile(kPaper), from, to));
    try {
      LoadAbsConfig(path);
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  }
  hotlap::test::TempDir dir_;
};

TEST_F(AbsConfigErrorTest, NamesTheFieldAndTheRange) {
  const std::string m = Error("vertical_load_N: 4314", "vertical_load_N: -4");
  EXPECT_TRUE(Contains(m, "paper.yaml: field 'wheel.vertical_load_N'"));
  EXPECT_TRUE(Contains(m, "> 0 N"));
  EXPECT_TRUE(Contains(Error("  period_s: 0.005", "  period_s: 0.0"), "controller.period_s"));
  EXPECT_TRUE(Contains(Error("high_accel_threshold_g: 5.0", "high_accel_threshold_g: 0.5"),
                       "must be above accel_threshold_g"));
}

TEST_F(AbsConfigErrorTest, UnknownAndMissingKeysAreErrors) {
  EXPECT_TRUE(Contains(Error("  slip_threshold:", "  slip_treshold:"), "slip_treshold"));
  EXPECT_TRUE(Contains(Error("reapply_fraction", "reapply_fraction_x"), "reapply_fraction"));
}

TEST_F(AbsConfigErrorTest, TheDelayMustBeWholeControllerPeriods) {
  EXPECT_TRUE(Contains(Error("  delay_s: 0.01", "  delay_s: 0.012"),
                       "not a whole number of controller periods"));
}

TEST_F(AbsConfigErrorTest, SurfacesReferToLawsThatExist) {
  EXPECT_TRUE(
      Contains(Error("{from_m: 3, law: wet}", "{from_m: 3, law: ice}"), "no friction law 'ice'"));
  EXPECT_TRUE(Contains(Error("{from_m: 0, law: dry}", "{from_m: 1, law: dry}"),
                       "the first segment must start at 0 m"));
  EXPECT_TRUE(Contains(Error("{from_m: 3, law: wet}", "{from_m: 0, law: wet}"),
                       "must be beyond the previous segment"));
  EXPECT_TRUE(Contains(Error("  surface: paper", "  surface: gravel"), "no surface 'gravel'"));
  EXPECT_TRUE(Contains(Error("- name: split", "- name: dry"), "'dry' is used twice"));
}

TEST_F(AbsConfigErrorTest, TheTyreAndBrakeFilesMustExist) {
  EXPECT_TRUE(Contains(Error("tyre_file: tyre_235_75r15_brush.yaml", "tyre_file: none.yaml"),
                       "does not exist"));
}

}  // namespace
