// FitCarToLog, the library's `hotlap fit`: on a log synthesized from a car whose rear-right
// corner is 50% off the shipped car (p1, p5; gamma 0.8), every parameter it fits comes back
// inside its reported joint interval, every corner asked for is in the result in the order asked,
// the file edits carry the fitted values with their source comments, the threads do not change
// the answer, and bad options or a log without the inputs are InputErrors that say what is wrong.

#include "hotlap/ident/car_log_fit.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <set>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "fit_test_util.h"
#include "hotlap/common/error.h"
#include "hotlap/ident/brake_thermal_fit.h"
#include "hotlap/ident/tyre_thermal_fit.h"
#include "test_util.h"

namespace hotlap::ident {
namespace {

namespace fs = std::filesystem;

constexpr Corner kFl = Corner::kFrontLeft, kFr = Corner::kFrontRight, kRl = Corner::kRearLeft,
                 kRr = Corner::kRearRight;

class CarLogFitTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    car_ = new vehicle::Car(test::Gen7Car());
    truth_ = new vehicle::Car(*car_);
    tyre::TyreThermalParams<double>& t = truth_->tyres[CornerIndex(kRr)].params;
    t.p1 *= 1.5;
    t.p5 *= 1.5;
    truth_->brakes[CornerIndex(kRr)].params.heat_partition = 0.8;
    sim::SynthOptions o;  // one lap, 0.5 degC noise, 0.2 s lag, seed 1
    o.rate_hz = 20.0;
    dir_ = new test::TempDir;
    sim::WriteSynthLog(dir_->path() / "oval.csv", sim::SynthesizeLog(*truth_, test::OvalRoad(), o));
    log_ = new Telemetry(Telemetry::Read(dir_->path() / "oval.csv"));
  }
  static void TearDownTestSuite() {
    delete log_;
    delete dir_;
    delete truth_;
    delete car_;
  }

  // Options as `hotlap fit` would give them, the sensor lag modelled, the truth attached.
  static CarFitOptions Options(CarFitKind kind, std::vector<Corner> corners) {
    CarFitOptions o;
    o.kind = kind;
    o.corners = std::move(corners);
    o.fit.sensor_lag_s = 0.2;
    o.truth = *truth_;
    o.source_date = "2030-01-02";
    return o;
  }

  static vehicle::Car* car_;
  static vehicle::Car* truth_;
  static test::TempDir* dir_;
  static Telemetry* log_;
};

vehicle::Car* CarLogFitTest::car_ = nullptr;
vehicle::Car* CarLogFitTest::truth_ = nullptr;
test::TempDir* CarLogFitTest::dir_ = nullptr;
Telemetry* CarLogFitTest::log_ = nullptr;

// Every model parameter of the corner has a truth, inside its joint interval, and within 5% of
// it where the fit calls it well determined. Returns how many were checked.
int ExpectTruthInsideJointIntervals(const CornerFitOutcome& c) {
  const std::string where(CornerName(c.corner));
  int checked = 0;
  for (const auto& [p, e] : ModelParameters(c)) {
    const auto it = c.truth.find(p->key);
    if (it == c.truth.end()) {
      ADD_FAILURE() << where << " " << p->key << ": no truth";
      continue;
    }
    const double t = it->second - p->display_offset;
    EXPECT_GE(t, e->joint_low) << where << " " << p->key;
    EXPECT_LE(t, e->joint_high) << where << " " << p->key;
    if (e->well_determined) {
      EXPECT_NEAR(e->value, t, 0.05 * std::abs(t)) << where << " " << p->key;
    }
    ++checked;
  }
  return checked;
}

using test::Contains;
using test::InputErrorOf;

