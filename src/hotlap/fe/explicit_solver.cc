#include "hotlap/fe/explicit_solver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include "hotlap/common/error.h"

namespace hotlap::fe {

namespace {

using Mat83 = Eigen::Matrix<double, 8, 3>;

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
  const double damping_factor = std::sqrt(1.0 + b1 * b1) - b1;
  double stable = std::numeric_limits<double>::infinity();
  double stable_unscaled = stable;
  for (size_t e = 0; e < ne; ++e) {
    Mat83 xe;
    for (int a = 0; a < 8; ++a) xe.row(a) = X_[mesh_.elements[e][a]].transpose();
    refs_[e] = CalcHex8Reference(xe);
    const YeohMaterial& m = materials_.at(mesh_.element_material[e]);
    double rho = m.density_kg_per_m3;
    double modulus = m.bulk_modulus_Pa + 4.0 / 3.0 * InitialShearModulus(m);
    for (int k = fibre_start_[e]; k < fibre_start_[e + 1]; ++k) {
      const FibreLayer& f = fibres_sorted_[k];
      rho += f.volume_fraction * rebars_.at(f.rebar).density_kg_per_m3;
      modulus += f.volume_fraction * rebars_.at(f.rebar).youngs_modulus_Pa;
    }
    mass_report_.physical_mass_kg += rho * refs_[e].volume_m3;
    const double grad2 = refs_[e].grad.squaredNorm();
    // omega_e^2 <= 8 c_d^2 sum_a |B0_a|^2 (Flanagan & Belytschko 1981); dt_e = 2 / omega_e.
    double dt_e = damping_factor / (std::sqrt(modulus / rho) * std::sqrt(2.0 * grad2));
    stable_unscaled = std::min(stable_unscaled, dt_e);
    if (options_.mass_scaling_min_step_s > 0.0 && dt_e < options_.mass_scaling_min_step_s) {
      const double scale = std::pow(options_.mass_scaling_min_step_s / dt_e, 2);
      mass_report_.added_mass_kg += (scale - 1.0) * rho * refs_[e].volume_m3;
      ++mass_report_.scaled_elements;
      rho *= scale;
      dt_e = options_.mass_scaling_min_step_s;
    }
    stable = std::min(stable, dt_e);
    elem_density_[e] = rho;
    elem_wave_speed_[e] = std::sqrt(modulus / rho);
    const double v0 = refs_[e].volume_m3;
    hg_stiffness_[e] = options_.hourglass_stiffness * InitialShearModulus(m) * v0 * grad2 / 8.0;
    hg_viscous_[e] =
        options_.hourglass_viscous * rho * elem_wave_speed_[e] * std::pow(v0, 2.0 / 3.0) / 4.0;
    for (int a = 0; a < 8; ++a) mass_[mesh_.elements[e][a]] += rho * v0 / 8.0;
  }
  mass_report_.stable_step_unscaled_s = stable_unscaled;
  stable_step_ = stable;
  dt_ = options_.time_step_s > 0.0 ? options_.time_step_s : options_.time_step_safety * stable;
  if (!(dt_ > 0.0) || !std::isfinite(dt_)) throw NumericalError("fe: no valid time step");
}

void ExplicitSolver::SetRoad(const RoadContact& road) {
  road_ = road;
  contact_stiffness_.assign(mesh_.nodes.size(), 0.0);
  for (size_t a = 0; a < mass_.size(); ++a) {
    contact_stiffness_[a] = road_.penalty_factor * mass_[a] / (dt_ * dt_);
  }
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

void ExplicitSolver::ComputeForces() {
  const size_t nn = x_.size(), ne = mesh_.elements.size();
  for (size_t a = 0; a < nn; ++a) {
    f_stored_[a].setZero();
    f_dissip_bv_[a].setZero();
    f_dissip_hg_[a].setZero();
    f_contact_[a].setZero();
    f_friction_[a].setZero();
    f_external_[a] = applied_[a];
    f_damp_[a] = -options_.mass_damping_per_s * mass_[a] * v_[a];
    contact_normal_[a] = 0.0;
  }
  stored_internal_ = stored_hg_ = stored_contact_ = 0.0;
  const double b1 = options_.bulk_viscosity_linear, b2 = options_.bulk_viscosity_quadratic;

  // Written with 3-vectors and 3x3 matrices only: Eigen's 8x3 products with transposes do not
  // inline well, and this loop is the solver's cost.
  using Eigen::Vector3d;
  std::array<Vector3d, 8> u, vel;
  for (size_t e = 0; e < ne; ++e) {
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
    if (!(j > 0.0)) {
      throw NumericalError("fe: element " + std::to_string(e) + " inverted (J = " +
                           std::to_string(j) + ") at t = " + std::to_string(time_) + " s");
    }
    const YeohMaterial& m = materials_[mesh_.element_material[e]];
    const Eigen::Matrix3d f_inv = F.inverse();
    const Eigen::Matrix3d f_inv_t = f_inv.transpose();
    Eigen::Matrix3d P;
    double w = CalcYeohPiolaAndEnergy(m, F, j, f_inv_t, P);
    for (int k = fibre_start_[e]; k < fibre_start_[e + 1]; ++k) {
      const FibreLayer& f = fibres_sorted_[k];
      w += AddFibreStress(rebars_[f.rebar], f, F, P);
    }
    const double v0 = ref.volume_m3;
    stored_internal_ += v0 * w;

    // Bulk viscosity (Abaqus/Explicit form): a pressure against the volumetric strain rate,
    // linear b1 rho c_d L_e evol, plus quadratic rho (b2 L_e evol)^2 in compression only.
    const double evol = f_dot.cwiseProduct(f_inv_t).sum();  // tr(F_dot F^-1)
    const double le = ref.length_m * std::cbrt(j);          // current characteristic length
    const double rho = elem_density_[e];
    double q = b1 * rho * elem_wave_speed_[e] * le * evol;
    if (evol < 0.0) q -= rho * (b2 * le * evol) * (b2 * le * evol);
    const Eigen::Matrix3d pv = (-v0 * j * q) * f_inv_t;
    const Eigen::Matrix3d ps = -v0 * P;

    // Hourglass: generalised displacements Q_alpha = sum_a gamma_alpha,a u_a (and rates).
    std::array<Vector3d, 4> qhg, qdot;
    const auto& gam = ref.hourglass;
    for (int al = 0; al < 4; ++al) {
      qhg[al].setZero();
      qdot[al].setZero();
      for (int a = 0; a < 8; ++a) {
        qhg[al] += gam(al, a) * u[a];
        qdot[al] += gam(al, a) * vel[a];
      }
      stored_hg_ += 0.5 * hg_stiffness_[e] * qhg[al].squaredNorm();
    }
    const double khg = hg_stiffness_[e], chg = hg_viscous_[e];
    // Nodal forces: -V0 P B0_a (rubber and cords), -V0 P_v B0_a (bulk viscosity),
    // -k gamma^T Q (hourglass stiffness), -c gamma^T Q_dot (hourglass viscosity).
    for (int a = 0; a < 8; ++a) {
      const Vector3d g = ref.grad.row(a).transpose();
      Vector3d hs = Vector3d::Zero(), hv = Vector3d::Zero();
      for (int al = 0; al < 4; ++al) {
        hs += gam(al, a) * qhg[al];
        hv += gam(al, a) * qdot[al];
      }
      f_stored_[nodes[a]] += ps * g - khg * hs;
      f_dissip_bv_[nodes[a]] += pv * g;
      if (chg > 0.0) f_dissip_hg_[nodes[a]] -= chg * hv;
    }
  }

  // Inflation pressure: a follower load on each face, a quarter of p times the area vector on
  // each of its nodes, pushing into the solid.
  if (pressure_Pa_ != 0.0) {
    for (const auto& face : mesh_.pressure_faces) {
      const Eigen::Vector3d area =
          0.5 * (x_[face[2]] - x_[face[0]]).cross(x_[face[3]] - x_[face[1]]);
      for (int n : face) f_external_[n] -= 0.25 * pressure_Pa_ * area;
    }
  }

  // Road: penalty normal force and friction (002:1).
  if (road_.enabled) {
    const Eigen::Vector3d road_velocity(road_.road_speed_x_mps, 0.0, 0.0);
    for (int a : mesh_.contact_nodes) {
      const double g = road_.height_m - x_[a].z();
      if (g <= 0.0) continue;
      const double fn = contact_stiffness_[a] * g;
      contact_normal_[a] = fn;
      f_contact_[a].z() += fn;
      stored_contact_ += 0.5 * contact_stiffness_[a] * g * g;
      f_friction_[a] +=
          CalcFrictionForce(road_.friction, fn, v_[a] - road_velocity, mass_[a] / dt_);
    }
  }
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

void ExplicitSolver::Step() {
  ComputeForces();
  const size_t nn = x_.size();
  v_old_ = v_;
  const std::vector<Eigen::Vector3d>& v_old = v_old_;
  const Eigen::Vector3d rim_v_old = rim_.velocity;
  const double rim_w_old = rim_.spin_rad_per_s;

  for (size_t a = 0; a < nn; ++a) {
    reaction_[a].setZero();
    if (is_rim_node_[a]) continue;
    const Eigen::Vector3d f = f_stored_[a] + f_dissip_bv_[a] + f_dissip_hg_[a] + f_damp_[a] +
                              f_contact_[a] + f_friction_[a] + f_external_[a];
    for (int d = 0; d < 3; ++d) {
      if (fixed_[a][d]) {
        v_[a](d) = fixed_velocity_[a](d);
        reaction_[a](d) = mass_[a] * (v_[a](d) - v_old[a](d)) / dt_ - f(d);
      } else {
        v_[a](d) += dt_ * f(d) / mass_[a];
      }
    }
  }
  // The rim: its applied loads and constraint reactions do work at its mean velocity.
  if (has_rim_) {
    AdvanceRim();
  }
  for (size_t a = 0; a < nn; ++a) {
    if (!is_rim_node_[a]) x_[a] += dt_ * v_[a];
  }

  // Energy accounting. The work of f(n) is f(n) . (x(n+1) - x(n-1)) / 2 (trapezoidal in the
  // forces), of which the second half lies beyond t(n) and is held back from the energies
  // reported at t(n); the kinetic energy at t(n) is m v(n-1/2) . v(n+1/2) / 2. For a linear
  // system this balance is exact under central differences; with the mean velocity squared, or
  // with the look-ahead half counted, it is off by terms of order omega dt, large for the
  // highest modes.
  // Work terms: external (with reactions), bulk viscosity, viscous hourglass, damping, friction.
  std::array<double, 5> back{}, ahead{};
  double ke = 0.0;
  const bool first = steps_ == 0;
  const auto add = [&](const Eigen::Vector3d& f, int kind, const Eigen::Vector3d& vo,
                       const Eigen::Vector3d& vn) {
    if (!first) back[kind] += f.dot(vo);
    ahead[kind] += f.dot(vn);
  };
  for (size_t a = 0; a < nn; ++a) {
    add(f_external_[a] + reaction_[a], 0, v_old[a], v_[a]);
    add(f_dissip_bv_[a], 1, v_old[a], v_[a]);
    add(f_dissip_hg_[a], 2, v_old[a], v_[a]);
    add(f_damp_[a], 3, v_old[a], v_[a]);
    add(f_friction_[a], 4, v_old[a], v_[a]);
    if (!is_rim_node_[a]) ke += 0.5 * mass_[a] * v_old[a].dot(v_[a]);
  }
  if (has_rim_) {
    const Eigen::Vector3d f(rim_loads_.force_x_N + rim_reaction_.force_x_N,
                            rim_loads_.torque_Nm + rim_reaction_.torque_Nm,
                            rim_loads_.force_z_N + rim_reaction_.force_z_N);
    add(f, 0, Eigen::Vector3d(rim_v_old.x(), rim_w_old, rim_v_old.z()),
        Eigen::Vector3d(rim_.velocity.x(), rim_.spin_rad_per_s, rim_.velocity.z()));
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
  energies_.friction = -now[4];
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

std::vector<Eigen::Vector3d> ExplicitSolver::CalcElementForces() {
  ComputeForces();
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

}  // namespace hotlap::fe
