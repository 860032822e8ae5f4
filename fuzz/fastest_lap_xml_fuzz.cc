// libFuzzer target: a fastest-lap circuit XML (LoadTrackFile of a .xml)
// (docs/reliability.md). Only InputError is an expected outcome.

#include <cstddef>
#include <cstdint>

#include "fuzz_input.h"
#include "hotlap/common/error.h"
#include "hotlap/track/track_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace fuzz = hotlap::fuzz;
  static const auto path = fuzz::WorkDir() / "circuit.xml";
  fuzz::WriteInput(path, data, size);
  try {
    (void)hotlap::track::LoadTrackFile(path);
  } catch (const hotlap::InputError&) {
  }
  return 0;
}
