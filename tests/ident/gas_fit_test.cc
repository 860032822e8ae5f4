// The tyre fit's gas stage (issue 42, item 6): a log synthesized from the car's own models (the
// gas-and-rim tyres with their brakes) whose gas path's conductances are moved from the file's
// (carcass-gas x1.5, gas-rim x0.7, rim-air x1.3), with the TPMS channels of `hotlap synth --truth
// car` (0.35 kPa and 0.5 degC noise through a 2 s lag), gives those conductances back inside
// their reported 95% intervals; a log without TPMS channels gets no gas stage. Twenty laps of a
// small oval logged at 2 Hz, one corner, keep it cheap (docs/fitting.md, "The gas path from
// TPMS").

#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "fit_test_util.h"
#include "hotlap/ident/car_log_fit.h"
#include "hotlap/ident/fitted_car.h"
#include "hotlap/ident/tyre_thermal_fit.h"
#include "hotlap/logs/telemetry.h"
#include "hotlap/tyre/tyre_thermal_fields.h"

namespace hotlap::ident {
namespace {

constexpr Corner kFl = Corner::kFrontLeft;
constexpr Corner kRr = Corner::kRearRight;

// The log `options` synthesizes from `truth`, written and read back as `hotlap fit` reads it.
Telemetry SynthesizedTelemetry(const vehicle::Car& truth, const sim::SynthOptions& options,
                               const test::TempDir& dir) {
  const sim::SynthLog log = sim::SynthesizeLog(truth, test::OvalRoad(), options);
  sim::WriteSynthLog(dir.path() / "log.csv", log);
  return Telemetry::Read(dir.path() / "log.csv");
}

CarFitOptions TyreFitOptions(std::vector<Corner> corners) {
  CarFitOptions o;
  o.kind = CarFitKind::kTyre;
  o.corners = std::move(corners);
  o.fit.sensor_lag_s = 0.2;  // synth's temperature sensors
  o.fit.tpms_lag_s = 2.0;    // synth's TPMS
  o.fit.random_starts = 0;   // the thermal stage's random starts are not under test
  o.fit.max_step_s = 0.05;   // the gas path is slow; the tread's 3 s time constant allows it
  o.source_date = "2026-01-01";
  o.source_log = "log.csv";
  return o;
}

const ReportedFit* FitTitled(const CornerFitOutcome& c, const std::string& title) {
  for (const ReportedFit& f : c.fits) {
    if (f.title == title) return &f;
  }
  return nullptr;
}

TEST(GasFitTest, RecoversTheGasPathFromTpms) {
  const vehicle::Car car = test::Gen7Car();
  vehicle::Car truth = car;
  for (auto& t : truth.tyres) {
    ASSERT_TRUE(t.params.HasGasAndRim());
    t.params.carcass_gas_conductance *= 1.5;
    t.params.gas_rim_conductance *= 0.7;
    t.params.rim_air_conductance *= 1.3;
  }
  sim::SynthOptions so;
  so.paper_models = false;  // the car's own models: gas, rim and bulk discs, with TPMS channels
  so.laps = 20;             // about 10 min: the rim's time constant is about 4 min
  so.rate_hz = 2.0;
  test::TempDir dir;
  const Telemetry log = SynthesizedTelemetry(truth, so, dir);
  ASSERT_TRUE(log.Has("pressure", kRr) && log.Has("gas_temp", kRr));

  CarFitResult r = FitCarToLog(car, log, TyreFitOptions({kRr}));
  // 7 tyre and wear parameters and 3 conductances.
  EXPECT_EQ(r.joint_family_size, 10);
  for (const CornerFitOutcome& c : r.corners) {
    const std::string where(CornerName(c.corner));
    const ReportedFit* gas = FitTitled(c, "gas");
    ASSERT_NE(gas, nullptr) << where;
    EXPECT_TRUE(gas->fit.converged) << where;
    const tyre::TyreThermalParams<double>& t = truth.tyre(c.corner).params;
    const std::map<std::string, double> true_value = {
        {"carcass_gas_W_per_K", t.carcass_gas_conductance},
        {"gas_rim_W_per_K", t.gas_rim_conductance},
        {"rim_air_W_per_K", t.rim_air_conductance},
        {"initial_rim_temp_C", truth.initial.rim_temp}};
    for (size_t i = 0; i < gas->fit.parameters.size(); ++i) {
      const FitParameter& p = gas->fit.parameters[i];
      const ParameterEstimate& e = gas->fit.estimates[i];
      const double v = true_value.at(p.key);
      std::printf("%s %-22s truth %9.4g fitted %9.4g se %8.3g 95%% [%.4g, %.4g]\n", where.c_str(),
                  p.key.c_str(), v + p.display_offset, e.value + p.display_offset, e.std_error,
                  e.ci_low + p.display_offset, e.ci_high + p.display_offset);
      // The rim's start absorbs the error of the carcass's (its first samples' median): its
      // interval, which does not carry that, is not checked.
      if (p.role != ParameterRole::kModel) continue;
      EXPECT_FALSE(e.undetermined) << where << " " << p.key;
      EXPECT_TRUE(v >= e.ci_low && v <= e.ci_high)
          << where << " " << p.key << ": truth " << v << " outside [" << e.ci_low << ", "
          << e.ci_high << "]";
    }
    // Residuals at the TPMS noise (0.35 kPa, 0.5 K).
    ASSERT_EQ(gas->fit.channels.size(), 2u) << where;
    EXPECT_NEAR(gas->fit.channels[0].rms, 350.0, 60.0) << where;
    EXPECT_NEAR(gas->fit.channels[1].rms, 0.5, 0.08) << where;
    // The modelled channels beside the measured, and the held gas path.
    EXPECT_EQ(c.channels.size(), 5u) << where;
    EXPECT_EQ(c.channels[3].quantity, "pressure");
    EXPECT_TRUE(gas->held.count("gas_liner_W_per_K")) << where;
    bool rms_pressure = false;
    for (const auto& [key, value] : c.rms) rms_pressure |= key == "rms_pressure_kPa";
    EXPECT_TRUE(rms_pressure) << where;
  }

  // The fitted car holds the conductances in their own sections and reads them back.
  const std::vector<FileEdit>& edits = r.edits.tyres[CornerIndex(kRr)];
  int gas_edits = 0;
  for (const FileEdit& e : edits) {
    gas_edits += e.key == "gas.carcass_gas_W_per_K" || e.key == "gas.gas_rim_W_per_K" ||
                 e.key == "rim.rim_air_W_per_K";
  }
  EXPECT_EQ(gas_edits, 3);
  r.edits.header = {"test"};
  WriteFittedCar(car, dir.path() / "fitted.yaml", r.edits);
  const vehicle::Car fitted = vehicle::LoadCar(dir.path() / "fitted.yaml");
  const ReportedFit* gas = FitTitled(r.corners[0], "gas");
  EXPECT_NEAR(fitted.tyre(kRr).params.rim_air_conductance, gas->fit.estimates[2].value,
              1e-6 * gas->fit.estimates[2].value);
}

TEST(GasFitTest, NoTpmsNoGasStage) {
  const vehicle::Car car = test::Gen7Car();
  sim::SynthOptions so;  // the paper's models: no gas node, so no TPMS channels
  so.rate_hz = 10.0;
  test::TempDir dir;
  const Telemetry log = SynthesizedTelemetry(car, so, dir);
  ASSERT_FALSE(log.Has("pressure", kRr) || log.Has("gas_temp", kRr));
  const CarFitResult r = FitCarToLog(car, log, TyreFitOptions({kRr}));
  EXPECT_EQ(r.joint_family_size, 7);
  const CornerFitOutcome& c = r.corners[0];
  EXPECT_EQ(FitTitled(c, "gas"), nullptr);
  EXPECT_EQ(c.channels.size(), 3u);
  for (const std::string& w : CornerWarnings(c)) {
    EXPECT_EQ(w.find("pressure"), std::string::npos) << w;
  }
  for (const FileEdit& e : r.edits.tyres[CornerIndex(kRr)]) {
    EXPECT_NE(e.key.rfind("gas.", 0), 0u) << e.key;
    EXPECT_NE(e.key.rfind("rim.", 0), 0u) << e.key;
  }
}

}  // namespace
}  // namespace hotlap::ident
