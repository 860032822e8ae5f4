// The FE steps' JSON on hand-made results: the energies (with the hourglass share), a step's
// figures in the documented units, the cord strain rounded, and its warning above the allowance.

#include "hotlap/fe/step_json.h"

#include <gtest/gtest.h>

#include "hotlap/fe/explicit_model.h"

namespace hotlap::fe {
namespace {

TEST(FeStepJson, EnergiesAndStepsInTheDocumentedUnits) {
  Energies e;
  e.kinetic = 10.0;
  e.internal = 200.0;
  e.hourglass_stored = 3.0;
  e.hourglass_dissipated = 1.0;
  e.external_work = 214.0;
  const nlohmann::json je = FeEnergiesJson(e);
  EXPECT_EQ(je["hourglass_J"], 4.0);
  EXPECT_EQ(je["hourglass_over_internal"], 0.02);
  EXPECT_EQ(je["balance_error_J"], 0.0);

  InflateResult inf;
  inf.pressure_Pa = 2.4e5;
  inf.outer_radius_before_m = 0.36;
  inf.outer_radius_after_m = 0.3612345678;
  inf.max_cord_strain = 0.0123456;
  const nlohmann::json ji = InflateJson(inf, e);
  EXPECT_EQ(ji["pressure_kPa"], 240.0);
  EXPECT_EQ(ji["outer_radius_after_mm"], 361.235);
  EXPECT_EQ(ji["max_cord_strain"], 0.01235);
  EXPECT_EQ(ji["energies"]["kinetic_J"], 10.0);

  FootprintResult fp;
  fp.contact_area_m2 = 0.0123;
  fp.vertical_stiffness_N_per_m = 2.5e5;
  const nlohmann::json jf = FootprintJson(fp, e);
  EXPECT_EQ(jf["contact_area_cm2"], 123.0);
  EXPECT_EQ(jf["vertical_stiffness_kN_per_m"], 250.0);

  RollResult rr;
  rr.effective_radius_m = 0.3942;
  const nlohmann::json jr = RollJson(rr, e);
  EXPECT_EQ(jr["effective_radius_mm"], 394.2);
  EXPECT_EQ(jr["paper_spin_rad_per_s"], 28.268);
}

TEST(CordStrainWarning, OnlyAboveTheAllowance) {
  EXPECT_EQ(CordStrainWarning("roll", kCordStrainAllowance), "");
  EXPECT_EQ(
      CordStrainWarning("roll", 0.0456),
      "fe roll: warning: a cord reached a strain of 4.6%, above the 3% the stable step allows "
      "for (the safety factor covers some more; a smaller solver.time_step_safety covers "
      "more still)");
  EXPECT_EQ(CordStrainJson(0.045678), 0.04568);
}

}  // namespace
}  // namespace hotlap::fe
