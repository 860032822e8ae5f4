#pragma once
/// @file
/// Conversions between the library's types and Python's for the `hotlap` module: JSON summaries
/// to dicts (the same keys as `--json`), column sets to dicts of NumPy arrays, and NumPy arrays
/// (or sequences) to vectors of doubles.

#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <nlohmann/json.hpp>

#include "hotlap/common/telemetry.h"

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

/// A log given as a CSV path (str or os.PathLike) or as {column name with unit: array}
/// (docs/telemetry-csv.md), read by the library's rules; InputError as Telemetry::Read.
Telemetry LogFrom(const py::handle& telemetry);

}  // namespace hotlap::python
