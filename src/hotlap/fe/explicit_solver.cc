#include "hotlap/fe/explicit_solver.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>
#include <utility>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/LU>

#include "hotlap/common/error.h"
#include "hotlap/fe/checkpoint.h"

#ifdef _OPENMP
#include <omp.h>
#endif

namespace hotlap::fe {

namespace {

using Mat83 = Eigen::Matrix<double, 8, 3>;

// Sums over nodes and elements are taken over blocks of this many terms (each block in order,
// then the blocks in order), so that they do not depend on the thread count.
constexpr long kSumBlock = 512;

// Central differences with the damping force lagged half a step are stable for a mode of
// frequency omega and damping rate mu = 2 xi omega while (omega dt)^2 / 4 + mu dt / 2 <= 1, i.e.
// dt <= (2 / omega^2)(sqrt(omega^2 + mu^2 / 4) - mu / 2) = (2 / omega)(sqrt(1 + xi^2) - xi).
// Decreasing in both, so the largest frequency and the largest damping rate give a safe step.
double DampedStableStep(double omega2, double mu) {
  return 2.0 / omega2 * (std::sqrt(omega2 + 0.25 * mu * mu) - 0.5 * mu);
}

Eigen::Vector3d Vec3Zero() { return Eigen::Vector3d::Zero(); }

long Blocks(size_t n) { return (static_cast<long>(n) + kSumBlock - 1) / kSumBlock; }

Eigen::Matrix3d RotationY(double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  Eigen::Matrix3d r;
  r << c, 0, s, 0, 1, 0, -s, 0, c;
  return r;
}

// omega y-hat x r.
Eigen::Vector3d SpinVelocity(double omega, const Eigen::Vector3d& r) {
  return {omega * r.z(), 0.0, -omega * r.x()};
}

}  // namespace

ExplicitSolver::ExplicitSolver(Mesh mesh, std::vector<YeohMaterial> materials,
                               std::vector<RebarMaterial> rebars, const SolverOptions& options)
    : mesh_(std::move(mesh)),
      materials_(std::move(materials)),
      rebars_(std::move(rebars)),
      options_(options) {
  const size_t nn = mesh_.nodes.size(), ne = mesh_.elements.size();
  X_ = mesh_.nodes;
  x_ = X_;
  v_.assign(nn, Eigen::Vector3d::Zero());
  applied_ = reaction_ = v_;
  f_stored_ = f_dissip_bv_ = f_dissip_hg_ = f_damp_ = f_contact_ = f_friction_ = f_external_ = v_;
  contact_normal_.assign(nn, 0.0);
  stick_extension_.assign(nn, Eigen::Vector2d::Zero());
  on_road_.assign(nn, 0);
  fixed_.assign(nn, {0, 0, 0});
  fixed_velocity_ = v_;
  mass_.assign(nn, 0.0);
  is_rim_node_.assign(nn, 0);

  // Cords sorted by host element (CSR).
  fibres_sorted_ = mesh_.fibres;
  std::stable_sort(fibres_sorted_.begin(), fibres_sorted_.end(),
                   [](const FibreLayer& a, const FibreLayer& b) { return a.element < b.element; });
  fibre_start_.assign(ne + 1, 0);
  for (const FibreLayer& f : fibres_sorted_) ++fibre_start_[f.element + 1];
  for (size_t e = 0; e < ne; ++e) fibre_start_[e + 1] += fibre_start_[e];

  refs_.resize(ne);
  elem_density_.resize(ne);
  elem_wave_speed_.resize(ne);
  hg_stiffness_.resize(ne);
  hg_viscous_.resize(ne);
  const double b1 = options_.bulk_viscosity_linear;
  double stable = std::numeric_limits<double>::infinity();
  double stable_unscaled = stable;
  for (size_t e = 0; e < ne; ++e) {
    Mat83 xe;
    for (int a = 0; a < 8; ++a) xe.row(a) = X_[mesh_.elements[e][a]].transpose();
    refs_[e] = CalcHex8Reference(xe);
    const YeohMaterial& m = materials_.at(mesh_.element_material[e]);
    const double mu0 = InitialShearModulus(m);
    const double rubber_modulus = m.bulk_modulus_Pa + 4.0 / 3.0 * mu0;
    const double grad2 = refs_[e].grad.squaredNorm();
    const double v0 = refs_[e].volume_m3;
    // Highest frequency with lumped mass (rho V0 / 8 per node), bounded term by term (the
    // largest eigenvalue of a sum is at most the sum of the largest): rubber omega^2 <=
    // 8 (K + 4/3 mu0) / rho sum_a |B0_a|^2 (Flanagan & Belytschko 1981); each cord's tangent
    // V0 phi E (g g^T) (x) (F a0 (F a0)^T + E_f I), g_a = B0_a . a0, has the largest eigenvalue
    // V0 phi E |g|^2 (lambda^2 + E_f) = V0 phi E |g|^2 (1 + 3 E_f); the hourglass stiffness
    // k Gamma^T Gamma (x) I, Gamma the 4 x 8 matrix of the vectors gamma_alpha, has k
    // lambda_max(Gamma Gamma^T).
    double rho = m.density_kg_per_m3;
    double cord_stiffness = 0.0;  // sum phi E (1 + 3 E_max) |g|^2
    for (int k = fibre_start_[e]; k < fibre_start_[e + 1]; ++k) {
      const FibreLayer& f = fibres_sorted_[k];
      const RebarMaterial& r = rebars_.at(f.rebar);
      rho += f.volume_fraction * r.density_kg_per_m3;
      const double g2 = (refs_[e].grad * f.direction).squaredNorm();
      cord_stiffness +=
          f.volume_fraction * r.youngs_modulus_Pa * (1.0 + 3.0 * kCordStrainAllowance) * g2;
    }
    mass_report_.physical_mass_kg += rho * v0;
    const Eigen::Matrix4d gg = refs_[e].hourglass * refs_[e].hourglass.transpose();
    const double hg_eig = Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d>(gg, Eigen::EigenvaluesOnly)
                              .eigenvalues()
                              .maxCoeff();
    const double khg = options_.hourglass_stiffness * mu0 * v0 * grad2 / 8.0;
    // Bulk viscosity and viscous hourglass act on the rubber's volumetric and hourglass modes:
    // they use the rubber's dilatational wave speed (with the cords' mass).
    const auto wave_speed = [&](double density) { return std::sqrt(rubber_modulus / density); };
    const auto viscous_hg = [&](double density) {
      return options_.hourglass_viscous * density * wave_speed(density) * std::pow(v0, 2.0 / 3.0) /
             4.0;
    };
    const double omega2 = 8.0 * (rubber_modulus * grad2 + cord_stiffness + khg * hg_eig / v0) / rho;
    // Damping rates (largest eigenvalue over the lumped mass): the linear bulk viscosity is the
    // rank-one b1 rho c L_e V0 B0 B0^T at the reference state, rate 8 b1 c L_e sum_a |B0_a|^2;
    // the viscous hourglass c_hg Gamma^T Gamma (x) I, rate 8 c_hg lambda_max / (rho V0).
    const double mu = 8.0 * b1 * wave_speed(rho) * refs_[e].length_m * grad2 +
                      8.0 * viscous_hg(rho) * hg_eig / (rho * v0);
    // Scaling rho by s scales omega and mu by 1/sqrt(s), so the step by sqrt(s).
    double dt_e = DampedStableStep(omega2, mu);
    stable_unscaled = std::min(stable_unscaled, dt_e);
    if (options_.mass_scaling_min_step_s > 0.0 && dt_e < options_.mass_scaling_min_step_s) {
      const double scale = std::pow(options_.mass_scaling_min_step_s / dt_e, 2);
      mass_report_.added_mass_kg += (scale - 1.0) * rho * v0;
      ++mass_report_.scaled_elements;
      rho *= scale;
      dt_e = options_.mass_scaling_min_step_s;
    }
    stable = std::min(stable, dt_e);
    elem_density_[e] = rho;
    elem_wave_speed_[e] = wave_speed(rho);
    hg_stiffness_[e] = khg;
    hg_viscous_[e] = viscous_hg(rho);
    for (int a = 0; a < 8; ++a) mass_[mesh_.elements[e][a]] += rho * v0 / 8.0;
  }
  // Element colours, greedy: each element takes the lowest colour that no element sharing one of
  // its nodes has yet (a structured hexahedral mesh needs 8).
  std::vector<std::uint64_t> node_colours(nn, 0);
  std::vector<int> colour(ne);
  int n_colours = 0;
  for (size_t e = 0; e < ne; ++e) {
    std::uint64_t used = 0;
    for (int n : mesh_.elements[e]) used |= node_colours[n];
    if (~used == 0) throw NumericalError("fe: more than 64 element colours needed");
    int c = 0;
    while (used & (std::uint64_t{1} << c)) ++c;
    colour[e] = c;
    n_colours = std::max(n_colours, c + 1);
    for (int n : mesh_.elements[e]) node_colours[n] |= std::uint64_t{1} << c;
  }
  colour_start_.assign(n_colours + 1, 0);
  for (size_t e = 0; e < ne; ++e) ++colour_start_[colour[e] + 1];
  for (int c = 0; c < n_colours; ++c) colour_start_[c + 1] += colour_start_[c];
  colour_elements_.resize(ne);
  std::vector<int> fill(colour_start_.begin(), colour_start_.end() - 1);
  for (size_t e = 0; e < ne; ++e) colour_elements_[fill[colour[e]]++] = static_cast<int>(e);
  viscous_hourglass_ =
      std::any_of(hg_viscous_.begin(), hg_viscous_.end(), [](double c) { return c > 0.0; });
  elem_energy_.assign(ne, {0.0, 0.0});
  v_old_ = v_;
  // Pressure faces of each node (CSR), gathered in face order; contact nodes as flags.
  node_face_start_.assign(nn + 1, 0);
  for (const auto& face : mesh_.pressure_faces) {
    for (int n : face) ++node_face_start_[n + 1];
  }
  for (size_t a = 0; a < nn; ++a) node_face_start_[a + 1] += node_face_start_[a];
  node_faces_.resize(node_face_start_[nn]);
  std::vector<int> next(node_face_start_.begin(), node_face_start_.end() - 1);
  for (size_t k = 0; k < mesh_.pressure_faces.size(); ++k) {
    for (int n : mesh_.pressure_faces[k]) node_faces_[next[n]++] = static_cast<int>(k);
  }
  is_contact_node_.assign(nn, 0);
  for (int a : mesh_.contact_nodes) is_contact_node_[a] = 1;
  kernel_ = DefaultElementKernel();

  mass_report_.stable_step_unscaled_s = stable_unscaled;
  stable_step_ = stable;
  dt_ = options_.time_step_s > 0.0 ? options_.time_step_s : options_.time_step_safety * stable;
  if (!(dt_ > 0.0) || !std::isfinite(dt_)) throw NumericalError("fe: no valid time step");
}

double ExplicitSolver::MaxCordStrain() const {
  double worst = 0.0;
  for (size_t e = 0; e < mesh_.elements.size(); ++e) {
    if (fibre_start_[e] == fibre_start_[e + 1]) continue;
    Eigen::Matrix3d F = Eigen::Matrix3d::Zero();
    for (int a = 0; a < 8; ++a) F.noalias() += x_[mesh_.elements[e][a]] * refs_[e].grad.row(a);
    for (int k = fibre_start_[e]; k < fibre_start_[e + 1]; ++k) {
      worst = std::max(worst, 0.5 * ((F * fibres_sorted_[k].direction).squaredNorm() - 1.0));
    }
  }
  return worst;
}

void ExplicitSolver::SetRoad(const RoadContact& road) {
  road_ = road;
  contact_stiffness_.assign(mesh_.nodes.size(), 0.0);
  stick_stiffness_.assign(mesh_.nodes.size(), 0.0);
  for (size_t a = 0; a < mass_.size(); ++a) {
    contact_stiffness_[a] = road_.penalty_factor * mass_[a] / (dt_ * dt_);
    stick_stiffness_[a] = road_.tangential_penalty_factor * mass_[a] / (dt_ * dt_);
  }
  stick_extension_.assign(mesh_.nodes.size(), Eigen::Vector2d::Zero());
  on_road_.assign(mesh_.nodes.size(), 0);
}

void ExplicitSolver::SetRim(const RimSettings& rim) {
  has_rim_ = true;
  rim_settings_ = rim;
  rim_ = RimState{};
  rim_.centre = rim.centre;
  rim_mass_ = rim.mass_kg;
  rim_inertia_ = rim.inertia_kgm2;
  rim_offsets_.clear();
  for (int a : mesh_.rim_nodes) {
    is_rim_node_[a] = 1;
    const Eigen::Vector3d r = X_[a] - rim.centre;
    rim_offsets_.push_back(r);
    rim_mass_ += mass_[a];
    rim_inertia_ += mass_[a] * (r.x() * r.x() + r.z() * r.z());
  }
}

void ExplicitSolver::Prescribe(int node, int dof, double velocity_mps) {
  fixed_[node][dof] = 1;
  fixed_velocity_[node](dof) = velocity_mps;
}

void ExplicitSolver::SetInitialVelocity(const std::vector<Eigen::Vector3d>& v) {
  double before = 0.0, after = 0.0;
  for (size_t a = 0; a < v_.size(); ++a) {
    if (is_rim_node_[a]) continue;
    before += 0.5 * mass_[a] * v_[a].squaredNorm();
    v_[a] = v[a];
    after += 0.5 * mass_[a] * v_[a].squaredNorm();
  }
  if (steps_ == 0) {
    energies_.initial_kinetic = after;
  } else {
    work_to_midstep_[0] += after - before;
  }
}

void ExplicitSolver::SetRimMotion(double vx_mps, double vz_mps, double spin_rad_per_s) {
  const double before = 0.5 * rim_mass_ * rim_.velocity.squaredNorm() +
                        0.5 * rim_inertia_ * rim_.spin_rad_per_s * rim_.spin_rad_per_s;
  rim_.velocity = Eigen::Vector3d(vx_mps, 0.0, vz_mps);
  rim_.spin_rad_per_s = spin_rad_per_s;
  rim_target_ = Eigen::Vector3d(vx_mps, vz_mps, spin_rad_per_s);
  const double after = 0.5 * rim_mass_ * rim_.velocity.squaredNorm() +
                       0.5 * rim_inertia_ * spin_rad_per_s * spin_rad_per_s;
  for (size_t k = 0; k < mesh_.rim_nodes.size(); ++k) {
    const int a = mesh_.rim_nodes[k];
    v_[a] = rim_.velocity + SpinVelocity(spin_rad_per_s, x_[a] - rim_.centre);
  }
  if (steps_ > 0) work_to_midstep_[0] += after - before;
}

void ExplicitSolver::AddRimTranslationalMass(double mass_kg) {
  rim_mass_ += mass_kg;
  if (steps_ > 0) work_to_midstep_[0] += 0.5 * mass_kg * rim_.velocity.squaredNorm();
}

void ExplicitSolver::SetRimModes(RimDofMode x_mode, RimDofMode z_mode, RimDofMode spin_mode) {
  rim_settings_.x_mode = x_mode;
  rim_settings_.z_mode = z_mode;
  rim_settings_.spin_mode = spin_mode;
}

void ExplicitSolver::SetRimVelocity(double vx_mps, double vz_mps, double spin_rad_per_s) {
  rim_target_ = Eigen::Vector3d(vx_mps, vz_mps, spin_rad_per_s);
}

void ExplicitSolver::set_threads(int threads) {
  if (threads < 0) throw InputError("fe: thread count " + std::to_string(threads) + " < 0");
  threads_ = threads;
}

int DefaultThreadCount() {
#ifdef _OPENMP
  return omp_get_max_threads();
#else
  return 1;
#endif
}

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

ElementKernel DefaultElementKernel() {
  const char* env = std::getenv("HOTLAP_FE_KERNEL");
  const std::string want = env != nullptr ? env : "";
  if (want == "portable") return ElementKernel::kPortable;
  if (want == "avx2") {
    if (!ElementKernelSupported(ElementKernel::kAvx2)) {
      throw InputError("fe: HOTLAP_FE_KERNEL=avx2, but this CPU has no AVX2 and FMA");
    }
    return ElementKernel::kAvx2;
  }
  if (!want.empty() && want != "auto") {
    throw InputError("fe: HOTLAP_FE_KERNEL='" + want + "': use portable, avx2 or auto");
  }
  return ElementKernelSupported(ElementKernel::kAvx2) ? ElementKernel::kAvx2
                                                      : ElementKernel::kPortable;
}

const char* ElementKernelName(ElementKernel kernel) {
  return kernel == ElementKernel::kAvx2 ? "avx2" : "portable";
}

void ExplicitSolver::set_element_kernel(ElementKernel kernel) {
  if (!ElementKernelSupported(kernel)) {
    throw InputError(std::string("fe: this CPU cannot run the ") + ElementKernelName(kernel) +
                     " element kernel");
  }
  kernel_ = kernel;
}

int ExplicitSolver::threads() const {
  if (threads_ > 0) return threads_;
  // The default: all cores, but no more threads than the mesh keeps busy (a thread per
  // kElementsPerThread elements), since each step synchronises the threads twice.
  const int useful = static_cast<int>(mesh_.elements.size() / kElementsPerThread);
  return std::max(1, std::min(DefaultThreadCount(), useful));
}

bool ExplicitSolver::AddElementForces(size_t e, Eigen::Vector3d* f_stored, Eigen::Vector3d* f_bulk,
                                      Eigen::Vector3d* f_hourglass) {
  const double b1 = options_.bulk_viscosity_linear, b2 = options_.bulk_viscosity_quadratic;
  // Written with 3-vectors and 3x3 matrices only: Eigen's 8x3 products with transposes do not
  // inline well, and this loop is the solver's cost.
  using Eigen::Vector3d;
  std::array<Vector3d, 8> u, vel;
  const auto& nodes = mesh_.elements[e];
  const Hex8Reference& ref = refs_[e];
  Eigen::Matrix3d F = Eigen::Matrix3d::Zero(), f_dot = Eigen::Matrix3d::Zero();
  for (int a = 0; a < 8; ++a) {
    const Vector3d& xa = x_[nodes[a]];
    const Eigen::RowVector3d g = ref.grad.row(a);
    F.noalias() += xa * g;
    vel[a] = v_[nodes[a]];
    f_dot.noalias() += vel[a] * g;
    u[a] = xa - X_[nodes[a]];
  }
  const double j = F.determinant();
  if (!(j > 0.0)) return false;
  const YeohMaterial& m = materials_[mesh_.element_material[e]];
  const Eigen::Matrix3d f_inv = F.inverse();
  const Eigen::Matrix3d f_inv_t = f_inv.transpose();
  Eigen::Matrix3d P;
  const double cbrt_j = CubeRoot(j);  // one cube root per element (Yeoh and bulk viscosity)
  double w = CalcYeohPiolaAndEnergy(m, F, j, cbrt_j, f_inv_t, P);
  for (int k = fibre_start_[e]; k < fibre_start_[e + 1]; ++k) {
    const FibreLayer& f = fibres_sorted_[k];
    w += AddFibreStress(rebars_[f.rebar], f, F, P);
  }
  const double v0 = ref.volume_m3;

  // Bulk viscosity (Abaqus/Explicit form): a pressure against the volumetric strain rate,
  // linear b1 rho c_d L_e evol, plus quadratic rho (b2 L_e evol)^2 in compression only.
  const double evol = f_dot.cwiseProduct(f_inv_t).sum();  // tr(F_dot F^-1)
  const double le = ref.length_m * cbrt_j;                // current characteristic length
  const double rho = elem_density_[e];
  double q = b1 * rho * elem_wave_speed_[e] * le * evol;
  if (evol < 0.0) q -= rho * (b2 * le * evol) * (b2 * le * evol);
  const Eigen::Matrix3d pv = (-v0 * j * q) * f_inv_t;
  const Eigen::Matrix3d ps = -v0 * P;

  // Hourglass: generalised displacements Q_alpha = sum_a gamma_alpha,a u_a (and rates, only
  // with viscous hourglass control: it is off by default and in the paper's model, and the
  // rates and their forces are a tenth of the element's arithmetic).
  const double khg = hg_stiffness_[e], chg = hg_viscous_[e];
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
  elem_energy_[e] = {v0 * w, hg_energy};
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
#define HOTLAP_FE_ELEMENT_RANGE_BODY                                   \
  for (long k = k0; k < k1; ++k) {                                     \
    const long e = list != nullptr ? list[k] : k;                      \
    if (!AddElementForces(e, f_stored, f_bulk, f_hourglass)) return e; \
  }                                                                    \
  return -1;

__attribute__((flatten)) long ExplicitSolver::AddElementRangePortable(
    const int* list, long k0, long k1, Eigen::Vector3d* f_stored, Eigen::Vector3d* f_bulk,
    Eigen::Vector3d* f_hourglass) {
  HOTLAP_FE_ELEMENT_RANGE_BODY
}

#if defined(__GNUC__) && defined(__x86_64__)
__attribute__((target("avx2,fma"), flatten)) long ExplicitSolver::AddElementRangeAvx2(
    const int* list, long k0, long k1, Eigen::Vector3d* f_stored, Eigen::Vector3d* f_bulk,
    Eigen::Vector3d* f_hourglass) {
  HOTLAP_FE_ELEMENT_RANGE_BODY
}
#endif
#undef HOTLAP_FE_ELEMENT_RANGE_BODY

long ExplicitSolver::AddElementRange(const int* list, long k0, long k1, Eigen::Vector3d* f_stored,
                                     Eigen::Vector3d* f_bulk, Eigen::Vector3d* f_hourglass) {
#if defined(__GNUC__) && defined(__x86_64__)
  if (kernel_ == ElementKernel::kAvx2) {
    return AddElementRangeAvx2(list, k0, k1, f_stored, f_bulk, f_hourglass);
  }
#endif
  return AddElementRangePortable(list, k0, k1, f_stored, f_bulk, f_hourglass);
}

std::pair<long, long> ExplicitSolver::BufferElements(int t, int buffers) const {
  const long ne = static_cast<long>(mesh_.elements.size());
  return {ne * t / buffers, ne * (t + 1) / buffers};
}

void ExplicitSolver::PrepareThreadBuffers(int buffers) {
  const size_t nn = x_.size();
  thread_forces_.assign(3 * static_cast<size_t>(buffers),
                        std::vector<Eigen::Vector3d>(nn, Vec3Zero()));
  node_thread_mask_.assign(nn, 0);
  for (int t = 0; t < buffers; ++t) {
    const auto [e0, e1] = BufferElements(t, buffers);
    for (long e = e0; e < e1; ++e) {
      for (int n : mesh_.elements[e]) node_thread_mask_[n] |= std::uint64_t{1} << t;
    }
  }
  buffer_count_ = buffers;
}

void ExplicitSolver::AdvanceRim() {
  Eigen::Vector3d force(rim_loads_.force_x_N, 0.0, rim_loads_.force_z_N);
  double torque = rim_loads_.torque_Nm;
  for (int a : mesh_.rim_nodes) {
    const Eigen::Vector3d f = f_stored_[a] + f_dissip_bv_[a] + f_dissip_hg_[a] + f_damp_[a] +
                              f_contact_[a] + f_friction_[a] + f_external_[a];
    const Eigen::Vector3d r = x_[a] - rim_.centre;
    force += f;
    torque += r.z() * f.x() - r.x() * f.z();
  }
  rim_reaction_ = RimLoads{};
  const auto advance = [&](RimDofMode mode, double& vel, double target, double load, double inertia,
                           double& reaction) {
    if (mode == RimDofMode::kFree) {
      vel += dt_ * load / inertia;
    } else {
      // The constraint supplies what the prescribed change of velocity needs.
      reaction = inertia * (target - vel) / dt_ - load;
      vel = target;
    }
  };
  advance(rim_settings_.x_mode, rim_.velocity.x(), rim_target_(0), force.x(), rim_mass_,
          rim_reaction_.force_x_N);
  advance(rim_settings_.z_mode, rim_.velocity.z(), rim_target_(1), force.z(), rim_mass_,
          rim_reaction_.force_z_N);
  advance(rim_settings_.spin_mode, rim_.spin_rad_per_s, rim_target_(2), torque, rim_inertia_,
          rim_reaction_.torque_Nm);
  rim_.centre += dt_ * rim_.velocity;
  rim_.angle_rad += dt_ * rim_.spin_rad_per_s;
  const Eigen::Matrix3d rot = RotationY(rim_.angle_rad);
  for (size_t k = 0; k < mesh_.rim_nodes.size(); ++k) {
    const int a = mesh_.rim_nodes[k];
    const Eigen::Vector3d r = rot * rim_offsets_[k];
    x_[a] = rim_.centre + r;
    v_[a] = rim_.velocity + SpinVelocity(rim_.spin_rad_per_s, r);
  }
}

void ExplicitSolver::RunStep(bool advance) {
  const long nn = static_cast<long>(x_.size()), ne = static_cast<long>(mesh_.elements.size());
  const long nf = static_cast<long>(mesh_.pressure_faces.size());
  const int nt = threads();
  const bool coloured = assembly_ == Assembly::kColoured;
  // Per-thread buffers on one thread: the elements add straight to the nodes, in element order
  // (the same bits as one buffer).
  const bool direct = !coloured && nt == 1;
  const int buffers = coloured || direct ? 0 : std::min(nt, kMaxBuffers);
  if (buffers > 0 && buffers != buffer_count_) PrepareThreadBuffers(buffers);
  const long node_blocks = Blocks(nn), elem_blocks = Blocks(ne);
  node_sums_.resize(node_blocks);
  elem_sums_.resize(elem_blocks);
  face_force_.resize(nf);
  const double p = pressure_Pa_;
  const Eigen::Vector3d road_velocity(road_.road_speed_x_mps, 0.0, 0.0);
  long bad = ne;  // the lowest inverted element, if any

  // One parallel region per step. Its synchronisation points: the end of the element loop
  // (every colour's loop with the coloured assembly) and the end of the node loop; few, because
  // on a loaded machine each one can cost a scheduler time slice.
#pragma omp parallel num_threads(nt)
  {
    // Inflation pressure: a follower load on each face, a quarter of p times the area vector on
    // each of its nodes, pushing into the solid (gathered per node below).
    if (p != 0.0) {
#pragma omp for schedule(static) nowait
      for (long k = 0; k < nf; ++k) {
        const auto& face = mesh_.pressure_faces[k];
        face_force_[k] = -0.125 * p * (x_[face[2]] - x_[face[0]]).cross(x_[face[3]] - x_[face[1]]);
      }
    }
    if (coloured || direct) {
#pragma omp for schedule(static)
      for (long a = 0; a < nn; ++a) {
        f_stored_[a].setZero();
        f_dissip_bv_[a].setZero();
        f_dissip_hg_[a].setZero();
      }
      // Elements of one colour share no node: they add to the nodes without a race. Each thread
      // takes a contiguous share of each colour (as schedule(static)); the barrier after each
      // colour separates the colours.
      const int n_loops = direct ? 1 : colours();
#ifdef _OPENMP
      const int team = omp_get_num_threads(), rank = omp_get_thread_num();
#else
      const int team = 1, rank = 0;
#endif
      for (int c = 0; c < n_loops; ++c) {
        const long k0 = direct ? 0 : colour_start_[c], k1 = direct ? ne : colour_start_[c + 1];
        const long n = k1 - k0;
        // The lowest inverted element of this share (a colour lists its elements ascending).
        const long e = AddElementRange(direct ? nullptr : colour_elements_.data(),
                                       k0 + n * rank / team, k0 + n * (rank + 1) / team,
                                       f_stored_.data(), f_dissip_bv_.data(), f_dissip_hg_.data());
        if (e >= 0) {
#pragma omp critical(hotlap_fe_inverted)
          bad = std::min(bad, e);
        }
#pragma omp barrier
      }
    } else {
#ifdef _OPENMP
      const int team = omp_get_num_threads(), rank = omp_get_thread_num();
#else
      const int team = 1, rank = 0;
#endif
      // The buffers are zero here (the node loop zeroes what it sums). Buffer t takes a fixed
      // range of elements, so node_thread_mask_ holds; a smaller team than asked for takes
      // several buffers per thread.
      for (int t = rank; t < buffers; t += team) {
        Eigen::Vector3d* fs = thread_forces_[3 * t].data();
        Eigen::Vector3d* fb = thread_forces_[3 * t + 1].data();
        Eigen::Vector3d* fh = thread_forces_[3 * t + 2].data();
        const auto [e0, e1] = BufferElements(t, buffers);
        const long e = AddElementRange(nullptr, e0, e1, fs, fb, fh);
        if (e >= 0) {
#pragma omp critical(hotlap_fe_inverted)
          bad = std::min(bad, e);
        }
      }
#pragma omp barrier
    }
    // Past the barrier: every element and face force is known, and so is `bad`.
    if (bad == ne) {
#pragma omp for schedule(static) nowait
      for (long b = 0; b < elem_blocks; ++b) {
        std::array<double, 2> sum{0.0, 0.0};
        for (long e = b * kSumBlock; e < std::min(ne, (b + 1) * kSumBlock); ++e) {
          sum[0] += elem_energy_[e][0];
          sum[1] += elem_energy_[e][1];
        }
        elem_sums_[b] = sum;
      }
#pragma omp for schedule(static)
      for (long b = 0; b < node_blocks; ++b) {
        NodeSums sum{};
        for (long a = b * kSumBlock; a < std::min(nn, (b + 1) * kSumBlock); ++a) {
          NodeUpdate(a, buffers, road_velocity, advance, sum);
        }
        node_sums_[b] = sum;
      }
    }
  }
  if (bad < ne) {
    // The node loop did not run: zero the buffers for a later step.
    for (auto& buffer : thread_forces_) std::fill(buffer.begin(), buffer.end(), Vec3Zero());
    Eigen::Matrix3d F = Eigen::Matrix3d::Zero();
    for (int a = 0; a < 8; ++a) F.noalias() += x_[mesh_.elements[bad][a]] * refs_[bad].grad.row(a);
    throw NumericalError("fe: element " + std::to_string(bad) +
                         " inverted (J = " + std::to_string(F.determinant()) +
                         ") at t = " + std::to_string(time_) + " s");
  }
  // Sums in block order: the same for every thread count.
  stored_internal_ = stored_hg_ = stored_contact_ = 0.0;
  for (const auto& b : elem_sums_) {
    stored_internal_ += b[0];
    stored_hg_ += b[1];
  }
  NodeSums total{};
  for (const NodeSums& b : node_sums_) {
    for (size_t k = 0; k < total.size(); ++k) total[k] += b[k];
  }
  stored_contact_ = total[kContactSum];
  if (!advance) return;

  // The rim: its applied loads and constraint reactions do work at its mean velocity.
  const Eigen::Vector3d rim_v_old = rim_.velocity;
  const double rim_w_old = rim_.spin_rad_per_s;
  if (has_rim_) {
    AdvanceRim();
    // The rim nodes' force terms, now that their new velocities are known.
    for (int a : mesh_.rim_nodes) AddWorkTerms(a, total);
  }

  // Energy accounting. The work of f(n) is f(n) . (x(n+1) - x(n-1)) / 2 (trapezoidal in the
  // forces), of which the second half lies beyond t(n) and is held back from the energies
  // reported at t(n); the kinetic energy at t(n) is m v(n-1/2) . v(n+1/2) / 2. For a linear
  // system this balance is exact under central differences; with the mean velocity squared, or
  // with the look-ahead half counted, it is off by terms of order omega dt, large for the
  // highest modes.
  // Work terms (AddWorkTerms): external (with reactions), bulk viscosity, viscous hourglass,
  // damping, friction; each as the sum of f . v(n-1/2) ("back") and of f . v(n+1/2) ("ahead").
  const bool first = steps_ == 0;
  std::array<double, 5> back{}, ahead{};
  for (int k = 0; k < 5; ++k) {
    back[k] = first ? 0.0 : total[k];
    ahead[k] = total[5 + k];
  }
  double ke = total[kKineticSum];
  if (has_rim_) {
    const Eigen::Vector3d f(rim_loads_.force_x_N + rim_reaction_.force_x_N,
                            rim_loads_.torque_Nm + rim_reaction_.torque_Nm,
                            rim_loads_.force_z_N + rim_reaction_.force_z_N);
    const Eigen::Vector3d vo(rim_v_old.x(), rim_w_old, rim_v_old.z());
    const Eigen::Vector3d vn(rim_.velocity.x(), rim_.spin_rad_per_s, rim_.velocity.z());
    if (!first) back[0] += f.dot(vo);
    ahead[0] += f.dot(vn);
    ke += 0.5 * rim_mass_ * rim_v_old.dot(rim_.velocity) +
          0.5 * rim_inertia_ * rim_w_old * rim_.spin_rad_per_s;
  }
  if (first) energies_.initial_kinetic = ke;
  std::array<double, 5> now{};
  for (int k = 0; k < 5; ++k) {
    work_to_midstep_[k] += 0.5 * dt_ * (back[k] + ahead[k]);
    now[k] = work_to_midstep_[k] - 0.5 * dt_ * ahead[k];
  }
  energies_.external_work = now[0];
  energies_.bulk_viscous = -now[1];
  energies_.hourglass_dissipated = -now[2];
  energies_.damping = -now[3];
  slip_dissipation_ += total[kSlipSum];
  energies_.friction = road_.stick == StickModel::kViscous ? -now[4] : slip_dissipation_;
  energies_.kinetic = ke;
  energies_.internal = stored_internal_;
  energies_.hourglass_stored = stored_hg_;
  energies_.contact_stored = stored_contact_;
  if (!std::isfinite(ke) || !std::isfinite(stored_internal_)) {
    throw NumericalError("fe: non-finite energy at t = " + std::to_string(time_) + " s");
  }
  time_ += dt_;
  ++steps_;
}

void ExplicitSolver::AddWorkTerms(long a, NodeSums& sum) const {
  const Eigen::Vector3d fe = f_external_[a] + reaction_[a];
  const Eigen::Vector3d* f[5] = {&fe, &f_dissip_bv_[a], &f_dissip_hg_[a], &f_damp_[a],
                                 &f_friction_[a]};
  for (int k = 0; k < 5; ++k) {
    sum[k] += f[k]->dot(v_old_[a]);
    sum[5 + k] += f[k]->dot(v_[a]);
  }
  // A moving road works on the friction force: external work; the friction term is the work
  // relative to the road.
  const double road_power = f_friction_[a].x() * road_.road_speed_x_mps;
  sum[0] += road_power;
  sum[5] += road_power;
  sum[4] -= road_power;
  sum[9] -= road_power;
}

void ExplicitSolver::NodeUpdate(long a, int buffers, const Eigen::Vector3d& road_velocity,
                                bool advance, NodeSums& sum) {
  if (buffers > 0) {
    // Sum the buffers in thread order, reading (and zeroing for the next step) only those whose
    // elements touch this node: the others hold zeros, and at the paper's mesh size the memory
    // traffic of reading and clearing them all is a large part of the step.
    Eigen::Vector3d fs = Vec3Zero(), fb = Vec3Zero(), fh = Vec3Zero();
    for (std::uint64_t mask = node_thread_mask_[a]; mask != 0; mask &= mask - 1) {
      const int t = std::countr_zero(mask);
      Eigen::Vector3d& bs = thread_forces_[3 * t][a];
      Eigen::Vector3d& bb = thread_forces_[3 * t + 1][a];
      fs += bs;
      fb += bb;
      bs.setZero();
      bb.setZero();
      if (viscous_hourglass_) {  // else no element adds to the hourglass buffers
        Eigen::Vector3d& bh = thread_forces_[3 * t + 2][a];
        fh += bh;
        bh.setZero();
      }
    }
    f_stored_[a] = fs;
    f_dissip_bv_[a] = fb;
    f_dissip_hg_[a] = fh;
  }
  Eigen::Vector3d fe = applied_[a];
  if (pressure_Pa_ != 0.0) {
    for (int k = node_face_start_[a]; k < node_face_start_[a + 1]; ++k) {
      fe += face_force_[node_faces_[k]];
    }
  }
  f_external_[a] = fe;
  f_damp_[a] = -options_.mass_damping_per_s * mass_[a] * v_[a];
  f_contact_[a].setZero();
  f_friction_[a].setZero();
  contact_normal_[a] = 0.0;
  // Road: penalty normal force and friction (002:1); road_contact.h.
  if (road_.enabled && is_contact_node_[a]) {
    const double g = road_.height_m - x_[a].z();
    const bool on_road = g > 0.0;
    double fn = 0.0;
    if (on_road) {
      fn = contact_stiffness_[a] * g;
      contact_normal_[a] = fn;
      f_contact_[a].z() = fn;
      sum[kContactSum] += 0.5 * contact_stiffness_[a] * g * g;
    }
    const Eigen::Vector3d slip = v_[a] - road_velocity;  // v(n-1/2) relative to the road
    if (road_.stick == StickModel::kViscous) {
      if (on_road) f_friction_[a] = CalcFrictionForce(road_.friction, fn, slip, mass_[a] / dt_);
    } else if (on_road || on_road_[a]) {
      // The stick spring's trial extension x_t(n) - anchor(n-1): the last extension plus the
      // node's move relative to the road over the last step, dt v_slip(n-1/2) (the anchor moves
      // with the road). A node touching down anchors where it crossed the road plane during the
      // last step (linearly; where it is if it was below the plane already, e.g. a road just
      // set); one leaving the road lets go (limit 0).
      const Eigen::Vector2d slip_t(slip.x(), slip.y());
      const bool was_on_road = on_road_[a] != 0;
      const Eigen::Vector2d last = was_on_road ? stick_extension_[a] : Eigen::Vector2d::Zero();
      const Eigen::Vector2d moved = last + dt_ * slip_t;  // with the anchor carried along
      Eigen::Vector2d trial = moved;
      if (!was_on_road) {
        const double g_last = g + dt_ * v_[a].z();  // the penetration a step ago
        trial *= g_last < 0.0 && steps_ > 0 ? g / (g - g_last) : 0.0;
      }
      const double k = stick_stiffness_[a];
      const double limit =
          on_road ? CalcFrictionCoefficient(road_.friction, slip_t.norm()) * fn : 0.0;
      Eigen::Vector2d ext = trial;
      const Eigen::Vector2d f = ReturnMapFriction(k, limit, ext);
      f_friction_[a] = Eigen::Vector3d(f.x(), f.y(), 0.0);
      sum[kContactSum] += 0.5 * k * ext.squaredNorm();
      if (advance) {
        // Dissipated over [t(n-1), t(n)]: (f(n-1) + f(n)) / 2 against the anchor's move relative
        // to the road, moved - ext (zero in stick; before touch-down the anchor is taken as
        // carried with the node, f(n-1) being zero); with the spring energy this closes the
        // node's friction work exactly (explicit_solver.h, Energies).
        sum[kSlipSum] += 0.5 * k * (last + ext).dot(moved - ext);
        stick_extension_[a] = ext;
        on_road_[a] = on_road;
      }
    }
  }
  if (!advance) return;
  v_old_[a] = v_[a];
  reaction_[a].setZero();
  if (is_rim_node_[a]) return;  // moved with the rim, after the node loop
  const Eigen::Vector3d f = f_stored_[a] + f_dissip_bv_[a] + f_dissip_hg_[a] + f_damp_[a] +
                            f_contact_[a] + f_friction_[a] + f_external_[a];
  for (int d = 0; d < 3; ++d) {
    if (fixed_[a][d]) {
      v_[a](d) = fixed_velocity_[a](d);
      reaction_[a](d) = mass_[a] * (v_[a](d) - v_old_[a](d)) / dt_ - f(d);
    } else {
      v_[a](d) += dt_ * f(d) / mass_[a];
    }
  }
  x_[a] += dt_ * v_[a];
  AddWorkTerms(a, sum);
  sum[kKineticSum] += 0.5 * mass_[a] * v_old_[a].dot(v_[a]);
}

void ExplicitSolver::Step() { RunStep(/*advance=*/true); }

std::vector<Eigen::Vector3d> ExplicitSolver::CalcElementForces() {
  RunStep(/*advance=*/false);
  std::vector<Eigen::Vector3d> f(x_.size());
  for (size_t a = 0; a < f.size(); ++a) f[a] = f_stored_[a] + f_dissip_bv_[a] + f_dissip_hg_[a];
  return f;
}

Eigen::Vector3d ExplicitSolver::RoadForce() const {
  Eigen::Vector3d f = Eigen::Vector3d::Zero();
  for (int a : mesh_.contact_nodes) f += f_contact_[a] + f_friction_[a];
  return f;
}

Eigen::Matrix3d ExplicitSolver::ElementStress(int e) const {
  Mat83 xe;
  for (int a = 0; a < 8; ++a) xe.row(a) = x_[mesh_.elements[e][a]].transpose();
  const Eigen::Matrix3d F = xe.transpose() * refs_[e].grad;
  Eigen::Matrix3d P = CalcYeohFirstPiola(materials_[mesh_.element_material[e]], F);
  for (int k = fibre_start_[e]; k < fibre_start_[e + 1]; ++k) {
    const FibreLayer& f = fibres_sorted_[k];
    AddFibreStress(rebars_[f.rebar], f, F, P);
  }
  return P * F.transpose() / F.determinant();
}

void ExplicitSolver::SaveState(BinaryWriter& out) const {
  out.PutTag("SOLV");
  out.PutDouble(dt_);
  out.PutDouble(time_);
  out.PutI64(steps_);
  out.PutDouble(pressure_Pa_);
  out.PutDouble(options_.mass_damping_per_s);
  for (const auto* v :
       {&x_, &v_, &applied_, &reaction_, &fixed_velocity_, &f_stored_, &f_dissip_bv_, &f_dissip_hg_,
        &f_damp_, &f_contact_, &f_friction_, &f_external_}) {
    out.PutVectors(*v);
  }
  out.PutU64(fixed_.size());
  for (const auto& f : fixed_) out.PutU64(f[0] | f[1] << 1 | f[2] << 2);
  out.PutDoubles(contact_normal_);
  out.PutTag("ROAD");
  out.PutU64(road_.enabled ? 1 : 0);
  for (double d : {road_.height_m, road_.penalty_factor, road_.road_speed_x_mps,
                   road_.friction.static_coefficient, road_.friction.kinetic_coefficient,
                   road_.friction.decay_s_per_m, road_.tangential_penalty_factor}) {
    out.PutDouble(d);
  }
  out.PutU64(static_cast<std::uint64_t>(road_.stick));
  // The stick springs of the contact nodes (in mesh.contact_nodes order): on the road, extension.
  out.PutTag("STIK");
  out.PutU64(mesh_.contact_nodes.size());
  for (int a : mesh_.contact_nodes) {
    out.PutU64(on_road_[a] ? 1 : 0);
    out.PutDouble(stick_extension_[a].x());
    out.PutDouble(stick_extension_[a].y());
  }
  out.PutTag("RIM_");
  out.PutU64(has_rim_ ? 1 : 0);
  out.PutU64(static_cast<std::uint64_t>(rim_settings_.x_mode) |
             static_cast<std::uint64_t>(rim_settings_.z_mode) << 8 |
             static_cast<std::uint64_t>(rim_settings_.spin_mode) << 16);
  out.PutVector(rim_.centre);
  out.PutVector(rim_.velocity);
  out.PutDouble(rim_.angle_rad);
  out.PutDouble(rim_.spin_rad_per_s);
  for (const RimLoads* l : {&rim_loads_, &rim_reaction_}) {
    out.PutDouble(l->force_x_N);
    out.PutDouble(l->force_z_N);
    out.PutDouble(l->torque_Nm);
  }
  out.PutVector(rim_target_);
  out.PutDouble(rim_mass_);
  out.PutDouble(rim_inertia_);
  out.PutTag("ENRG");
  const Energies& e = energies_;
  for (double d : {e.kinetic, e.internal, e.hourglass_stored, e.hourglass_dissipated,
                   e.bulk_viscous, e.damping, e.contact_stored, e.friction, e.external_work,
                   e.initial_kinetic, stored_internal_, stored_hg_, stored_contact_}) {
    out.PutDouble(d);
  }
  for (double d : work_to_midstep_) out.PutDouble(d);
  out.PutDouble(slip_dissipation_);
}

void ExplicitSolver::LoadState(BinaryReader& in) {
  in.ExpectTag("SOLV");
  const double dt = in.GetDouble();
  if (dt != dt_) {
    in.Damaged("its time step " + std::to_string(dt) + " s is not this model's " +
               std::to_string(dt_) + " s");
  }
  const size_t nn = x_.size();
  const double time = in.GetFinite();
  const std::int64_t steps = in.GetI64();
  if (steps < 0) in.Damaged("a negative step count");
  const double pressure = in.GetFinite();
  const double damping = in.GetFinite();
  std::vector<Eigen::Vector3d>* arrays[] = {
      &x_,           &v_,           &applied_, &reaction_,  &fixed_velocity_, &f_stored_,
      &f_dissip_bv_, &f_dissip_hg_, &f_damp_,  &f_contact_, &f_friction_,     &f_external_};
  std::vector<std::vector<Eigen::Vector3d>> read;
  for (size_t k = 0; k < std::size(arrays); ++k) read.push_back(in.GetVectors(nn));
  for (const Eigen::Vector3d& p : read[0]) {
    if (!p.allFinite()) in.Damaged("a non-finite node position");
  }
  if (in.GetCount(8) != nn) in.Damaged("the fixed-dof table does not match the mesh");
  std::vector<std::array<char, 3>> fixed(nn);
  for (auto& f : fixed) {
    const std::uint64_t bits = in.GetU64();
    if (bits > 7) in.Damaged("a fixed-dof entry out of range");
    f = {char(bits & 1), char(bits >> 1 & 1), char(bits >> 2 & 1)};
  }
  std::vector<double> normal = in.GetDoubles(nn);
  in.ExpectTag("ROAD");
  RoadContact road;
  road.enabled = in.GetU64() != 0;
  road.height_m = in.GetFinite();
  road.penalty_factor = in.GetFinite();
  road.road_speed_x_mps = in.GetFinite();
  road.friction.static_coefficient = in.GetFinite();
  road.friction.kinetic_coefficient = in.GetFinite();
  road.friction.decay_s_per_m = in.GetFinite();
  road.tangential_penalty_factor = in.GetFinite();
  const std::uint64_t stick = in.GetU64();
  if (stick > static_cast<std::uint64_t>(StickModel::kViscous)) {
    in.Damaged("a stick model out of range");
  }
  road.stick = static_cast<StickModel>(stick);
  in.ExpectTag("STIK");
  const size_t nc = mesh_.contact_nodes.size();
  if (in.GetCount(24) != nc) in.Damaged("the stick anchors do not match the mesh's contact nodes");
  std::vector<char> on_road(nc);
  std::vector<Eigen::Vector2d> extension(nc);
  for (size_t k = 0; k < nc; ++k) {
    const std::uint64_t flag = in.GetU64();
    if (flag > 1) in.Damaged("a stick anchor flag out of range");
    on_road[k] = static_cast<char>(flag);
    extension[k].x() = in.GetFinite();
    extension[k].y() = in.GetFinite();
  }
  in.ExpectTag("RIM_");
  const bool has_rim = in.GetU64() != 0;
  if (has_rim != has_rim_) in.Damaged("its rim does not match this model's");
  const std::uint64_t modes = in.GetU64();
  const auto mode = [&](int shift) {
    const std::uint64_t m = modes >> shift & 0xff;
    if (m > static_cast<std::uint64_t>(RimDofMode::kPrescribedVelocity) || modes >> 24 != 0) {
      in.Damaged("a rim mode out of range");
    }
    return static_cast<RimDofMode>(m);
  };
  RimSettings settings = rim_settings_;
  settings.x_mode = mode(0);
  settings.z_mode = mode(8);
  settings.spin_mode = mode(16);
  RimState rim;
  rim.centre = in.GetVector();
  rim.velocity = in.GetVector();
  rim.angle_rad = in.GetFinite();
  rim.spin_rad_per_s = in.GetFinite();
  RimLoads loads[2];
  for (RimLoads& l : loads) {
    l.force_x_N = in.GetDouble();
    l.force_z_N = in.GetDouble();
    l.torque_Nm = in.GetDouble();
  }
  const Eigen::Vector3d target = in.GetVector();
  const double rim_mass = in.GetFinite(), rim_inertia = in.GetFinite();
  in.ExpectTag("ENRG");
  Energies e;
  double stored[3];
  for (double* d : {&e.kinetic, &e.internal, &e.hourglass_stored, &e.hourglass_dissipated,
                    &e.bulk_viscous, &e.damping, &e.contact_stored, &e.friction, &e.external_work,
                    &e.initial_kinetic, &stored[0], &stored[1], &stored[2]}) {
    *d = in.GetFinite();
  }
  std::array<double, 5> work{};
  for (double& d : work) d = in.GetFinite();
  const double slip_dissipation = in.GetFinite();

  // Everything read and checked: only now change the solver.
  time_ = time;
  steps_ = steps;
  pressure_Pa_ = pressure;
  options_.mass_damping_per_s = damping;
  for (size_t k = 0; k < std::size(arrays); ++k) *arrays[k] = std::move(read[k]);
  fixed_ = std::move(fixed);
  contact_normal_ = std::move(normal);
  if (road.enabled) {
    SetRoad(road);
  } else {
    road_ = road;
  }
  for (size_t k = 0; k < nc; ++k) {  // after SetRoad, which drops the anchors
    on_road_[mesh_.contact_nodes[k]] = on_road[k];
    stick_extension_[mesh_.contact_nodes[k]] = extension[k];
  }
  rim_settings_ = settings;
  rim_ = rim;
  rim_loads_ = loads[0];
  rim_reaction_ = loads[1];
  rim_target_ = target;
  rim_mass_ = rim_mass;
  rim_inertia_ = rim_inertia;
  energies_ = e;
  stored_internal_ = stored[0];
  stored_hg_ = stored[1];
  stored_contact_ = stored[2];
  work_to_midstep_ = work;
  slip_dissipation_ = slip_dissipation;
}

}  // namespace hotlap::fe
