// libFuzzer target: a MoTeC i2 CSV export (ReadMotecCsv with the shipped channel map, then
// the telemetry rules of Telemetry::FromTable)
// (docs/reliability.md). Only InputError is an expected outcome.

#include <cstddef>
#include <cstdint>

#include "fuzz_input.h"
#include "hotlap/common/error.h"
#include "hotlap/logs/motec_channel_map.h"
#include "hotlap/logs/motec_csv.h"
#include "hotlap/logs/telemetry.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace fuzz = hotlap::fuzz;
  static const hotlap::MotecChannelMap map =
      hotlap::LoadMotecChannelMap(fuzz::CopyOfData("data/motec_channels.yaml", "map.yaml"));
  static const auto path = fuzz::WorkDir() / "export.csv";
  fuzz::WriteInput(path, data, size);
  try {
    hotlap::MotecTable motec = hotlap::ReadMotecCsv(path, map);
    (void)hotlap::Telemetry::FromTable(std::move(motec.table), "time");
  } catch (const hotlap::InputError&) {
  }
  return 0;
}
