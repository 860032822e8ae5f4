// FitRunJson on a small hand-made fit: the run's keys, a model parameter with its intervals and
// truth, a held and a nuisance parameter, an undetermined one as null, correlations and channels.

#include "hotlap/ident/fit_run_json.h"

#include <gtest/gtest.h>

#include "ident/fit_run_example.h"

namespace hotlap::ident {
namespace {

TEST(FitRunJson, HoldsTheRunAndItsCorners) {
  FitRun run = testing::MakeExampleFitRun();
  run.result.corners[0].truth = {{"p1", 0.515}};
  const nlohmann::json j = FitRunJson(run);
  EXPECT_EQ(j["command"], "fit tyre");
  EXPECT_EQ(j["telemetry"], "logs/run1.csv");
  EXPECT_EQ(j["car"], "gen7");
  EXPECT_EQ(j["out"], "fitted/car.yaml");
  EXPECT_EQ(j["samples"], 3);
  EXPECT_EQ(j["duration_s"], 1.0);
  EXPECT_EQ(j["elapsed_s"], 1.23456789);
  EXPECT_EQ(j["joint_family_size"], 2);
  EXPECT_EQ(j["options"]["loss"], "huber");
  EXPECT_EQ(j["warnings"][0], "rr: short log");

  const nlohmann::json& rr = j["corners"]["rr"];
  EXPECT_EQ(rr["fitted"], true);
  EXPECT_EQ(rr["rms_tread_C"], 0.512345);
  const nlohmann::json& p1 = rr["parameters"]["p1"];
  EXPECT_EQ(p1["value"], 0.49);
  EXPECT_EQ(p1["ci95"], nlohmann::json({0.47, 0.51}));
  EXPECT_EQ(p1["ci95_joint"], nlohmann::json({0.46, 0.52}));
  EXPECT_EQ(p1["well_determined"], true);
  EXPECT_EQ(p1["start"], 0.3);
  EXPECT_EQ(p1["truth"], 0.515);
  EXPECT_EQ(p1["in_ci95"], false);
  EXPECT_EQ(p1["in_ci95_joint"], true);
  // Undetermined: an infinite standard error is null.
  EXPECT_TRUE(rr["parameters"]["p5"]["std_error"].is_null());
  EXPECT_EQ(rr["parameters"]["p5"]["undetermined"], true);
  // Held at the car's value; the nuisance parameter only under its fit, in display units.
  EXPECT_EQ(rr["parameters"]["p4"]["value"], 7.0);
  EXPECT_EQ(rr["parameters"]["p4"]["held"], true);
  EXPECT_FALSE(rr["parameters"].contains("t0_K"));
  const nlohmann::json& fit = rr["fits"]["thermal"];
  EXPECT_EQ(fit["nuisance"]["t0_K"]["value"], 26.85);
  EXPECT_TRUE(fit["nuisance"]["t0_K"]["ci95_joint"].is_null());
  EXPECT_EQ(fit["held"]["p4"], 7.0);
  EXPECT_EQ(fit["correlation"]["parameters"], nlohmann::json({"p1", "t0_K", "p5"}));
  EXPECT_EQ(fit["correlation"]["matrix"][0][0], 1.0);
  EXPECT_TRUE(fit["correlation"]["matrix"][0][2].is_null());
  EXPECT_EQ(fit["channels"]["tread_temp"]["rms"], 0.5);
  EXPECT_EQ(fit["channels"]["tread_temp"]["noise"], 0.4);
  EXPECT_TRUE(fit["channels"]["tread_temp"]["apparent_lag_s"].is_null());
  EXPECT_EQ(fit["converged"], true);
  EXPECT_EQ(fit["iterations"], 12);
  EXPECT_EQ(fit["warnings"][0], "p5 is undetermined");
}

}  // namespace
}  // namespace hotlap::ident
