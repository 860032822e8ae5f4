// libFuzzer target: a MoTeC channel map (LoadMotecChannelMap, hotlap replay --channel-map)
// (docs/reliability.md). Only InputError is an expected outcome.

#include <cstddef>
#include <cstdint>

#include "fuzz_input.h"
#include "hotlap/common/error.h"
#include "hotlap/logs/motec_channel_map.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace fuzz = hotlap::fuzz;
  static const auto path = fuzz::WorkDir() / "map.yaml";
  fuzz::WriteInput(path, data, size);
  try {
    (void)hotlap::LoadMotecChannelMap(path);
  } catch (const hotlap::InputError&) {
  }
  return 0;
}
