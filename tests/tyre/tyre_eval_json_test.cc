#include "hotlap/tyre/tyre_eval_json.h"

#include <gtest/gtest.h>

namespace hotlap::tyre {
namespace {

TEST(TyreEvalJsonTest, InputsByColumnForcesAndGrid) {
  const std::vector<double> values = DefaultOperatingPointValues();
  nlohmann::json j = TyreEvalJson("mf", "left.tir", 0.95, values);
  EXPECT_EQ(j["command"], "tyre eval");
  EXPECT_EQ(j["model"], "mf");
  EXPECT_EQ(j["params"], "left.tir");
  EXPECT_DOUBLE_EQ(j["grip_factor"].get<double>(), 0.95);
  const auto& inputs = OperatingPointInputs();
  ASSERT_EQ(j["inputs"].size(), inputs.size());
  for (size_t i = 0; i < inputs.size(); ++i) {
    EXPECT_DOUBLE_EQ(j["inputs"][inputs[i].column].get<double>(), values[i]) << inputs[i].column;
  }
  TyreForces<double> f;
  f.fx = -1200.0;
  f.fy = 3400.0;
  f.mz = -55.5;
  f.mx = 1.0;
  f.my = -30.0;
  j.update(TyreForcesJson(f));
  EXPECT_DOUBLE_EQ(j["fx_N"].get<double>(), -1200.0);
  EXPECT_DOUBLE_EQ(j["fy_N"].get<double>(), 3400.0);
  EXPECT_DOUBLE_EQ(j["mz_Nm"].get<double>(), -55.5);
  EXPECT_DOUBLE_EQ(j["my_Nm"].get<double>(), -30.0);
  TyreGrid g;
  g.points = 12;
  g.peak_abs_fx = 5000.0;
  g.peak_abs_fy = 6000.0;
  g.peak_abs_mz = 150.0;
  AddTyreGridJson(j, g, "grid.csv");
  EXPECT_EQ(j["out"], "grid.csv");
  EXPECT_EQ(j["points"], 12);
  EXPECT_DOUBLE_EQ(j["peak_abs_fy_N"].get<double>(), 6000.0);
  EXPECT_DOUBLE_EQ(j["peak_abs_mz_Nm"].get<double>(), 150.0);
}

}  // namespace
}  // namespace hotlap::tyre
