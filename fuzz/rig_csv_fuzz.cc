// libFuzzer target: tyre rig data CSV (ReadRigCsv, hotlap tyre fit --data)
// (docs/reliability.md). Only InputError is an expected outcome.

#include <cstddef>
#include <cstdint>

#include "fuzz_input.h"
#include "hotlap/common/error.h"
#include "hotlap/ident/rig_data.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace fuzz = hotlap::fuzz;
  static const auto path = fuzz::WorkDir() / "rig.csv";
  fuzz::WriteInput(path, data, size);
  try {
    (void)hotlap::ident::ReadRigCsv(path);
  } catch (const hotlap::InputError&) {
  }
  return 0;
}
