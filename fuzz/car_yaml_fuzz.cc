// libFuzzer target: a car file (LoadCar: the car YAML and the tyre, brake and .tir files it names)
// (docs/reliability.md). Only InputError is an expected outcome.

#include <cstddef>
#include <cstdint>

#include "fuzz_input.h"
#include "hotlap/common/error.h"
#include "hotlap/vehicle/car.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace fuzz = hotlap::fuzz;
  // Beside a copy of the Gen-7-like car's files, which a car file names by relative path.
  static const auto path = fuzz::CopyOfData("data/cars/gen7", "gen7") / "fuzz_car.yaml";
  fuzz::WriteInput(path, data, size);
  try {
    (void)hotlap::vehicle::LoadCar(path);
  } catch (const hotlap::InputError&) {
  }
  return 0;
}
