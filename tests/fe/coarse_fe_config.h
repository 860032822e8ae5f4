#pragma once
// The shipped FE tyre file (data/fe/paper_235_75r15.yaml) made cheap for tests: a very coarse
// mesh (720 elements), mass scaling to a 12 us step, a 10 ms roll and a 1 ms history, the lumped
// ABS tuning (data/abs/paper.yaml) named by its absolute path; everything else as shipped. Used by
// the FE command, stop and ensemble tests.

#include <filesystem>
#include <string>

#include "test_util.h"

namespace hotlap::test {

// Writes the coarse configuration to `path` (inflation `pressure_kPa`) and returns `path`.
inline std::filesystem::path WriteCoarseFeConfig(const std::filesystem::path& path,
                                                 const std::string& pressure_kPa = "220") {
  std::string y = ReadTextFile(SourcePath("data/fe/paper_235_75r15.yaml"));
  y = ReplaceOnce(y, "meridional_elements_half: 10", "meridional_elements_half: 5");
  y = ReplaceOnce(y, "circumferential_elements_contact: 24", "circumferential_elements_contact: 8");
  y = ReplaceOnce(y, "circumferential_elements_rest: 60", "circumferential_elements_rest: 16");
  // Its unscaled step is 9.7 us: scaling to 12 us adds about half the tyre's mass (reported).
  y = ReplaceOnce(y, "mass_scaling_min_step_s: 0", "mass_scaling_min_step_s: 1.2e-5");
  // The lumped tuning (no wheel-speed filter): the coarse tyre's bounds were set with it.
  y = ReplaceOnce(y, "config_file: ../abs/fe_tyre.yaml",
                  "config_file: " + SourcePath("data/abs/paper.yaml").string());
  y = ReplaceOnce(y, "lumped_config_file: ../abs/paper.yaml",
                  "lumped_config_file: " + SourcePath("data/abs/paper.yaml").string());
  y = ReplaceOnce(y, "damping_per_s: 250", "damping_per_s: 150");  // mass scaled: heavier
  y = ReplaceOnce(y, "duration_s: 0.1 ", "duration_s: 0.01 ");
  y = ReplaceOnce(y, "history_interval_s: 1.0e-4", "history_interval_s: 1.0e-3");
  y = ReplaceOnce(y, "pressure_kPa: 220 ", "pressure_kPa: " + pressure_kPa + " ");
  return WriteTextFile(path, y);
}

}  // namespace hotlap::test
