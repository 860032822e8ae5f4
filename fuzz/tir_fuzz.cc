// libFuzzer target: a Magic Formula .tir file (ParseTirFile, in memory)
// (docs/reliability.md). Only InputError is an expected outcome.

#include <cstddef>
#include <cstdint>

#include "fuzz_input.h"
#include "hotlap/common/error.h"
#include "hotlap/tyre/tir_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace fuzz = hotlap::fuzz;
  try {
    (void)hotlap::tyre::ParseTirFile(fuzz::AsText(data, size), "fuzz.tir");
  } catch (const hotlap::InputError&) {
  }
  return 0;
}
