// hotlap.read_log, hotlap.log_info, hotlap.convert_log: a log of any format hotlap reads (hotlap
// CSV, MoTeC i2 CSV export, MoTeC .ld) as hotlap's channels, described, or written as hotlap's
// CSV: what `hotlap log info|convert` do (docs/telemetry-formats.md).

#include <optional>
#include <string>

#include <fmt/format.h>
#include <pybind11/stl.h>

#include "hotlap/common/error.h"
#include "hotlap/logs/log_info.h"
#include "hotlap/logs/log_table.h"
#include "hotlap/logs/telemetry.h"
#include "py_convert.h"

namespace hotlap::python {

namespace {

TelemetryReadOptions Options(const py::object& channel_map, std::optional<int> lap,
                             std::optional<double> rate_hz) {
  TelemetryReadOptions options = ReadOptionsFrom(channel_map, lap);
  if (rate_hz && !(*rate_hz > 0.0))
    throw InputError(fmt::format("rate_hz {} must be > 0", *rate_hz));
  options.ld_rate_hz = rate_hz;
  return options;
}

std::string PathText(const py::object& path) { return py::str(path).cast<std::string>(); }

py::dict ReadLog(const py::object& path, const py::object& channel_map, std::optional<int> lap,
                 std::optional<double> rate_hz) {
  const LogTable log = ReadLogTable(PathText(path), Options(channel_map, lap, rate_hz));
  py::dict metadata;
  for (const auto& [key, value] : log.table.metadata) metadata[py::str(key)] = value;
  py::dict out;
  out["format"] = std::string(LogFormatName(log.format));
  out["metadata"] = metadata;
  out["channels"] = ColumnsToDict(log.table.columns, log.table.values);
  return out;
}

py::object LogInfoDict(const py::object& path, const py::object& channel_map,
                       std::optional<int> lap, std::optional<double> rate_hz) {
  return ToPython(
      LogInfoJson(DescribeLog(ReadLogTable(PathText(path), Options(channel_map, lap, rate_hz)))));
}

void ConvertLog(const py::object& path, const py::object& out, const py::object& channel_map,
                std::optional<int> lap, std::optional<double> rate_hz) {
  WriteLogCsv(ReadLogTable(PathText(path), Options(channel_map, lap, rate_hz)), PathText(out));
}

}  // namespace

void BindLog(py::module_& m) {
  m.def("read_log", &ReadLog, py::arg("path"), py::kw_only(), py::arg("channel_map") = py::none(),
        py::arg("lap") = py::none(), py::arg("rate_hz") = py::none(),
        "A log (hotlap CSV, MoTeC i2 CSV export or MoTeC .ld) as hotlap reads it: {'format': "
        "str, 'metadata': {key: value}, 'channels': {column: array}} with hotlap's column names "
        "and canonical units (what `hotlap log convert` writes). channel_map: a MoTeC log's "
        "channel map (as --channel-map); lap: only that lap (as --lap); rate_hz: a .ld log's "
        "time base (default its fastest channel's rate).");
  m.def("log_info", &LogInfoDict, py::arg("path"), py::kw_only(),
        py::arg("channel_map") = py::none(), py::arg("lap") = py::none(),
        py::arg("rate_hz") = py::none(),
        "What a log holds: the dict `hotlap log info --json` writes (format, metadata, channels "
        "with unit, rate and samples, laps, duration).");
  m.def("convert_log", &ConvertLog, py::arg("path"), py::arg("out"), py::kw_only(),
        py::arg("channel_map") = py::none(), py::arg("lap") = py::none(),
        py::arg("rate_hz") = py::none(),
        "Writes a log as hotlap's telemetry CSV at `out` (atomically), as `hotlap log convert`.");
}

}  // namespace hotlap::python
