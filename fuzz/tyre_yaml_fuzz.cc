// libFuzzer target: a tyre file (LoadTyreFile: thermal and wear parameters; LoadBrushParams and
// LoadUniTireParams: the force models' parameter files)
// (docs/reliability.md). Only InputError is an expected outcome.

#include <cstddef>
#include <cstdint>

#include "fuzz_input.h"
#include "hotlap/common/error.h"
#include "hotlap/tyre/tyre_force_params_io.h"
#include "hotlap/tyre/tyre_params_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace fuzz = hotlap::fuzz;
  // Beside a copy of the Gen-7-like car's tyre files (a tyre file names its compound file).
  static const auto path = fuzz::CopyOfData("data/cars/gen7/tyres", "tyres") / "fuzz_tyre.yaml";
  fuzz::WriteInput(path, data, size);
  try {
    (void)hotlap::tyre::LoadTyreFile(path);
  } catch (const hotlap::InputError&) {
  }
  // The force model parameter files (brush, UniTire) are tyre files too.
  try {
    (void)hotlap::tyre::LoadBrushParams(path);
  } catch (const hotlap::InputError&) {
  }
  try {
    (void)hotlap::tyre::LoadUniTireParams(path);
  } catch (const hotlap::InputError&) {
  }
  return 0;
}
