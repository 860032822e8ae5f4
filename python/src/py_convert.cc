#include "py_convert.h"

#include <algorithm>
#include <cstring>
#include <utility>

#include "hotlap/common/csv.h"
#include "hotlap/common/error.h"
#include "hotlap/logs/lap_select.h"

namespace hotlap::python {

py::object ToPython(const nlohmann::json& j) {
  switch (j.type()) {
    case nlohmann::json::value_t::null:
      return py::none();
    case nlohmann::json::value_t::boolean:
      return py::bool_(j.get<bool>());
    case nlohmann::json::value_t::number_integer:
      return py::int_(j.get<long long>());
    case nlohmann::json::value_t::number_unsigned:
      return py::int_(j.get<unsigned long long>());
    case nlohmann::json::value_t::number_float:
      return py::float_(j.get<double>());
    case nlohmann::json::value_t::string:
      return py::str(j.get<std::string>());
    case nlohmann::json::value_t::array: {
      py::list list;
      for (const nlohmann::json& item : j) list.append(ToPython(item));
      return list;
    }
    case nlohmann::json::value_t::object: {
      py::dict dict;
      for (const auto& [key, value] : j.items()) dict[py::str(key)] = ToPython(value);
      return dict;
    }
    default:
      return py::none();
  }
}

py::array_t<double> ToArray(const std::vector<double>& v) {
  py::array_t<double> out(static_cast<py::ssize_t>(v.size()));
  if (!v.empty()) std::memcpy(out.mutable_data(), v.data(), v.size() * sizeof(double));
  return out;
}

py::dict ColumnsToDict(const std::vector<std::string>& names,
                       const std::vector<std::vector<double>>& values) {
  py::dict out;
  for (size_t i = 0; i < names.size(); ++i) out[py::str(names[i])] = ToArray(values[i]);
  return out;
}

std::vector<double> ToVector(const py::handle& values, const std::string& what) {
  py::array_t<double, py::array::c_style | py::array::forcecast> a;
  try {
    a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(values);
  } catch (const py::error_already_set&) {
    a = {};
  }
  if (!a) throw py::value_error(what + ": not an array of numbers");
  if (a.ndim() != 1) {
    throw py::value_error(what + ": a one-dimensional array is needed, not " +
                          std::to_string(a.ndim()) + "-dimensional");
  }
  return std::vector<double>(a.data(), a.data() + a.size());
}

TelemetryReadOptions ReadOptionsFrom(const py::object& channel_map, std::optional<int> lap) {
  TelemetryReadOptions options;
  if (!channel_map.is_none()) options.channel_map = py::str(channel_map).cast<std::string>();
  options.lap = lap;
  return options;
}

Telemetry LogFrom(const py::handle& telemetry, const TelemetryReadOptions& options) {
  if (py::isinstance<py::str>(telemetry) || py::hasattr(telemetry, "__fspath__")) {
    return Telemetry::Read(py::str(telemetry).cast<std::string>(), "time", options);
  }
  if (!py::isinstance<py::dict>(telemetry)) {
    throw InputError("telemetry: a CSV path or a dict of {column: array}");
  }
  CsvTable table;
  table.path = "<telemetry dict>";
  for (const auto& [key, value] : telemetry.cast<py::dict>()) {
    const std::string name = py::str(key).cast<std::string>();
    table.columns.push_back(name);
    table.values.push_back(ToVector(value, "telemetry['" + name + "']"));
  }
  const size_t rows = table.values.empty() ? 0 : table.values.front().size();
  const bool even = std::all_of(table.values.begin(), table.values.end(),
                                [&](const std::vector<double>& v) { return v.size() == rows; });
  if (options.lap && even) {  // uneven columns: FromTable says so
    for (size_t i = 0; i < rows; ++i) table.line_numbers.push_back(static_cast<int>(i) + 2);
    SelectLap(table, *options.lap);
  }
  return Telemetry::FromTable(std::move(table));
}

}  // namespace hotlap::python
