// libFuzzer target: a segment track file (LoadTrackFile of a .yaml: segments, closure, ribbon)
// (docs/reliability.md). Only InputError is an expected outcome.

#include <cstddef>
#include <cstdint>

#include "fuzz_input.h"
#include "hotlap/common/error.h"
#include "hotlap/track/track_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace fuzz = hotlap::fuzz;
  static const auto path = fuzz::WorkDir() / "track.yaml";
  fuzz::WriteInput(path, data, size);
  try {
    (void)hotlap::track::LoadTrackFile(path);
  } catch (const hotlap::InputError&) {
  }
  return 0;
}
