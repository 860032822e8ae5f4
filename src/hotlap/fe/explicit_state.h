#pragma once
/// @file
/// The explicit solver's state: everything that changes while it runs (MuJoCo's mjData without
/// its scratch), one plain struct. VisitFields lists its fields; the checkpoint's writer and
/// reader both walk that list (explicit_checkpoint.h), so the checkpoint holds the state whole,
/// and a test (FeExplicitState.VisitFieldsCoversEveryMember) fails when a member is added to a
/// struct here but not to its VisitFields.
///
///   fe::ExplicitState state = fe::MakeInitialState(model);
///   fe::SetRim(model, rim, state);       // optional: mesh.rim_nodes tied to a rigid body
///   fe::SetRoad(road, state);            // optional
///   state.pressure_Pa = 220e3;           // inflation, Pa, on mesh.pressure_faces
///   fe::AdvanceExplicit(model, step_options, state, workspace);  // explicit_step.h
///
/// Energies: the strain energy (rubber and cords) and the stored hourglass and contact energies
/// are state functions evaluated from the positions (and the stick springs' extensions); the
/// kinetic energy at t(n) is m v(n-1/2) . v(n+1/2) / 2 (the form that central differences conserve
/// exactly for a linear system); dissipation and external work are accumulated as
/// (f(n) + f(n+1)) . (x(n+1) - x(n)) / 2 up to t(n). The initial kinetic energy is that form at
/// the first step. Friction with the elastic stick is booked from the return mapping, not from the
/// nodes' motion: (f(n) + f(n+1)) . (anchor(n+1) - anchor(n)) / 2 per node, the anchors' moves
/// relative to the road (the road's own work on the friction forces, f . v_road, is external).
/// Their balance is therefore a genuine check of the force computation (Energies::BalanceError):
/// for a stick spring, it closes only if the friction force applied to the node, the spring's
/// stored energy and the anchor's moves agree.

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "hotlap/fe/explicit_model.h"
#include "hotlap/fe/road_contact.h"
#include "hotlap/fe/visit_fields.h"

namespace hotlap::fe {

/// Energy accounting, J. Stored terms are state functions; the others are accumulated.
struct Energies {
  double kinetic = 0.0;               ///< nodes and rigid rim, m v(n-1/2) . v(n+1/2) / 2
  double internal = 0.0;              ///< strain energy of the rubber and the cords (stored)
  double hourglass_stored = 0.0;      ///< FB stiffness-form energy (stored)
  double hourglass_dissipated = 0.0;  ///< FB viscous-form work
  double bulk_viscous = 0.0;          ///< dissipated by bulk viscosity
  double damping = 0.0;               ///< dissipated by mass-proportional damping
  /// Penalty energies of the road, normal k g^2 / 2 and tangential (the stick springs)
  /// k_t |x_t - anchor|^2 / 2 (stored).
  double contact_stored = 0.0;
  /// Dissipated by road friction: the limit force's work over the anchors' moves (elastic
  /// stick), or all the friction work relative to the road (viscous stick).
  double friction = 0.0;
  double external_work = 0.0;    ///< pressure, nodal loads, rim loads, prescribed motion, road
  double initial_kinetic = 0.0;  ///< the kinetic energy at the first step

  double Hourglass() const { return hourglass_stored + hourglass_dissipated; }
  /// kinetic + internal + hourglass + dissipated + contact - external work - initial kinetic.
  double BalanceError() const {
    return kinetic + internal + Hourglass() + bulk_viscous + damping + contact_stored + friction -
           external_work - initial_kinetic;
  }
};

/// What can move the rim along one of its three planar degrees of freedom.
enum class RimDofMode : std::uint8_t { kFree, kPrescribedVelocity };
/// The largest RimDofMode (checkpoint readers refuse anything above; field_io.h).
constexpr std::uint64_t EnumMax(RimDofMode) {
  return std::uint64_t(RimDofMode::kPrescribedVelocity);
}

/// The rigid rim: mesh.rim_nodes move with a rigid body that translates in x and z and turns
/// about the axle (+y). Positive spin about +y rolls the tyre towards +x on a road below it.
struct RimSettings {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< axle centre (reference), m
  double mass_kg = 0.0;       ///< the rim's own mass (tied nodes add theirs), kg
  double inertia_kgm2 = 0.0;  ///< the rim's own spin inertia, kg m^2
  RimDofMode x_mode = RimDofMode::kPrescribedVelocity;
  RimDofMode z_mode = RimDofMode::kPrescribedVelocity;
  RimDofMode spin_mode = RimDofMode::kPrescribedVelocity;
};

/// The rim's motion.
struct RimState {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();    ///< m
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  ///< at the last half step, m/s
  double angle_rad = 0.0;                              ///< spin about +y, rad
  double spin_rad_per_s = 0.0;                         ///< at the last half step, rad/s
};

/// Loads on the rim (or, for prescribed DOFs, the reactions the constraint needed).
struct RimLoads {
  double force_x_N = 0.0;
  double force_z_N = 0.0;
  double torque_Nm = 0.0;  ///< about +y; a brake torque on a forward-rolling wheel is negative
};

/// Everything that changes while the solver runs. Node arrays are indexed as model.mesh.nodes.
/// Velocities are at the last half step (central differences), positions and forces at the
/// last whole step.
struct ExplicitState {
  double time_s = 0.0;
  std::int64_t steps = 0;
  double pressure_Pa = 0.0;                ///< inflation, on mesh.pressure_faces (a follower load)
  double mass_damping_per_s = 0.0;         ///< alpha of the damping force -alpha m v, 1/s
  std::vector<Eigen::Vector3d> x;          ///< positions, m
  std::vector<Eigen::Vector3d> v;          ///< velocities at the last half step, m/s
  std::vector<Eigen::Vector3d> applied;    ///< nodal forces held until changed, N
  std::vector<Eigen::Vector3d> reaction;   ///< at prescribed dofs, last step (zero elsewhere), N
  std::vector<std::array<char, 3>> fixed;  ///< 1 where a dof's velocity is prescribed
  std::vector<Eigen::Vector3d> fixed_velocity;  ///< the prescribed velocities, m/s
  // The last step's nodal forces by kind, N.
  std::vector<Eigen::Vector3d> f_stored;     ///< rubber, cords, hourglass stiffness
  std::vector<Eigen::Vector3d> f_dissip_bv;  ///< bulk viscosity
  std::vector<Eigen::Vector3d> f_dissip_hg;  ///< viscous hourglass
  std::vector<Eigen::Vector3d> f_damp;       ///< mass-proportional damping
  std::vector<Eigen::Vector3d> f_contact;    ///< the road's normal force
  std::vector<Eigen::Vector3d> f_friction;   ///< the road's friction
  std::vector<Eigen::Vector3d> f_external;   ///< applied and pressure
  std::vector<double> contact_normal;        ///< the road's normal force (z), N

