// The `hotlap` Python module's compiled part, `hotlap._hotlap` (python/hotlap/__init__.py is the
// package around it; docs/python.md). Bad input raises ValueError with the message the command
// line prints; a numerical failure raises hotlap.NumericalError.

#include <pybind11/pybind11.h>

#include "hotlap/common/data_path.h"
#include "hotlap/common/error.h"

namespace py = pybind11;

namespace hotlap::python {
void BindTyre(py::module_& m);
void BindSim(py::module_& m);
void BindOcp(py::module_& m);
void BindIdent(py::module_& m);
void BindReport(py::module_& m);
void BindLog(py::module_& m);
void BindRace(py::module_& m);
void BindFe(py::module_& m);
void BindSynth(py::module_& m);
void BindObserve(py::module_& m);
}  // namespace hotlap::python

PYBIND11_MODULE(_hotlap, m) {
  m.doc() = "hotlap: race-car tyre and brake thermal models, fits and optimal laps (compiled part)";
  m.attr("__version__") = HOTLAP_VERSION;
  static py::exception<hotlap::NumericalError> numerical_error(m, "NumericalError",
                                                               PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const hotlap::InputError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const hotlap::NumericalError& e) {
      numerical_error(e.what());
    }
  });
  m.def(
      "data_dir", [] { return hotlap::DataDir().string(); },
      "The folder the built-in cars, tracks and tyres are read from.");
  hotlap::python::BindTyre(m);
  hotlap::python::BindSim(m);
  hotlap::python::BindOcp(m);
  hotlap::python::BindIdent(m);
  hotlap::python::BindReport(m);
  hotlap::python::BindLog(m);
  hotlap::python::BindRace(m);
  hotlap::python::BindFe(m);
  hotlap::python::BindSynth(m);
  hotlap::python::BindObserve(m);
}
