// Editing parameter files value by value: what is not edited stays byte for byte.

#include "hotlap/ident/yaml_text_edit.h"

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "test_util.h"

namespace hotlap::ident {
namespace {

const char* kText =
    "# header comment\n"
    "name: x\n"
    "heat_generation:              # 000 Table 4\n"
    "  p1: 0.284                      # share of sliding power (000:9)\n"
    "  p2_J_per_kgN: 7.44e-05\n"
    "wear:\n"
    "  wp1_mm_per_s: 1.2e-06\n"
    "tyre_forces:\n"
    "  fl: {file: tyres/left.tir, pressure_kPa: 137.9}   # set-up\n"
    "  fr:\n"
    "    file: tyres/right.tir\n";

TEST(YamlTextEditTest, ReplacesValuesAndCommentsKeepingEverythingElse) {
  YamlTextEditor e(kText, "f.yaml");
  e.SetValue("heat_generation.p1", "0.43", "fitted 2026 to log.csv");
  e.SetValue("heat_generation.p2_J_per_kgN", "1e-05");
  e.SetValue("tyre_forces.fl.file", "car/tyres/left.tir");
  e.SetValue("tyre_forces.fr.file", "car/tyres/right.tir");
  e.PrependComments({"Fitted by a test."});
  EXPECT_EQ(e.Text(),
            "# Fitted by a test.\n"
            "# header comment\n"
            "name: x\n"
            "heat_generation:              # 000 Table 4\n"
            "  p1: 0.43                       # fitted 2026 to log.csv\n"
            "  p2_J_per_kgN: 1e-05\n"
            "wear:\n"
            "  wp1_mm_per_s: 1.2e-06\n"
            "tyre_forces:\n"
            "  fl: {file: car/tyres/left.tir, pressure_kPa: 137.9}   # set-up\n"
            "  fr:\n"
            "    file: car/tyres/right.tir\n");
}

TEST(YamlTextEditTest, KeysAreFoundByTheirPathOnly) {
  YamlTextEditor e(kText, "f.yaml");
  EXPECT_TRUE(e.Has("wear.wp1_mm_per_s"));
  EXPECT_TRUE(e.Has("tyre_forces.fl.pressure_kPa"));
  EXPECT_FALSE(e.Has("p1"));
  EXPECT_FALSE(e.Has("wear.p1"));
  try {
    e.SetValue("wear.wp2", "1.0");
    FAIL();
  } catch (const InputError& error) {
    EXPECT_TRUE(test::Contains(error.what(), "f.yaml: no value 'wear.wp2'"));
  }
  EXPECT_THROW(e.SetValue("heat_generation", "1"), InputError);  // a mapping, not a value
}

TEST(YamlTextEditTest, FlowValueGetsItsCommentAtTheEndOfTheLine) {
  YamlTextEditor e("heat_generation: {p1: 0.2, p5_W_per_m2K: 100}\n", "f.yaml");
  e.SetValue("heat_generation.p5_W_per_m2K", "150", "fitted");
  EXPECT_EQ(e.Text(), "heat_generation: {p1: 0.2, p5_W_per_m2K: 150}  # p5_W_per_m2K: fitted\n");
}

}  // namespace
}  // namespace hotlap::ident
