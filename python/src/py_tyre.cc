// hotlap.load_tyre and hotlap.tyre_forces: a tyre force model over NumPy arrays through the
// library's batch evaluation (the Magic Formula's SIMD lanes), the inputs in the units of
// `hotlap tyre eval` (tyre::OperatingPointInputs).

#include <algorithm>
#include <cmath>
#include <span>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "hotlap/common/data_path.h"
#include "hotlap/common/error.h"
#include "hotlap/tyre/tyre_force_model.h"
#include "hotlap/tyre/tyre_grid.h"
#include "py_convert.h"

namespace hotlap::python {

namespace {

using Model = tyre::TyreForceModel<double>;
using Point = tyre::TyreOperatingPoint<double>;
using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

// Forces at n points; inputs[k] holds OperatingPointInputs()[k]'s values in its own units, n of
// them or one (the same at every point). The points are converted and evaluated a block at a
// time, so that the operating points and forces stay in cache and nothing of the size of the
// arrays is allocated besides the outputs.
py::dict TyreForces(const Model& model, const std::vector<Array>& inputs) {
  const auto& spec = tyre::OperatingPointInputs();
  if (inputs.size() != spec.size()) {
    throw InputError(fmt::format("tyre_forces: {} inputs, not {}", inputs.size(), spec.size()));
  }
  py::ssize_t n = 1;
  for (const Array& a : inputs) n = std::max(n, a.size());
  std::vector<const double*> in;
  std::vector<size_t> stride;
  for (size_t k = 0; k < inputs.size(); ++k) {
    if (inputs[k].ndim() != 1 || (inputs[k].size() != n && inputs[k].size() != 1)) {
      throw InputError(fmt::format("tyre_forces: {} has {} values, not {} or 1", spec[k].column,
                                   inputs[k].size(), n));
    }
    in.push_back(inputs[k].data());
    stride.push_back(inputs[k].size() == 1 ? 0 : 1);
  }
  py::array_t<double> fx(n), fy(n), mz(n), mx(n), my(n);
  double* const outputs[5] = {fx.mutable_data(), fy.mutable_data(), mz.mutable_data(),
                              mx.mutable_data(), my.mutable_data()};
  {
    py::gil_scoped_release release;
    constexpr size_t kBlock = 1024;
    std::vector<Point> points(kBlock);
    std::vector<tyre::TyreForces<double>> out(kBlock);
    for (size_t first = 0; first < static_cast<size_t>(n); first += kBlock) {
      const size_t count = std::min(kBlock, static_cast<size_t>(n) - first);
      for (size_t j = 0; j < count; ++j) {
        const size_t i = first + j;
        for (size_t k = 0; k < spec.size(); ++k) {
          points[j].*(spec[k].field) = in[k][i * stride[k]] * spec[k].scale + spec[k].shift;
        }
        if (!(points[j].fz > 0.0)) {
          throw InputError(fmt::format("tyre_forces: fz_N[{}] = {} N; the load must be > 0",
                                       i * stride[0], in[0][i * stride[0]]));
        }
        tyre::CheckOperatingPoint(points[j], "tyre_forces: ");  // as `hotlap tyre eval`'s
      }
      tyre::CalcTyreForcesBatch(model, std::span(points.data(), count),
                                std::span(out.data(), count));
      for (size_t j = 0; j < count; ++j) {
        const tyre::TyreForces<double>& f = out[j];
        if (!std::isfinite(f.fx) || !std::isfinite(f.fy) || !std::isfinite(f.mz)) {
          const size_t i = first + j;
          throw NumericalError(fmt::format(
              "tyre_forces: the model gives a non-finite force at point {} (fz {} N, slip angle "
              "{} deg, slip ratio {})",
              i, in[0][i * stride[0]], in[1][i * stride[1]], in[2][i * stride[2]]));
        }
        outputs[0][first + j] = f.fx;
        outputs[1][first + j] = f.fy;
        outputs[2][first + j] = f.mz;
        outputs[3][first + j] = f.mx;
        outputs[4][first + j] = f.my;
      }
    }
  }
  py::dict d;
  d["fx_N"] = fx;
  d["fy_N"] = fy;
  d["mz_Nm"] = mz;
  d["mx_Nm"] = mx;
  d["my_Nm"] = my;
  return d;
}

}  // namespace

void BindTyre(py::module_& m) {
  py::class_<Model>(m, "TyreModel",
                    "A steady-state tyre force model (Magic Formula from a .tir file, brush or "
                    "UniTire from YAML); load one with hotlap.load_tyre.")
      .def_property_readonly("kind", [](const Model& model) { return std::string(model.kind()); })
      .def("__repr__",
           [](const Model& model) { return fmt::format("<hotlap.TyreModel {}>", model.kind()); });
  m.def(
      "load_tyre",
      [](const std::filesystem::path& name_or_path) {
        return tyre::LoadTyreForceModel(ResolveTyreFile(name_or_path.string()));
      },
      py::arg("name_or_path"),
      "Loads a tyre force model: a .tir file (Magic Formula) or a .yaml file (brush, UniTire), or "
      "a built-in tyre by name ('gen7/left', 'brush_example').");
  m.def("_tyre_forces", &TyreForces, py::arg("model"), py::arg("inputs"));
  py::list names;
  for (const tyre::OperatingPointInput& input : tyre::OperatingPointInputs()) {
    names.append(input.column);
  }
  m.attr("_tyre_input_names") = names;
  py::list defaults;
  for (const double v : tyre::DefaultOperatingPointValues()) defaults.append(v);
  m.attr("_tyre_input_defaults") = defaults;
}

}  // namespace hotlap::python
