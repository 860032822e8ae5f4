#pragma once
/// @file
/// Conversions between the library's types and Python's for the `hotlap` module: JSON summaries
/// to dicts (the same keys as `--json`), column sets to dicts of NumPy arrays, and NumPy arrays
/// (or sequences) to vectors of doubles.

#include <optional>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <nlohmann/json.hpp>

#include "hotlap/logs/telemetry.h"

namespace hotlap::python {

namespace py = pybind11;

/// A JSON value as Python objects: objects to dicts (key order kept), arrays to lists, numbers to
/// int or float, null to None.
py::object ToPython(const nlohmann::json& j);

/// A 1-D float64 array holding a copy of `v`.
py::array_t<double> ToArray(const std::vector<double>& v);

/// {name: array} of named columns (e.g. sim::ColumnSet's names and values).
py::dict ColumnsToDict(const std::vector<std::string>& names,
                       const std::vector<std::vector<double>>& values);

/// A 1-D sequence of numbers (a NumPy array of any real type, a list) as doubles; ValueError
/// naming `what` if it is not one-dimensional or not numeric.
std::vector<double> ToVector(const py::handle& values, const std::string& what);

/// A log given as a path (str or os.PathLike: hotlap CSV, MoTeC i2 CSV or MoTeC `.ld`,
/// docs/telemetry-formats.md) or as {column name with unit: array} (docs/telemetry-csv.md), read
/// by the library's rules; InputError as Telemetry::Read. `options` (channel map, lap, `.ld` time
/// base) apply to a path; a dict takes only `options.lap` (its `lap` column).
Telemetry LogFrom(const py::handle& telemetry, const TelemetryReadOptions& options = {});

/// The read options from the keyword arguments `channel_map` (None or a path) and `lap` (None or
/// an int), as `--channel-map` and `--lap`.
TelemetryReadOptions ReadOptionsFrom(const py::object& channel_map, std::optional<int> lap);

}  // namespace hotlap::python
