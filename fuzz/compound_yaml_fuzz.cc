// libFuzzer target: a tyre compound file (LoadTyreCompound: grip and wear-rate cubics)
// (docs/reliability.md). Only InputError is an expected outcome.

#include <cstddef>
#include <cstdint>

#include "fuzz_input.h"
#include "hotlap/common/error.h"
#include "hotlap/tyre/tyre_params_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace fuzz = hotlap::fuzz;
  static const auto path = fuzz::WorkDir() / "compound.yaml";
  fuzz::WriteInput(path, data, size);
  try {
    (void)hotlap::tyre::LoadTyreCompound(path);
  } catch (const hotlap::InputError&) {
  }
  return 0;
}
