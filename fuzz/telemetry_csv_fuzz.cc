// libFuzzer target: a hotlap telemetry CSV log (Telemetry::Read: CSV, channel names and units, lap
// selection; a file that starts as a MoTeC export goes to the MoTeC reader, as in hotlap replay)
// (docs/reliability.md). Only InputError is an expected outcome.

#include <cstddef>
#include <cstdint>

#include "fuzz_input.h"
#include "hotlap/common/error.h"
#include "hotlap/logs/telemetry.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace fuzz = hotlap::fuzz;
  static const auto path = fuzz::WorkDir() / "log.csv";
  fuzz::WriteInput(path, data, size);
  try {
    (void)hotlap::Telemetry::Read(path, "time");
  } catch (const hotlap::InputError&) {
  }
  try {
    hotlap::TelemetryReadOptions options;
    options.lap = 2;
    (void)hotlap::Telemetry::Read(path, "distance", options);
  } catch (const hotlap::InputError&) {
  }
  return 0;
}
