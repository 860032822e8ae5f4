// The ABS wheel-speed filter (brake/wheel_speed_filter.h): a steady signal passes unchanged
// from the first sample, the notch removes a sine at its frequency and passes a slow one, the
// low-pass removes a fast one, "none" is the identity, and the file's mapping is checked.

#include "hotlap/brake/wheel_speed_filter.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "test_util.h"

namespace hotlap::brake {
namespace {

constexpr double kPeriod = 0.005;

// The largest |output - mean| over the last second of 3 s of 30 + sin(2 pi f t).
double RippleAfterSettling(const WheelSpeedFilterParams& p, double f_hz) {
  WheelSpeedFilter filter(p, kPeriod);
  double ripple = 0.0;
  for (int k = 0; k < 600; ++k) {
    const double t = k * kPeriod;
    const double y = filter.Step(30.0 + std::sin(2.0 * std::numbers::pi * f_hz * t));
    if (t >= 2.0) ripple = std::max(ripple, std::abs(y - 30.0));
  }
  return ripple;
}

TEST(WheelSpeedFilterTest, SteadySignalPassesUnchangedFromTheFirstSample) {
  for (const WheelSpeedFilterParams& p :
       {WheelSpeedFilterParams{WheelSpeedFilterKind::kNotch, 55.0, 1.0},
        WheelSpeedFilterParams{WheelSpeedFilterKind::kLowPass, 30.0, std::sqrt(0.5)}}) {
    WheelSpeedFilter filter(p, kPeriod);
    for (int k = 0; k < 50; ++k) EXPECT_NEAR(filter.Step(31.25), 31.25, 1e-12) << k;
  }
}

TEST(WheelSpeedFilterTest, NotchRemovesItsFrequencyAndPassesASlowSignal) {
  const WheelSpeedFilterParams notch{WheelSpeedFilterKind::kNotch, 55.0, 1.0};
  EXPECT_LT(RippleAfterSettling(notch, 55.0), 1e-6);
  EXPECT_GT(RippleAfterSettling(notch, 2.0), 0.95);
  EXPECT_LT(RippleAfterSettling(notch, 2.0), 1.05);
  // Half way from the notch to its band edge it still passes part of the signal.
  EXPECT_GT(RippleAfterSettling(notch, 30.0), 0.3);
}

TEST(WheelSpeedFilterTest, LowPassRemovesAFastSignal) {
  const WheelSpeedFilterParams lp{WheelSpeedFilterKind::kLowPass, 20.0, std::sqrt(0.5)};
  EXPECT_LT(RippleAfterSettling(lp, 60.0), 0.15);
  EXPECT_GT(RippleAfterSettling(lp, 2.0), 0.95);
}

TEST(WheelSpeedFilterTest, NoneIsTheIdentity) {
  WheelSpeedFilter filter(WheelSpeedFilterParams{}, kPeriod);
  for (double x : {1.0, -3.5, 1e9}) EXPECT_EQ(filter.Step(x), x);
}

TEST(WheelSpeedFilterTest, FileMappingIsChecked) {
  const test::TempDir tmp;
  const auto read = [&](const std::string& text) {
    YamlReader y = YamlReader::Load(test::WriteTextFile(tmp.path() / "filter.yaml", text));
    return ReadWheelSpeedFilterParams(y, kPeriod);
  };
  const WheelSpeedFilterParams p = read("{kind: notch, frequency_hz: 55, quality: 2}");
  EXPECT_EQ(p.kind, WheelSpeedFilterKind::kNotch);
  EXPECT_EQ(p.frequency_hz, 55.0);
  EXPECT_EQ(p.quality, 2.0);
  EXPECT_EQ(read("{kind: none}").kind, WheelSpeedFilterKind::kNone);
  EXPECT_THROW(read("{kind: comb, frequency_hz: 55, quality: 2}"), InputError);
  EXPECT_THROW(read("{kind: notch, frequency_hz: 100, quality: 2}"), InputError);  // Nyquist
  EXPECT_THROW(read("{kind: notch, frequency_hz: 55, quality: 0}"), InputError);
  EXPECT_THROW(read("{kind: notch, frequency_hz: 55}"), InputError);
}

}  // namespace
}  // namespace hotlap::brake
