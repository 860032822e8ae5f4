// The fit run both `hotlap fit` and `hotlap.fit` make: the kind's words both ways, options out of
// range named in the caller's spelling, and a run that fits the corners asked and writes the
// fitted car with a header naming the program, the run and the log (none without `out`).

#include "hotlap/runs/fit_run.h"

#include <filesystem>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "ident/fit_test_util.h"
#include "test_util.h"

namespace hotlap::runs {
namespace {

namespace fs = std::filesystem;

TEST(FitRun, KindsParseAndNameBothWays) {
  for (ident::CarFitKind kind :
       {ident::CarFitKind::kTyre, ident::CarFitKind::kContactLength, ident::CarFitKind::kBrake}) {
    EXPECT_EQ(ParseFitKind(FitKindName(kind), NameStyle::kPython), kind);
  }
  EXPECT_EQ(test::InputErrorOf([] { ParseFitKind("wheel", NameStyle::kPython); }),
            "kind 'wheel': one of 'tyre', 'contact-length', 'brake'");
}

TEST(FitRun, OptionsOutOfRangeAreNamedInTheCallersSpelling) {
  ident::CarFitOptions o;
  o.fit.solver.loss_scale = 0.0;
  EXPECT_EQ(test::InputErrorOf([&] { CheckFitOptions(o, NameStyle::kPython); }),
            "loss_scale 0 must be > 0");
  EXPECT_EQ(test::InputErrorOf([&] { CheckFitOptions(o, NameStyle::kCommandLine); }),
            "--loss-scale 0 must be > 0");
  o = {};
  o.fit.random_starts = -1;
  EXPECT_EQ(test::InputErrorOf([&] { CheckFitOptions(o, NameStyle::kPython); }),
            "random_starts -1 must be >= 0");
  o = {};
  o.fit.sensor_lag_s = -0.5;
  EXPECT_EQ(test::InputErrorOf([&] { CheckFitOptions(o, NameStyle::kPython); }),
            "sensor_lag_s -0.5 must be >= 0");
  o = {};
  o.wear_sd_mm = 0.0;
  EXPECT_EQ(test::InputErrorOf([&] { CheckFitOptions(o, NameStyle::kPython); }),
            "wear_sd_mm 0 must be > 0");
  EXPECT_NO_THROW(CheckFitOptions({}, NameStyle::kPython));
}

TEST(FitRun, ContactLengthRunFitsTheCornersAskedAndWritesTheFittedCar) {
  const vehicle::Car car = test::Gen7Car();
  test::TempDir dir;
  sim::SynthOptions synth;
  synth.rate_hz = 10.0;
  sim::WriteSynthLog(dir.path() / "oval.csv", sim::SynthesizeLog(car, test::OvalRoad(), synth));
  const Telemetry log = Telemetry::Read(dir.path() / "oval.csv");
  FitRunOptions o;
  o.kind = ident::CarFitKind::kContactLength;
  o.corners = "rr,fl";
  o.threads = 1;
  const ident::FitRun unwritten = RunFit(car, log, o, {"prog", "the log"}, NameStyle::kPython);
  EXPECT_EQ(unwritten.command, "fit contact-length");
  EXPECT_EQ(unwritten.telemetry, log.path().string());
  ASSERT_EQ(unwritten.result.corners.size(), 2u);
  EXPECT_EQ(unwritten.result.corners[0].corner, Corner::kFrontLeft);  // in the car's order
  EXPECT_EQ(unwritten.result.corners[1].corner, Corner::kRearRight);
  EXPECT_EQ(unwritten.time.size(), log.size());
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator()), 1);

  o.out = (dir.path() / "fitted.yaml").string();
  const ident::FitRun run = RunFit(car, log, o, {"prog 9", "LOG"}, NameStyle::kPython);
  EXPECT_EQ(run.out, o.out);
  const std::string fitted = test::ReadTextFile(o.out);
  EXPECT_TRUE(test::Contains(fitted, "Fitted by prog 9 fit contact-length on ")) << fitted;
  EXPECT_TRUE(test::Contains(fitted, " to LOG.")) << fitted;
  EXPECT_EQ(test::InputErrorOf([&] {
              FitRunOptions bad = o;
              bad.corners = "fl,xx";
              RunFit(car, log, bad, {"prog", "log"}, NameStyle::kCommandLine);
            }).find("--corners"),
            0u);
}

}  // namespace
}  // namespace hotlap::runs
