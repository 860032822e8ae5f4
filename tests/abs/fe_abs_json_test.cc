// FeAbsStopJson on a hand-made FE ABS stop: speeds, cycles (null where there is no window), the
// cord strain rounded and the energies.

#include "hotlap/abs/fe_abs_json.h"

#include <gtest/gtest.h>

namespace hotlap::sim {
namespace {

TEST(FeAbsStopJson, HoldsTheStopAndItsCycles) {
  FeAbsStopResult r;
  r.brake.initial_speed_mps = 8.0;
  r.brake.final_speed_mps = 5.123456789;
  r.brake.max_slip = 0.2;
  r.brake.max_cord_strain = 0.0212345;
  r.cycle_starts_s = {0.0123456789012, 0.05};
  r.cycles.cycles = 2;
  r.cycles.cycles_per_s = 20.0;
  r.cycles.first_cycle_start_s = 0.0123456789012;
  r.cycles.second_cycle_start_s = 0.05;
  r.cycles.fraction_time_lambda_below_0_135 = 0.912345;
  fe::Energies e;
  e.kinetic = 100.0;
  const nlohmann::json j = FeAbsStopJson(r, 0.1, e);
  EXPECT_EQ(j["duration_s"], 0.1);
  EXPECT_EQ(j["initial_speed_mps"], 8.0);
  EXPECT_EQ(j["final_speed_mps"], 5.12346);
  EXPECT_EQ(j["control_cycles"], 2);
  EXPECT_EQ(j["cycle_starts_s"], nlohmann::json({0.0123456789, 0.05}));
  EXPECT_EQ(j["second_cycle_start_s"], 0.05);
  EXPECT_TRUE(j["abs_exit_s"].is_null());
  EXPECT_TRUE(j["max_lambda_after_first_cycle"].is_null());
  EXPECT_EQ(j["fraction_time_lambda_below_0_135"], 0.9123);
  EXPECT_EQ(j["max_cord_strain"], 0.02123);
  EXPECT_EQ(j["energies"]["kinetic_J"], 100.0);
}

}  // namespace
}  // namespace hotlap::sim
