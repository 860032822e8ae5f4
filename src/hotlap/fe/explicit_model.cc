#include "hotlap/fe/explicit_model.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <fmt/format.h>

#include "hotlap/common/error.h"

namespace hotlap::fe {

namespace {

using Mat83 = Eigen::Matrix<double, 8, 3>;

// Central differences with the damping force lagged half a step are stable for a mode of
// frequency omega and damping rate mu = 2 xi omega while (omega dt)^2 / 4 + mu dt / 2 <= 1, i.e.
// dt <= (2 / omega^2)(sqrt(omega^2 + mu^2 / 4) - mu / 2) = (2 / omega)(sqrt(1 + xi^2) - xi).
// Decreasing in both, so the largest frequency and the largest damping rate give a safe step.
double DampedStableStep(double omega2, double mu) {
  return 2.0 / omega2 * (std::sqrt(omega2 + 0.25 * mu * mu) - 0.5 * mu);
}

// Cords sorted by host element (CSR).
void SortFibres(ExplicitModel& m) {
  const size_t ne = m.mesh.elements.size();
  m.fibres_sorted = m.mesh.fibres;
  std::stable_sort(m.fibres_sorted.begin(), m.fibres_sorted.end(),
                   [](const FibreLayer& a, const FibreLayer& b) { return a.element < b.element; });
  m.fibre_start.assign(ne + 1, 0);
  for (const FibreLayer& f : m.fibres_sorted) ++m.fibre_start[f.element + 1];
  for (size_t e = 0; e < ne; ++e) m.fibre_start[e + 1] += m.fibre_start[e];
}

// Each element's reference gradients, stable step (with mass scaling), density, wave speed and
// hourglass coefficients, and the lumped masses; the stable step of the mesh.
void CalcElementTables(ExplicitModel& m) {
  const size_t nn = m.mesh.nodes.size(), ne = m.mesh.elements.size();
  const SolverOptions& options = m.options;
  const std::vector<Eigen::Vector3d>& X = m.mesh.nodes;
  m.mass.assign(nn, 0.0);
  m.refs.resize(ne);
  m.elem_density.resize(ne);
  m.elem_wave_speed.resize(ne);
  m.hg_stiffness.resize(ne);
  m.hg_viscous.resize(ne);
  const double b1 = options.bulk_viscosity_linear;
  double stable = std::numeric_limits<double>::infinity();
  double stable_unscaled = stable;
  for (size_t e = 0; e < ne; ++e) {
    Mat83 xe;
    for (int a = 0; a < 8; ++a) xe.row(a) = X[m.mesh.elements[e][a]].transpose();
    m.refs[e] = CalcHex8Reference(xe);
    const Hex8Reference& ref = m.refs[e];
    const YeohMaterial& mat = m.materials.at(m.mesh.element_material[e]);
    const double mu0 = InitialShearModulus(mat);
    const double rubber_modulus = mat.bulk_modulus_Pa + 4.0 / 3.0 * mu0;
    const double grad2 = ref.grad.squaredNorm();
    const double v0 = ref.volume_m3;
    // Highest frequency with lumped mass (rho V0 / 8 per node), bounded term by term (the
    // largest eigenvalue of a sum is at most the sum of the largest): rubber omega^2 <=
    // 8 (K + 4/3 mu0) / rho sum_a |B0_a|^2 (Flanagan & Belytschko 1981); each cord's tangent
    // V0 phi E (g g^T) (x) (F a0 (F a0)^T + E_f I), g_a = B0_a . a0, has the largest eigenvalue
    // V0 phi E |g|^2 (lambda^2 + E_f) = V0 phi E |g|^2 (1 + 3 E_f); the hourglass stiffness
    // k Gamma^T Gamma (x) I, Gamma the 4 x 8 matrix of the vectors gamma_alpha, has k
    // lambda_max(Gamma Gamma^T).
    double rho = mat.density_kg_per_m3;
    double cord_stiffness = 0.0;  // sum phi E (1 + 3 E_max) |g|^2
    for (int k = m.fibre_start[e]; k < m.fibre_start[e + 1]; ++k) {
      const FibreLayer& f = m.fibres_sorted[k];
      const RebarMaterial& r = m.rebars.at(f.rebar);
      rho += f.volume_fraction * r.density_kg_per_m3;
      const double g2 = (ref.grad * f.direction).squaredNorm();
      cord_stiffness +=
          f.volume_fraction * r.youngs_modulus_Pa * (1.0 + 3.0 * kCordStrainAllowance) * g2;
    }
    m.mass_report.physical_mass_kg += rho * v0;
    const Eigen::Matrix4d gg = ref.hourglass * ref.hourglass.transpose();
    const double hg_eig = Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d>(gg, Eigen::EigenvaluesOnly)
                              .eigenvalues()
                              .maxCoeff();
    const double khg = options.hourglass_stiffness * mu0 * v0 * grad2 / 8.0;
    // Bulk viscosity and viscous hourglass act on the rubber's volumetric and hourglass modes:
    // they use the rubber's dilatational wave speed (with the cords' mass).
    const auto wave_speed = [&](double density) { return std::sqrt(rubber_modulus / density); };
    const auto viscous_hg = [&](double density) {
      return options.hourglass_viscous * density * wave_speed(density) * std::pow(v0, 2.0 / 3.0) /
             4.0;
    };
    const double omega2 = 8.0 * (rubber_modulus * grad2 + cord_stiffness + khg * hg_eig / v0) / rho;
    // Damping rates (largest eigenvalue over the lumped mass): the linear bulk viscosity is the
    // rank-one b1 rho c L_e V0 B0 B0^T at the reference state, rate 8 b1 c L_e sum_a |B0_a|^2;
    // the viscous hourglass c_hg Gamma^T Gamma (x) I, rate 8 c_hg lambda_max / (rho V0).
    const double mu = 8.0 * b1 * wave_speed(rho) * ref.length_m * grad2 +
                      8.0 * viscous_hg(rho) * hg_eig / (rho * v0);
    // Scaling rho by s scales omega and mu by 1/sqrt(s), so the step by sqrt(s).
    double dt_e = DampedStableStep(omega2, mu);
    stable_unscaled = std::min(stable_unscaled, dt_e);
    if (options.mass_scaling_min_step_s > 0.0 && dt_e < options.mass_scaling_min_step_s) {
      const double scale = std::pow(options.mass_scaling_min_step_s / dt_e, 2);
      m.mass_report.added_mass_kg += (scale - 1.0) * rho * v0;
      ++m.mass_report.scaled_elements;
      rho *= scale;
      dt_e = options.mass_scaling_min_step_s;
    }
    stable = std::min(stable, dt_e);
    m.elem_density[e] = rho;
    m.elem_wave_speed[e] = wave_speed(rho);
    m.hg_stiffness[e] = khg;
    m.hg_viscous[e] = viscous_hg(rho);
    for (int a = 0; a < 8; ++a) m.mass[m.mesh.elements[e][a]] += rho * v0 / 8.0;
  }
  m.viscous_hourglass =
      std::any_of(m.hg_viscous.begin(), m.hg_viscous.end(), [](double c) { return c > 0.0; });
  m.mass_report.stable_step_unscaled_s = stable_unscaled;
  m.stable_step_s = stable;
}

// Element colours, greedy: each element takes the lowest colour that no element sharing one of
// its nodes has yet (a structured hexahedral mesh needs 8).
void ColourElements(ExplicitModel& m) {
  const size_t nn = m.mesh.nodes.size(), ne = m.mesh.elements.size();
  std::vector<std::uint64_t> node_colours(nn, 0);
  std::vector<int> colour(ne);
  int n_colours = 0;
  for (size_t e = 0; e < ne; ++e) {
    std::uint64_t used = 0;
    for (int n : m.mesh.elements[e]) used |= node_colours[n];
    if (~used == 0) throw NumericalError("fe: more than 64 element colours needed");
    int c = 0;
    while (used & (std::uint64_t{1} << c)) ++c;
    colour[e] = c;
    n_colours = std::max(n_colours, c + 1);
    for (int n : m.mesh.elements[e]) node_colours[n] |= std::uint64_t{1} << c;
  }
  m.colour_start.assign(n_colours + 1, 0);
  for (size_t e = 0; e < ne; ++e) ++m.colour_start[colour[e] + 1];
  for (int c = 0; c < n_colours; ++c) m.colour_start[c + 1] += m.colour_start[c];
  m.colour_elements.resize(ne);
  std::vector<int> fill(m.colour_start.begin(), m.colour_start.end() - 1);
  for (size_t e = 0; e < ne; ++e) m.colour_elements[fill[colour[e]]++] = static_cast<int>(e);
}

// Pressure faces of each node (CSR), gathered in face order; contact and rim nodes as flags.
void IndexNodes(ExplicitModel& m) {
  const size_t nn = m.mesh.nodes.size();
  m.node_face_start.assign(nn + 1, 0);
  for (const auto& face : m.mesh.pressure_faces) {
    for (int n : face) ++m.node_face_start[n + 1];
  }
  for (size_t a = 0; a < nn; ++a) m.node_face_start[a + 1] += m.node_face_start[a];
  m.node_faces.resize(m.node_face_start[nn]);
  std::vector<int> next(m.node_face_start.begin(), m.node_face_start.end() - 1);
  for (size_t k = 0; k < m.mesh.pressure_faces.size(); ++k) {
    for (int n : m.mesh.pressure_faces[k]) m.node_faces[next[n]++] = static_cast<int>(k);
  }
  m.is_contact_node.assign(nn, 0);
  for (int a : m.mesh.contact_nodes) m.is_contact_node[a] = 1;
  m.is_rim_node.assign(nn, 0);
  for (int a : m.mesh.rim_nodes) m.is_rim_node[a] = 1;
}

Eigen::Matrix3d DeformationGradient(const ExplicitModel& m, const std::vector<Eigen::Vector3d>& x,
                                    size_t e) {
  Eigen::Matrix3d F = Eigen::Matrix3d::Zero();
  for (int a = 0; a < 8; ++a) F.noalias() += x[m.mesh.elements[e][a]] * m.refs[e].grad.row(a);
  return F;
}

}  // namespace

ExplicitModel MakeExplicitModel(Mesh mesh, std::vector<YeohMaterial> materials,
                                std::vector<RebarMaterial> rebars, const SolverOptions& options) {
  ExplicitModel m;
  m.mesh = std::move(mesh);
  m.materials = std::move(materials);
  m.rebars = std::move(rebars);
  m.options = options;
  SortFibres(m);
  CalcElementTables(m);
  ColourElements(m);
  IndexNodes(m);
  if (!(options.time_step_scale > 0.0 && options.time_step_scale <= 1.0)) {
    throw InputError(
        fmt::format("fe: time step scale {:g} is outside (0, 1]", options.time_step_scale));
  }
  m.contact_step_s =
      options.time_step_s > 0.0 ? options.time_step_s : options.time_step_safety * m.stable_step_s;
  m.time_step_s = options.time_step_scale * m.contact_step_s;
  if (!(m.time_step_s > 0.0) || !std::isfinite(m.time_step_s)) {
    throw NumericalError("fe: no valid time step");
  }
  return m;
}

double CalcMaxCordStrain(const ExplicitModel& model, const std::vector<Eigen::Vector3d>& x) {
  double worst = 0.0;
  for (size_t e = 0; e < model.mesh.elements.size(); ++e) {
    if (model.fibre_start[e] == model.fibre_start[e + 1]) continue;
    const Eigen::Matrix3d F = DeformationGradient(model, x, e);
    for (int k = model.fibre_start[e]; k < model.fibre_start[e + 1]; ++k) {
      worst = std::max(worst, 0.5 * ((F * model.fibres_sorted[k].direction).squaredNorm() - 1.0));
    }
  }
  return worst;
}

Eigen::Matrix3d CalcElementStress(const ExplicitModel& model, const std::vector<Eigen::Vector3d>& x,
                                  int e) {
  Mat83 xe;
  for (int a = 0; a < 8; ++a) xe.row(a) = x[model.mesh.elements[e][a]].transpose();
  const Eigen::Matrix3d F = xe.transpose() * model.refs[e].grad;
  Eigen::Matrix3d P = CalcYeohFirstPiola(model.materials[model.mesh.element_material[e]], F);
  for (int k = model.fibre_start[e]; k < model.fibre_start[e + 1]; ++k) {
    const FibreLayer& f = model.fibres_sorted[k];
    AddFibreStress(model.rebars[f.rebar], f, F, P);
  }
  return P * F.transpose() / F.determinant();
}

}  // namespace hotlap::fe
