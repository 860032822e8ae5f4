#pragma once
/// @file
/// The explicit solver's model: what does not change while it runs (MuJoCo's mjModel). The mesh,
/// its rubber and cord materials and the solver settings, and what is computed from them once:
/// each element's reference gradients, density, wave speed and hourglass coefficients, the lumped
/// nodal masses, the element colours, the pressure faces of each node, and the time step. What
/// changes is ExplicitState (explicit_state.h); explicit_step.h advances a state of a model.
///
///   const fe::ExplicitModel model = fe::MakeExplicitModel(mesh, materials, rebars, options);
///   fe::ExplicitState state = fe::MakeInitialState(model);
///
/// The time step is fixed: SolverOptions::time_step_safety times the smallest element's stable
/// step, the central-difference limit (omega dt)^2 / 4 + mu dt / 2 <= 1 of a mode of frequency
/// omega damped at the rate mu = 2 xi omega with the damping force lagged half a step:
///   dt_e = (2 / omega^2) (sqrt(omega^2 + mu^2 / 4) - mu / 2) = (2 / omega) (sqrt(1 + xi^2) - xi),
/// taken with the element's largest frequency and largest damping rate (the limit decreases in
/// both, so this is safe whatever the modes). With lumped mass rho V0 / 8 per node (rho with the
/// cords' mass):
///   omega^2 = 8 / rho [(K + 4/3 mu0) sum_a |B0_a|^2
///                      + sum_cords phi E (1 + 3 E_max) sum_a (B0_a . a0)^2 + k_hg lambda_hg / V0],
///   mu = 8 b1 c_d L_e sum_a |B0_a|^2 + 8 c_hg lambda_hg / (rho V0),  c_d^2 = (K + 4/3 mu0) / rho,
/// lambda_hg the largest eigenvalue of Gamma Gamma^T (Gamma: the four hourglass vectors), k_hg and
/// c_hg the hourglass stiffness and viscosity. The rubber term is the Flanagan-Belytschko bound
/// for the one-point hexahedron (for a cube of edge L, omega = sqrt(12) c_d / L; the cube's true
/// highest frequency, its volumetric mode, is within 3.3% of it when K = 20 mu0). A cord is stiff
/// only along itself: its term uses the gradient along the cord, B0_a . a0, and is exact for its
/// mode at the cord strain E_max = kCordStrainAllowance (CalcMaxCordStrain reports the strain
/// reached). In a thin belt element whose cords run along its long sides it is several times
/// below the isotropic c^2 = (K + 4/3 mu0 + phi E) / rho used before. The bulk viscosity's rate
/// is exact at the reference state (it is rank one along B0); not counted: its quadratic term
/// (compression only), the growth of its rate as an element is squeezed thin, and mass damping
/// (set per step, a few hundred per second against some 1e4 per second), all left to the safety
/// factor. The bulk viscosity and the viscous hourglass use the rubber's c_d: the cords do not
/// stiffen the hourglass modes, nor the volumetric mode of a thin element (which squeezes its
/// thickness, across the cords).

#include <vector>

#include <Eigen/Core>

#include "hotlap/fe/hex8.h"
#include "hotlap/fe/mesh.h"
#include "hotlap/fe/rebar.h"
#include "hotlap/fe/yeoh.h"