TEST_F(CarLogFitTest, TyreFitRecoversTheTruthAndEditsTheFittedValues) {
  const CarFitResult r = FitCarToLog(*car_, *log_, Options(CarFitKind::kTyre, {kRr}));
  ASSERT_EQ(r.corners.size(), 1u);
  const CornerFitOutcome& rr = r.corners[0];
  EXPECT_EQ(rr.corner, kRr);
  ASSERT_TRUE(rr.fitted);
  ASSERT_EQ(rr.fits.size(), 2u);
  EXPECT_EQ(rr.fits[0].title, "thermal");
  EXPECT_EQ(rr.fits[1].title, "wear");
  EXPECT_EQ(r.joint_family_size, 7);  // p1..p5, wp1, wp2 of one corner
  EXPECT_EQ(rr.fits[0].fit.parameters.size() + rr.fits[1].fit.parameters.size(),
            rr.fits[0].fit.estimates.size() + rr.fits[1].fit.estimates.size());
  EXPECT_EQ(ExpectTruthInsideJointIntervals(rr), 7);
  // The 50% change is found: p1 is always well determined by a lap.
  const auto params = ModelParameters(rr);
  ASSERT_EQ(params[0].first->key, "p1");
  EXPECT_TRUE(params[0].second->well_determined);
  EXPECT_NEAR(params[0].second->value, truth_->tyre(kRr).params.p1,
              0.05 * truth_->tyre(kRr).params.p1);
  EXPECT_GT(std::abs(params[0].second->value - car_->tyre(kRr).params.p1),
            0.2 * car_->tyre(kRr).params.p1);
  // RMS at the 0.5 degC noise.
  ASSERT_GE(rr.rms.size(), 2u);
  EXPECT_EQ(rr.rms[0].first, "rms_tread_C");
  EXPECT_NEAR(rr.rms[0].second, 0.5, 0.1);
  // Measured beside modelled at every sample, in degC.
  ASSERT_EQ(rr.channels.size(), 3u);
  EXPECT_EQ(rr.channels[0].quantity, "tread_temp");
  EXPECT_EQ(rr.channels[0].measured.size(), log_->size());
  EXPECT_EQ(rr.channels[0].model.size(), log_->size());
  EXPECT_GT(rr.channels[0].model[0], 0.0);
  EXPECT_LT(rr.channels[0].model[0], 200.0);

  // One edit per model parameter, valued as fitted, commented with the date and the log.
  const std::vector<FileEdit>& edits = r.edits.tyres[CornerIndex(kRr)];
  ASSERT_EQ(edits.size(), 7u);
  for (size_t k = 0; k < edits.size(); ++k) {
    EXPECT_DOUBLE_EQ(edits[k].value, params[k].second->value) << edits[k].key;
    EXPECT_EQ(edits[k].comment.rfind("fitted 2030-01-02 to oval.csv", 0), 0u) << edits[k].comment;
  }
  EXPECT_EQ(edits[0].key, "heat_generation.p1");
  EXPECT_EQ(edits[5].key, "wear.wp1_mm_per_s");
  for (Corner other : {kFl, kFr, kRl}) EXPECT_TRUE(r.edits.tyres[CornerIndex(other)].empty());
  for (const auto& b : r.edits.brakes) EXPECT_TRUE(b.empty());
  EXPECT_TRUE(r.edits.header.empty());  // the caller's
}

TEST_F(CarLogFitTest, WearPerLapFitsWp1AndHoldsWp2) {
  CarFitOptions o = Options(CarFitKind::kTyre, {kFl});
  o.wear_per_lap_mm = {{kFl, 0.02}};
  o.laps = 2;
  o.fit.random_starts = 2;
  const CarFitResult r = FitCarToLog(*car_, *log_, o);
  ASSERT_EQ(r.corners.size(), 1u);
  const CornerFitOutcome& fl = r.corners[0];
  ASSERT_EQ(fl.fits.size(), 2u);
  const ReportedFit& wear = fl.fits[1];
  ASSERT_EQ(wear.title, "wear");
  ASSERT_EQ(wear.fit.parameters.size(), 1u);
  EXPECT_EQ(wear.fit.parameters[0].key, "wp1_mm_per_s");
  ASSERT_EQ(wear.held.count("wp2"), 1u);
  EXPECT_DOUBLE_EQ(wear.held.at("wp2"), car_->tyre(kFl).params.wear_exponent);
  EXPECT_TRUE(fl.fits[0].held.empty());
  // Two laps of 0.02 mm: the wear model ends at 0.04 mm.
  ASSERT_EQ(fl.channels.size(), 3u);
  EXPECT_NEAR(fl.channels[2].model.back() - fl.channels[2].model.front(), 0.04, 0.004);
}

