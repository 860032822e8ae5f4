// libFuzzer target: a brake file (LoadBrakeFile: disc and calliper thermal parameters)
// (docs/reliability.md). Only InputError is an expected outcome.

#include <cstddef>
#include <cstdint>

#include "fuzz_input.h"
#include "hotlap/brake/brake_params_io.h"
#include "hotlap/common/error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace fuzz = hotlap::fuzz;
  static const auto path = fuzz::WorkDir() / "brake.yaml";
  fuzz::WriteInput(path, data, size);
  try {
    (void)hotlap::brake::LoadBrakeFile(path);
  } catch (const hotlap::InputError&) {
  }
  return 0;
}
