// libFuzzer target: the finite-element tyre configuration (LoadFeConfig)
// (docs/reliability.md). Only InputError is an expected outcome.

#include <cstddef>
#include <cstdint>

#include "fuzz_input.h"
#include "hotlap/common/error.h"
#include "hotlap/fe/fe_config.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace fuzz = hotlap::fuzz;
  // In a copy of data/fe beside a copy of data/abs (the configuration names ../abs/paper.yaml).
  static const auto path = [] {
    fuzz::CopyOfData("data/abs", "abs");
    return fuzz::CopyOfData("data/fe", "fe") / "fuzz_fe.yaml";
  }();
  fuzz::WriteInput(path, data, size);
  try {
    (void)hotlap::fe::LoadFeConfig(path);
  } catch (const hotlap::InputError&) {
  }
  return 0;
}