TEST_F(CarLogFitTest, ContactLengthNamesEveryCornerInTheOrderAsked) {
  const std::vector<Corner> order = {kRr, kFl, kRl, kFr};
  CarFitOptions o = Options(CarFitKind::kContactLength, order);
  o.source_log = "named.csv";
  const CarFitResult r = FitCarToLog(*car_, *log_, o);
  ASSERT_EQ(r.corners.size(), order.size());
  EXPECT_EQ(r.joint_family_size, 8);
  for (size_t n = 0; n < order.size(); ++n) {
    const CornerFitOutcome& c = r.corners[n];
    EXPECT_EQ(c.corner, order[n]);
    EXPECT_TRUE(c.fitted) << CornerName(c.corner);
    EXPECT_EQ(ExpectTruthInsideJointIntervals(c), 2);
    ASSERT_EQ(c.rms.size(), 1u);
    EXPECT_EQ(c.rms[0].first, "rms_rolling_radius_mm");
    EXPECT_NEAR(c.rms[0].second, 0.1, 0.02);  // the 0.1 mm sensor noise
    const std::vector<FileEdit>& e = r.edits.tyres[CornerIndex(c.corner)];
    ASSERT_EQ(e.size(), 2u);
    EXPECT_EQ(e[0].key, "contact_length.p_cp1");
    EXPECT_EQ(e[1].key, "contact_length.p_cp2");
    EXPECT_TRUE(Contains(e[0].comment, "to named.csv")) << e[0].comment;
  }
}

TEST_F(CarLogFitTest, BrakeFitFindsGammaAndEditsGammaXiAndTheCholeskyEntries) {
  const CarFitResult r = FitCarToLog(*car_, *log_, Options(CarFitKind::kBrake, {kRr}));
  ASSERT_EQ(r.corners.size(), 1u);
  const CornerFitOutcome& rr = r.corners[0];
  ASSERT_TRUE(rr.fitted);
  EXPECT_EQ(r.joint_family_size, 14);
  EXPECT_EQ(ExpectTruthInsideJointIntervals(rr), 14);
  const auto params = ModelParameters(rr);
  ASSERT_EQ(params[0].first->key, "heat_partition");
  EXPECT_NEAR(params[0].second->value, 0.8, 0.02);
  // gamma and xi as reported, the twelve entries of L as solved (the file stores L).
  std::set<std::string> keys;
  for (const FileEdit& e : r.edits.brakes[CornerIndex(kRr)]) keys.insert(e.key);
  const std::vector<std::string>& expected = BrakeParameterKeys();
  EXPECT_EQ(keys, std::set<std::string>(expected.begin(), expected.end()));
  EXPECT_DOUBLE_EQ(r.edits.brakes[CornerIndex(kRr)][0].value, params[0].second->value);
  for (const auto& t : r.edits.tyres) EXPECT_TRUE(t.empty());
}

TEST_F(CarLogFitTest, ThreadsDoNotChangeTheResult) {
  CarFitOptions o = Options(CarFitKind::kTyre, {kFr, kRr});
  o.fit.random_starts = 2;
  o.threads = 1;
  const CarFitResult one = FitCarToLog(*car_, *log_, o);
  o.threads = 2;
  const CarFitResult two = FitCarToLog(*car_, *log_, o);
  ASSERT_EQ(one.corners.size(), 2u);
  ASSERT_EQ(two.corners.size(), 2u);
  for (size_t n = 0; n < 2; ++n) {
    const auto a = ModelParameters(one.corners[n]), b = ModelParameters(two.corners[n]);
    ASSERT_EQ(a.size(), 7u);
    ASSERT_EQ(a.size(), b.size());
    for (size_t k = 0; k < a.size(); ++k) {
      EXPECT_EQ(a[k].second->value, b[k].second->value) << a[k].first->key;
      EXPECT_EQ(a[k].second->std_error, b[k].second->std_error) << a[k].first->key;
      EXPECT_EQ(a[k].second->joint_high, b[k].second->joint_high) << a[k].first->key;
    }
    EXPECT_EQ(CornerWarnings(one.corners[n]), CornerWarnings(two.corners[n]));
  }
  for (int i = 0; i < 4; ++i) {
    ASSERT_EQ(one.edits.tyres[i].size(), two.edits.tyres[i].size());
    for (size_t k = 0; k < one.edits.tyres[i].size(); ++k) {
      EXPECT_EQ(one.edits.tyres[i][k].value, two.edits.tyres[i][k].value);
      EXPECT_EQ(one.edits.tyres[i][k].comment, two.edits.tyres[i][k].comment);
    }
  }
}

