#include "hotlap/fe/explicit_solver.h"

#include <string>
#include <utility>

#include "hotlap/common/error.h"

namespace hotlap::fe {

ExplicitSolver::ExplicitSolver(Mesh mesh, std::vector<YeohMaterial> materials,
                               std::vector<RebarMaterial> rebars, const SolverOptions& options)
    : model_(MakeExplicitModel(std::move(mesh), std::move(materials), std::move(rebars), options)),
      state_(MakeInitialState(model_)) {}

void ExplicitSolver::SetRimModes(RimDofMode x_mode, RimDofMode z_mode, RimDofMode spin_mode) {
  if (!state_.rim_settings) throw InputError("fe: SetRimModes needs a rim (SetRim)");
  state_.rim_settings->x_mode = x_mode;
  state_.rim_settings->z_mode = z_mode;
  state_.rim_settings->spin_mode = spin_mode;
}

void ExplicitSolver::set_threads(int threads) {
  if (threads < 0) throw InputError("fe: thread count " + std::to_string(threads) + " < 0");
  step_options_.threads = threads;
}

void ExplicitSolver::set_element_kernel(ElementKernel kernel) {
  CheckElementKernelSupported(kernel);
  step_options_.kernel = kernel;
}

std::vector<double> ExplicitSolver::stick_stiffness() const {
  std::vector<double> k(model_.mass.size());
  for (size_t a = 0; a < k.size(); ++a) k[a] = StickStiffness(model_, state_, a);
  return k;
}

}  // namespace hotlap::fe
