// The ABS file's field tables (brake/abs_params_fields.h): they list every number of the
// controller and the hydraulics once, each key reads back from the shipped file into its member
// in SI, and a step or timer shorter than the controller period is refused with the period as
// the range's lower end.

#include "hotlap/brake/abs_params_fields.h"

#include <set>
#include <string>

#include <gtest/gtest.h>

#include "hotlap/brake/abs_params_io.h"
#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "test_util.h"

namespace hotlap::brake {
namespace {

// The file's value of `field` (a dotted path) as text, read as the readers read numbers.
double FileValue(const std::filesystem::path& file, const std::string& field) {
  for (const YamlScalarField& s : ListYamlScalars(file)) {
    if (s.field == field) return *ParseYamlNumber(s.text);
  }
  ADD_FAILURE() << field << " is not in " << file;
  return 0.0;
}

TEST(AbsParamsFields, EveryNumberIsListedOnce) {
  // Every double of the controller but the wheel radius (read with the wheel); every one of
  // the hydraulics. A member added to a struct and not to its table fails here.
  EXPECT_EQ((AbsControllerFields().size() + 1) * sizeof(double), sizeof(AbsControllerParams));
  EXPECT_EQ(BrakeHydraulicsFields().size() * sizeof(double), sizeof(BrakeHydraulicsParams<double>));
  std::set<std::string_view> keys;
  for (const AbsControllerField& f : AbsControllerFields()) {
    EXPECT_TRUE(keys.insert(f.key).second) << f.key;
    EXPECT_NE(f.member, &AbsControllerParams::wheel_radius_m) << f.key;
  }
  for (const BrakeHydraulicsField& f : BrakeHydraulicsFields()) {
    EXPECT_TRUE(keys.insert(f.key).second) << f.key;
  }
  EXPECT_EQ(AbsControllerFields().front().key, "period_s");  // the timers' ranges need it first
}

TEST(AbsParamsFields, EachKeyReadsBackFromTheShippedFileInSi) {
  const std::filesystem::path file = test::SourcePath("data/abs/paper.yaml");
  YamlReader y = YamlReader::Load(file);
  YamlReader controller_section = y.Map("controller");
  const AbsControllerParams controller = ReadAbsControllerParams(controller_section);
  YamlReader hydraulics_section = y.Map("hydraulics");
  const BrakeHydraulicsParams<double> hydraulics = ReadBrakeHydraulicsParams(hydraulics_section);
  for (const AbsControllerField& f : AbsControllerFields()) {
    const double v = FileValue(file, "controller." + std::string(f.key));
    EXPECT_EQ(controller.*f.member, f.ToSi(v)) << f.key;
  }
  for (const BrakeHydraulicsField& f : BrakeHydraulicsFields()) {
    const double v = FileValue(file, "hydraulics." + std::string(f.key));
    EXPECT_EQ(hydraulics.*f.member, f.ToSi(v)) << f.key;
  }
  // The conversions by hand: 1.6 g, 150 MPa/s, 150 N m/MPa.
  EXPECT_DOUBLE_EQ(controller.decel_threshold_mps2, 1.6 * kGravity);
  EXPECT_DOUBLE_EQ(controller.decrease_rate_Pa_per_s, 150e6);
  EXPECT_DOUBLE_EQ(hydraulics.torque_gain, 150e-6);
}

TEST(AbsParamsFields, ATimerShorterThanThePeriodIsRefused) {
  const std::filesystem::path file = test::SourcePath("data/abs/paper.yaml");
  try {
    YamlReader y = YamlReader::Load(file, {{"controller.low_grip_hold_s", 0.001, "override 'x'"}});
    YamlReader section = y.Map("controller");
    ReadAbsControllerParams(section);
    FAIL() << "a 1 ms timer at a 5 ms period was accepted";
  } catch (const InputError& e) {
    EXPECT_TRUE(test::Contains(e.what(), "low_grip_hold_s")) << e.what();
    EXPECT_TRUE(test::Contains(e.what(), "0.005")) << e.what();
  }
}

}  // namespace
}  // namespace hotlap::brake
