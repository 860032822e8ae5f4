// The synth run `hotlap synth` makes: the command's units into the simulation's options, the
// observer noise file "default" found and its process noise taken, the car's parameters named
// when no file gives others, and the printed text.

#include "hotlap/runs/synth_run.h"

#include <string>

#include <gtest/gtest.h>

#include "hotlap/observe/observer_config.h"
#include "hotlap/track/track_io.h"
#include "test_util.h"

namespace hotlap::runs {
namespace {

TEST(SynthRun, OptionsProcessNoiseAndText) {
  vehicle::Car car = vehicle::LoadCar(test::Gen7Dir() / "car.yaml");
  const track::Track track = track::LoadTrack("darlington");
  SynthRunOptions o;
  o.rate_hz = 10.0;
  o.step_m = 4.0;
  o.radius_noise_mm = 0.2;
  o.ambient_C = 30.0;
  o.process_noise = "default";
  const SynthRun run = RunSynth(car, track, o);
  EXPECT_DOUBLE_EQ(run.options.radius_noise_m, 2e-4);
  EXPECT_DOUBLE_EQ(run.options.ambient_temp, 303.15);
  EXPECT_EQ(run.process_noise_file, observe::DefaultObserverConfigPath().string());
  ASSERT_TRUE(run.options.process_noise.has_value());
  EXPECT_EQ(run.params_name, "the car's");
  EXPECT_GT(run.log.inputs.time.size(), 100u);
  const std::string text = SynthRunText(run, car, track);
  EXPECT_TRUE(test::Contains(text, "hotlap synth: car 'gen7' with the car's parameters, 1 lap(s)"));
  EXPECT_TRUE(test::Contains(text, "samples at 10 Hz"));
  EXPECT_TRUE(test::Contains(text, "truth with process noise from "));
  const SynthRun plain = RunSynth(car, track, {.rate_hz = 10.0, .step_m = 4.0});
  EXPECT_TRUE(plain.process_noise_file.empty());
  EXPECT_FALSE(test::Contains(SynthRunText(plain, car, track), "process noise"));
}

}  // namespace
}  // namespace hotlap::runs
