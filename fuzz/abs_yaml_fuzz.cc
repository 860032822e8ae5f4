// libFuzzer target: an ABS configuration (LoadAbsConfig: event, driver, wheel, controller,
// hydraulics) (docs/reliability.md). Only InputError is an expected outcome.

#include <cstddef>
#include <cstdint>

#include "fuzz_input.h"
#include "hotlap/abs/abs_config.h"
#include "hotlap/common/error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace fuzz = hotlap::fuzz;
  // Beside a copy of the shipped ABS files (a configuration names its tyre and brake files).
  static const auto path = fuzz::CopyOfData("data/abs", "abs") / "fuzz_abs.yaml";
  fuzz::WriteInput(path, data, size);
  try {
    (void)hotlap::sim::LoadAbsConfig(path);
  } catch (const hotlap::InputError&) {
  }
  return 0;
}
