#include "hotlap/fe/element_kernel.h"

#include <string>

#include <Eigen/LU>

#include "hotlap/common/error.h"

namespace hotlap::fe {

bool ElementKernelSupported(ElementKernel kernel) {
  switch (kernel) {
    case ElementKernel::kPortable:
      return true;
    case ElementKernel::kAvx2:
#if defined(__GNUC__) && defined(__x86_64__)
      __builtin_cpu_init();
      return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
#else
      return false;
#endif
  }
  return false;
}

ElementKernel BestElementKernel() {
  return ElementKernelSupported(ElementKernel::kAvx2) ? ElementKernel::kAvx2
                                                      : ElementKernel::kPortable;
}

const char* ElementKernelName(ElementKernel kernel) {
  return kernel == ElementKernel::kAvx2 ? "avx2" : "portable";
}

ElementKernel ParseElementKernel(std::string_view name, std::string_view what) {
  if (name == "portable") return ElementKernel::kPortable;
  if (name == "avx2") {
    if (!ElementKernelSupported(ElementKernel::kAvx2)) {
      throw InputError(std::string(what) + " avx2: this CPU has no AVX2 and FMA");
    }
    return ElementKernel::kAvx2;
  }
  if (name != "auto") {
    throw InputError(std::string(what) + " '" + std::string(name) +
                     "': use portable, avx2 or auto");
  }
  return BestElementKernel();
}

void CheckElementKernelSupported(ElementKernel kernel) {
  if (!ElementKernelSupported(kernel)) {
    throw InputError(std::string("fe: this CPU cannot run the ") + ElementKernelName(kernel) +
                     " element kernel");
  }
}

namespace internal {

ElementLoopData MakeElementLoopData(const ExplicitModel& model, const Eigen::Vector3d* x,
                                    const Eigen::Vector3d* v, std::array<double, 2>* energy) {
  ElementLoopData d;
  d.elements = model.mesh.elements.data();
  d.element_material = model.mesh.element_material.data();
  d.refs = model.refs.data();
  d.materials = model.materials.data();
  d.rebars = model.rebars.data();
  d.fibre_start = model.fibre_start.data();
  d.fibres = model.fibres_sorted.data();
  d.density = model.elem_density.data();
  d.wave_speed = model.elem_wave_speed.data();
  d.hg_stiffness = model.hg_stiffness.data();
  d.hg_viscous = model.hg_viscous.data();
  d.X = model.mesh.nodes.data();
  d.x = x;
  d.v = v;
  d.energy = energy;
  d.b1 = model.options.bulk_viscosity_linear;
  d.b2 = model.options.bulk_viscosity_quadratic;
  return d;
}

namespace {

// Forces of element e added to the three arrays (indexed by node); its strain and hourglass
// energies to data.energy[e]. False (nothing added) if the element is inverted.
inline bool AddElementForces(const ElementLoopData& data, size_t e, Eigen::Vector3d* f_stored,
                             Eigen::Vector3d* f_bulk, Eigen::Vector3d* f_hourglass) {
  const double b1 = data.b1, b2 = data.b2;
  // Written with 3-vectors and 3x3 matrices only: Eigen's 8x3 products with transposes do not
  // inline well, and this loop is the solver's cost.
  using Eigen::Vector3d;
  std::array<Vector3d, 8> u, vel;
  const auto& nodes = data.elements[e];
  const Hex8Reference& ref = data.refs[e];
  Eigen::Matrix3d F = Eigen::Matrix3d::Zero(), f_dot = Eigen::Matrix3d::Zero();
  for (int a = 0; a < 8; ++a) {
    const Vector3d& xa = data.x[nodes[a]];
    const Eigen::RowVector3d g = ref.grad.row(a);
    F.noalias() += xa * g;
    vel[a] = data.v[nodes[a]];
    f_dot.noalias() += vel[a] * g;
    u[a] = xa - data.X[nodes[a]];
  }
  const double j = F.determinant();
  if (!(j > 0.0)) return false;
  const YeohMaterial& m = data.materials[data.element_material[e]];
  const Eigen::Matrix3d f_inv = F.inverse();
  const Eigen::Matrix3d f_inv_t = f_inv.transpose();
  Eigen::Matrix3d P;
  const double cbrt_j = CubeRoot(j);  // one cube root per element (Yeoh and bulk viscosity)
  double w = CalcYeohPiolaAndEnergy(m, F, j, cbrt_j, f_inv_t, P);
  for (int k = data.fibre_start[e]; k < data.fibre_start[e + 1]; ++k) {
    const FibreLayer& f = data.fibres[k];
    w += AddFibreStress(data.rebars[f.rebar], f, F, P);
  }
  const double v0 = ref.volume_m3;

  // Bulk viscosity (Abaqus/Explicit form): a pressure against the volumetric strain rate,
  // linear b1 rho c_d L_e evol, plus quadratic rho (b2 L_e evol)^2 in compression only.
  const double evol = f_dot.cwiseProduct(f_inv_t).sum();  // tr(F_dot F^-1)
  const double le = ref.length_m * cbrt_j;                // current characteristic length
  const double rho = data.density[e];
  double q = b1 * rho * data.wave_speed[e] * le * evol;
  if (evol < 0.0) q -= rho * (b2 * le * evol) * (b2 * le * evol);
  const Eigen::Matrix3d pv = (-v0 * j * q) * f_inv_t;
  const Eigen::Matrix3d ps = -v0 * P;

  // Hourglass: generalised displacements Q_alpha = sum_a gamma_alpha,a u_a (and rates, only
  // with viscous hourglass control: it is off by default and in the paper's model, and the
  // rates and their forces are a tenth of the element's arithmetic).
  const double khg = data.hg_stiffness[e], chg = data.hg_viscous[e];
  const bool viscous_hg = chg > 0.0;
  std::array<Vector3d, 4> qhg, qdot;
  const auto& gam = ref.hourglass;
  double hg_energy = 0.0;
  for (int al = 0; al < 4; ++al) {
    qhg[al].setZero();
    for (int a = 0; a < 8; ++a) qhg[al] += gam(al, a) * u[a];
    hg_energy += 0.5 * khg * qhg[al].squaredNorm();
  }
  if (viscous_hg) {
    for (int al = 0; al < 4; ++al) {
      qdot[al].setZero();
      for (int a = 0; a < 8; ++a) qdot[al] += gam(al, a) * vel[a];
    }
  }
  data.energy[e] = {v0 * w, hg_energy};
  // Nodal forces: -V0 P B0_a (rubber and cords), -V0 P_v B0_a (bulk viscosity),
  // -k gamma^T Q (hourglass stiffness), -c gamma^T Q_dot (hourglass viscosity).
  for (int a = 0; a < 8; ++a) {
    const Vector3d g = ref.grad.row(a).transpose();
    Vector3d hs = Vector3d::Zero();
    for (int al = 0; al < 4; ++al) hs += gam(al, a) * qhg[al];
    f_stored[nodes[a]] += ps * g - khg * hs;
    f_bulk[nodes[a]] += pv * g;
    if (viscous_hg) {
      Vector3d hv = Vector3d::Zero();
      for (int al = 0; al < 4; ++al) hv += gam(al, a) * qdot[al];
      f_hourglass[nodes[a]] -= chg * hv;
    }
  }
  return true;
}

// The element loop, compiled twice: for the x86-64 baseline and for AVX2 with FMA. `flatten`
// inlines everything it calls (AddElementForces, the Yeoh and cord stresses, Eigen's small
// matrices), so the whole kernel is compiled for the variant's instruction set; the AVX2 variant
// runs only where the CPU has it (ElementKernelSupported).
#define HOTLAP_FE_ELEMENT_RANGE_BODY                                         \
  for (long k = k0; k < k1; ++k) {                                           \
    const long e = list != nullptr ? list[k] : k;                            \
    if (!AddElementForces(data, e, f_stored, f_bulk, f_hourglass)) return e; \
  }                                                                          \
  return -1;

__attribute__((flatten)) long AddElementRangePortable(const ElementLoopData data, const int* list,
                                                      long k0, long k1, Eigen::Vector3d* f_stored,
                                                      Eigen::Vector3d* f_bulk,
                                                      Eigen::Vector3d* f_hourglass) {
  HOTLAP_FE_ELEMENT_RANGE_BODY
}

#if defined(__GNUC__) && defined(__x86_64__)
__attribute__((target("avx2,fma"), flatten)) long AddElementRangeAvx2(
    const ElementLoopData data, const int* list, long k0, long k1, Eigen::Vector3d* f_stored,
    Eigen::Vector3d* f_bulk, Eigen::Vector3d* f_hourglass) {
  HOTLAP_FE_ELEMENT_RANGE_BODY
}
#endif
#undef HOTLAP_FE_ELEMENT_RANGE_BODY

}  // namespace

long AddElementRange(ElementKernel kernel, const ElementLoopData& data, const int* list, long k0,
                     long k1, Eigen::Vector3d* f_stored, Eigen::Vector3d* f_bulk,
                     Eigen::Vector3d* f_hourglass) {
#if defined(__GNUC__) && defined(__x86_64__)
  if (kernel == ElementKernel::kAvx2) {
    return AddElementRangeAvx2(data, list, k0, k1, f_stored, f_bulk, f_hourglass);
  }
#endif
  return AddElementRangePortable(data, list, k0, k1, f_stored, f_bulk, f_hourglass);
}

}  // namespace internal
}  // namespace hotlap::fe
