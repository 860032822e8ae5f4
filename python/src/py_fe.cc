// hotlap.fe: the finite-element tyre's steps, as `hotlap fe` runs them (docs/fe-tyre.md): the
// same library call (runs::RunFe) and the same summary as `--json`.

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "hotlap/fe/element_kernel.h"
#include "hotlap/runs/fe_run.h"
#include "py_convert.h"

namespace py = pybind11;

namespace hotlap::python {

namespace {

py::object Fe(const std::string& step, const std::string& config, const std::string& out,
              double duration_s, int threads, const std::string& kernel, double step_scale,
              int ensemble, const std::string& perturb, int first_member,
              const std::vector<std::string>& abs_set) {
  runs::FeRunOptions o;
  o.step = step;
  o.config = config;
  o.out = out;
  o.duration_s = duration_s;
  o.threads = threads;
  o.kernel = fe::ParseElementKernel(kernel, "kernel");
  o.step_scale = step_scale;
  o.ensemble = ensemble;
  o.perturbation = sim::ParseFePerturbation(perturb, "perturb");
  o.first_member = first_member;
  o.abs_set = abs_set;
  runs::FeRunResult r;
  {
    py::gil_scoped_release release;
    r = runs::RunFe(o);
  }
  return ToPython(r.summary);
}

}  // namespace

void BindFe(py::module_& m) {
  m.def("fe", &Fe, py::arg("step"), py::arg("config"), py::arg("out"), py::kw_only(),
        py::arg("duration_s") = 0.0, py::arg("threads") = 0, py::arg("kernel") = "auto",
        py::arg("step_scale") = 1.0, py::arg("ensemble") = 0, py::arg("perturb") = "spin",
        py::arg("first_member") = 0, py::arg("abs_set") = std::vector<std::string>{},
        "The finite-element tyre's steps up to `step` (inflate, footprint, roll, abs), their "
        "files written to `out`; with `ensemble` N > 0 the abs step as N perturbed stops "
        "(`perturb`: spin, sum-order, round-off), from member `first_member` of the sequence "
        "(a shard); `abs_set`: \"KEY=VALUE\" overrides of the "
        "ABS file's numbers (e.g. \"controller.reapply_fraction=0.85\"). Returns the summary "
        "`hotlap fe --json` "
        "writes (docs/fe-tyre.md).");
}

}  // namespace hotlap::python