TEST_F(CarLogFitTest, BadOptionsAreInputErrorsSayingWhatIsWrong) {
  const auto message = [&](const std::function<void(CarFitOptions&)>& spoil) {
    CarFitOptions o = Options(CarFitKind::kTyre, {kFl});
    spoil(o);
    return InputErrorOf([&] { FitCarToLog(*car_, *log_, o); });
  };
  EXPECT_TRUE(Contains(message([](CarFitOptions& o) { o.threads = 0; }),
                       "threads must be at least 1 (got 0)"));
  EXPECT_TRUE(Contains(message([](CarFitOptions& o) { o.corners.clear(); }), "no corner"));
  EXPECT_TRUE(Contains(message([](CarFitOptions& o) {
                         o.corners = {kRr, kFl, kRr};
                       }),
                       "corner 'rr' is asked for more than once"));
  EXPECT_TRUE(Contains(message([](CarFitOptions& o) { o.corners = {static_cast<Corner>(7)}; }),
                       "unknown corner (7)"));
  EXPECT_TRUE(Contains(message([](CarFitOptions& o) { o.laps = 0; }), "laps must be at least 1"));
  EXPECT_TRUE(Contains(message([](CarFitOptions& o) { o.wear_sd_mm = 0.0; }),
                       "wear standard deviation must be positive"));
  // The corner list as a user writes it: an unknown name is refused by the parser.
  EXPECT_TRUE(
      Contains(InputErrorOf([] { ParseCornerList("fl,xx", "--corners"); }), "unknown corner 'xx'"));
}

TEST_F(CarLogFitTest, ALogWithoutTheInputsIsAnInputErrorNamingTheColumn) {
  // Loads and radii, but no longitudinal forces or slip: enough for the contact length only.
  std::string text = "time_s,speed_mps,ambient_temp_C,track_temp_C";
  for (const char* c : {"fl", "fr", "rl", "rr"}) {
    text += fmt::format(",fz_{0}_N,rolling_radius_{0}_m", c);
  }
  text += "\n";
  for (int k = 0; k < 40; ++k) {
    text += fmt::format("{},60,25,40", 0.05 * k);
    for (int c = 0; c < 4; ++c) text += fmt::format(",{},{}", 4000 + 50 * k, 0.33 - 1e-5 * k);
    text += "\n";
  }
  const fs::path path = dir_->Write("no_forces.csv", text);
  const Telemetry log = Telemetry::Read(path);
  for (CarFitKind kind : {CarFitKind::kTyre, CarFitKind::kBrake}) {
    const std::string m = InputErrorOf([&] { FitCarToLog(*car_, log, Options(kind, {kFl})); });
    EXPECT_TRUE(Contains(m, "no_forces.csv")) << m;
    EXPECT_TRUE(Contains(m, "missing column 'fx_fl_N'")) << m;
  }
  // Without the loads the contact length cannot be fitted either.
  const fs::path no_fz = dir_->Write("no_fz.csv", "time_s,rolling_radius_rr_m\n0,0.33\n0.1,0.33\n");
  const std::string m = InputErrorOf([&] {
    FitCarToLog(*car_, Telemetry::Read(no_fz), Options(CarFitKind::kContactLength, {kRr}));
  });
  EXPECT_TRUE(Contains(m, "no_fz.csv")) << m;
  EXPECT_TRUE(Contains(m, "fz_rr_N")) << m;
}

TEST_F(CarLogFitTest, AMissingMeasuredChannelIsAWarningOfItsCorner) {
  // The shipped example log has the inputs but no rolling radius.
  const Telemetry example =
      Telemetry::Read(fs::path(HOTLAP_SOURCE_DIR) / "data/telemetry/darlington_example.csv");
  const CarFitResult r =
      FitCarToLog(*car_, example, Options(CarFitKind::kContactLength, {kFl, kRr}));
  ASSERT_EQ(r.corners.size(), 2u);
  for (const CornerFitOutcome& c : r.corners) {
    EXPECT_FALSE(c.fitted);
    EXPECT_TRUE(c.fits.empty());
    const std::vector<std::string> warnings = CornerWarnings(c);
    ASSERT_FALSE(warnings.empty()) << CornerName(c.corner);
    EXPECT_TRUE(Contains(warnings[0], "rolling_radius")) << warnings[0];
    EXPECT_TRUE(r.edits.tyres[CornerIndex(c.corner)].empty());
  }
}

}  // namespace
}  // namespace hotlap::ident