  RoadContact road;
  /// The stick springs (road_contact.h): each node's extension x_t - anchor (the anchor moves
  /// with the road), m, and whether it was on the road at the last step (its anchor is set).
  std::vector<Eigen::Vector2d> stick_extension;
  std::vector<char> on_road;

  std::optional<RimSettings> rim_settings;  ///< set by SetRim: mesh.rim_nodes are tied
  RimState rim;
  RimLoads rim_loads;                                    ///< applied to the rim, held until changed
  RimLoads rim_reaction;                                 ///< of the prescribed rim dofs, last step
  Eigen::Vector3d rim_target = Eigen::Vector3d::Zero();  ///< prescribed vx, vz (m/s), spin (rad/s)
  double rim_mass_kg = 0.0;       ///< with the tied nodes (and a quarter car, when braking)
  double rim_inertia_kgm2 = 0.0;  ///< with the tied nodes

  Energies energies;
  double stored_internal = 0.0, stored_hourglass = 0.0, stored_contact = 0.0;  ///< J
  /// Work up to the last half step: external, bulk viscosity, hourglass, damping, friction
  /// (relative to the road; the road's own work on the friction forces is external), J.
  std::array<double, 5> work_to_midstep{};
  double slip_dissipation = 0.0;  ///< friction dissipated by the anchors' moves, J
};

/// The state at rest at the reference positions, with the model's initial mass damping.
ExplicitState MakeInitialState(const ExplicitModel& model);

/// Sets the road; drops every stick anchor (no node has touched this road yet).
void SetRoad(const RoadContact& road, ExplicitState& state);
/// Ties mesh.rim_nodes to a rigid rim at rest. Prescribed rim DOFs start at zero velocity.
void SetRim(const ExplicitModel& model, const RimSettings& rim, ExplicitState& state);
/// Sets the velocity of every free node, m/s. Before the first step this is the initial
/// condition; later (a step that starts rolling) the change of kinetic energy is booked as
/// external work.
void SetInitialVelocity(const ExplicitModel& model, const std::vector<Eigen::Vector3d>& v,
                        ExplicitState& state);
/// Sets the rim's velocity and spin (translation m/s, spin rad/s), e.g. to start rolling; the
/// change of its kinetic energy is booked as external work after the first step.
void SetRimMotion(const ExplicitModel& model, double vx_mps, double vz_mps, double spin_rad_per_s,
                  ExplicitState& state);
/// The velocity omega y-hat x r of a point at r from the spin axis (the rim's y axis), m/s.
inline Eigen::Vector3d SpinVelocity(double omega, const Eigen::Vector3d& r) {
  return {omega * r.z(), 0.0, -omega * r.x()};
}

/// Adds translational mass to the rim (a quarter car for braking), kg; its spin inertia stays.
/// The added mass's kinetic energy at the rim's speed is booked as external work.
void AddRimTranslationalMass(double mass_kg, ExplicitState& state);

// The fields of each struct, in checkpoint order: visit(name, member) for every member.

HOTLAP_VISIT_FIELDS(Energies, kinetic, internal, hourglass_stored, hourglass_dissipated,
                    bulk_viscous, damping, contact_stored, friction, external_work, initial_kinetic)

HOTLAP_VISIT_FIELDS(RimSettings, centre, mass_kg, inertia_kgm2, x_mode, z_mode, spin_mode)

HOTLAP_VISIT_FIELDS(RimState, centre, velocity, angle_rad, spin_rad_per_s)

HOTLAP_VISIT_FIELDS(RimLoads, force_x_N, force_z_N, torque_Nm)

HOTLAP_VISIT_FIELDS(ExplicitState, time_s, steps, pressure_Pa, mass_damping_per_s, x, v, applied,
                    reaction, fixed, fixed_velocity, f_stored, f_dissip_bv, f_dissip_hg, f_damp,
                    f_contact, f_friction, f_external, contact_normal, road, stick_extension,
                    on_road, rim_settings, rim, rim_loads, rim_reaction, rim_target, rim_mass_kg,
                    rim_inertia_kgm2, energies, stored_internal, stored_hourglass, stored_contact,
                    work_to_midstep, slip_dissipation)

}  // namespace hotlap::fe