namespace hotlap::fe {

/// The cord strain (Green-Lagrange) up to which the stable step accounts for a stretched cord's
/// stiffness, 1 + 3 E_f: 3%, several times a tyre cord's working strain. The step's safety factor
/// (0.9) leaves room for far more (a cord-dominated element stays stable up to E_f of about 11%).
inline constexpr double kCordStrainAllowance = 0.03;

/// Solver settings. The defaults are Abaqus/Explicit's where it has one.
struct SolverOptions {
  double time_step_safety = 0.9;          ///< fraction of the stable step, in (0, 1]
  double bulk_viscosity_linear = 0.06;    ///< b1 (Abaqus default), 1
  double bulk_viscosity_quadratic = 1.2;  ///< b2 (Abaqus default), 1
  /// Hourglass stiffness k = coeff mu0 V0 sum|B0|^2 / 8 per element, 1 (FB stiffness form).
  double hourglass_stiffness = 0.05;
  /// Viscous hourglass c = coeff rho c_d V0^(2/3) / 4 per element, 1 (FB viscous form; 0 = off).
  double hourglass_viscous = 0.0;
  /// Mass scaling: elements whose stable step is below this get their density raised so that
  /// it is this, s (0 = none). Always reported (MassScalingReport).
  double mass_scaling_min_step_s = 0.0;
  /// alpha of the damping force -alpha m v, 1/s (>= 0): the initial value of
  /// ExplicitState::mass_damping_per_s (the steps change it).
  double mass_damping_per_s = 0.0;
  double time_step_s = 0.0;  ///< fixed step if > 0 (must not exceed the stable one), s
  /// The step actually taken is this times the step above (time_step_s if > 0, else
  /// time_step_safety times the stable step), in (0, 1]: a time-step study (`hotlap fe
  /// --step-scale`). The road's penalty springs keep the stiffness of the unscaled step
  /// (ExplicitModel::contact_step_s), so a smaller scale refines the time discretisation of the
  /// same model and does not stiffen the contact.
  double time_step_scale = 1.0;
};

/// What mass scaling did.
struct MassScalingReport {
  int scaled_elements = 0;
  double physical_mass_kg = 0.0;  ///< rubber + cords
  double added_mass_kg = 0.0;     ///< added by mass scaling
  double stable_step_unscaled_s = 0.0;
};

/// The immutable model. Build it with MakeExplicitModel; every table is indexed as the mesh.
struct ExplicitModel {
  Mesh mesh;  ///< mesh.nodes are the reference positions X
  std::vector<YeohMaterial> materials;
  std::vector<RebarMaterial> rebars;
  SolverOptions options;

  std::vector<Hex8Reference> refs;        ///< per element: B0, volume, length, hourglass vectors
  std::vector<double> elem_density;       ///< with cords and mass scaling, kg/m^3
  std::vector<double> elem_wave_speed;    ///< the rubber's c_d with that density, m/s
  std::vector<double> hg_stiffness;       ///< k_hg per element, N/m
  std::vector<double> hg_viscous;         ///< c_hg per element, N s/m
  bool viscous_hourglass = false;         ///< any hg_viscous > 0
  std::vector<int> fibre_start;           ///< CSR over fibres_sorted, per element
  std::vector<FibreLayer> fibres_sorted;  ///< mesh.fibres sorted by host element (stable)
  std::vector<double> mass;               ///< lumped nodal masses (cords, mass scaling), kg
  std::vector<int> colour_start;          ///< CSR over colour_elements, per colour
  std::vector<int> colour_elements;       ///< ascending within a colour
  std::vector<int> node_face_start;       ///< CSR over node_faces, per node
  std::vector<int> node_faces;            ///< pressure faces of each node, in face order
  std::vector<char> is_contact_node;      ///< 1 for mesh.contact_nodes
  std::vector<char> is_rim_node;          ///< 1 for mesh.rim_nodes (tied once a rim is set)
  double stable_step_s = 0.0;             ///< smallest element step, before the safety factor, s
  double time_step_s = 0.0;               ///< the fixed step, s
  /// The step the road's penalty stiffnesses refer to (k = factor m / contact_step_s^2): the
  /// step before SolverOptions::time_step_scale, s. Equal to time_step_s at scale 1.
  double contact_step_s = 0.0;
  MassScalingReport mass_report;

  /// Number of element colours (no two elements of a colour share a node).
  int colours() const { return static_cast<int>(colour_start.size()) - 1; }
  /// The elements of colour c, ascending.
  std::vector<int> ColourElements(int c) const {
    return {colour_elements.begin() + colour_start.at(c),
            colour_elements.begin() + colour_start.at(c + 1)};
  }
};

/// Builds the model: reference gradients, stable steps, mass scaling, lumped masses, colours.
/// Throws NumericalError if no valid time step results (or more than 64 colours are needed).
ExplicitModel MakeExplicitModel(Mesh mesh, std::vector<YeohMaterial> materials,
                                std::vector<RebarMaterial> rebars, const SolverOptions& options);

/// The largest Green-Lagrange strain of any cord at positions `x` (0 without cords or if none is
/// stretched). The stable step counts a cord's stiffness at kCordStrainAllowance; the safety
/// factor covers a cord-dominated element to about 11%.
double CalcMaxCordStrain(const ExplicitModel& model, const std::vector<Eigen::Vector3d>& x);

/// Cauchy stress of element `e` at positions `x` (rubber plus cords), Pa.
Eigen::Matrix3d CalcElementStress(const ExplicitModel& model, const std::vector<Eigen::Vector3d>& x,
                                  int e);

}  // namespace hotlap::fe
