#pragma once
/// @file
/// The explicit solver in one object: a model (explicit_model.h), its state (explicit_state.h),
/// the step options and the step's scratch (explicit_step.h), with the calls a run makes. A
/// hexahedral rubber mesh: lumped mass, central differences, one-point hexahedra with
/// Flanagan-Belytschko hourglass control, Yeoh rubber, smeared cords, bulk viscosity, optional
/// mass scaling and mass-proportional damping, a rigid road with friction, a follower inflation
/// pressure and a rigid rim driven by force and torque.
///
/// How to use:
///
///   fe::ExplicitSolver solver(mesh, materials, rebars, options);
///   solver.SetRoad(road);                 // optional
///   solver.SetRim(rim);                   // optional: mesh.rim_nodes tied to a rigid body
///   solver.Prescribe(node, dof, speed);   // optional velocity boundary conditions
///   solver.set_pressure(220e3);           // inflation, Pa, on mesh.pressure_faces
///   while (solver.time() < t_end) { solver.rim_loads().torque_Nm = ...; solver.Step(); }
///   const fe::Energies& e = solver.energies();
///
/// The same without the object: model(), state() and step_options() are the three parts, and
/// Step() is AdvanceExplicit(model, step_options, state, workspace). The checkpoint (SaveState,
/// LoadState) is the state whole (explicit_checkpoint.h).

#include <vector>

#include <Eigen/Core>

#include "hotlap/fe/checkpoint.h"
#include "hotlap/fe/element_kernel.h"
#include "hotlap/fe/explicit_checkpoint.h"
#include "hotlap/fe/explicit_model.h"
#include "hotlap/fe/explicit_state.h"
#include "hotlap/fe/explicit_step.h"
#include "hotlap/fe/mesh.h"
#include "hotlap/fe/rebar.h"
#include "hotlap/fe/road_contact.h"
#include "hotlap/fe/yeoh.h"

namespace hotlap::fe {

/// The explicit solver. Holds its model, state, step options and scratch.
class ExplicitSolver {
 public:
  ExplicitSolver(Mesh mesh, std::vector<YeohMaterial> materials, std::vector<RebarMaterial> rebars,
                 const SolverOptions& options);

  /// The immutable model: mesh, materials, tables, time step.
  const ExplicitModel& model() const { return model_; }
  /// The state: everything a checkpoint holds.
  const ExplicitState& state() const { return state_; }
  ExplicitState& mutable_state() { return state_; }
  /// Threads, assembly and element kernel of Step().
  const StepOptions& step_options() const { return step_options_; }

  /// Sets the road; drops every stick anchor (no node has touched this road yet).
  void SetRoad(const RoadContact& road) { fe::SetRoad(road, state_); }
  /// Ties mesh.rim_nodes to a rigid rim. Prescribed rim DOFs start at zero velocity.
  void SetRim(const RimSettings& rim) { fe::SetRim(model_, rim, state_); }
  /// Velocity boundary condition on one node's dof (0 x, 1 y, 2 z), m/s. Call again to change.
  void Prescribe(int node, int dof, double velocity_mps) {
    state_.fixed[node][dof] = 1;
    state_.fixed_velocity[node](dof) = velocity_mps;
  }
  /// fe::SetInitialVelocity: every free node's velocity, m/s.
  void SetInitialVelocity(const std::vector<Eigen::Vector3d>& v) {
    fe::SetInitialVelocity(model_, v, state_);
  }
  /// fe::SetRimMotion: the rim's velocity (m/s) and spin (rad/s).
  void SetRimMotion(double vx_mps, double vz_mps, double spin_rad_per_s) {
    fe::SetRimMotion(model_, vx_mps, vz_mps, spin_rad_per_s, state_);
  }
  /// fe::AddRimTranslationalMass, kg.
  void AddRimTranslationalMass(double mass_kg) { fe::AddRimTranslationalMass(mass_kg, state_); }
  /// Translational mass of the rim with its tied nodes, kg.
  double rim_mass() const { return state_.rim_mass_kg; }
  /// Changes how the rim's DOFs move (e.g. free spin for rolling); needs SetRim first.
  void SetRimModes(RimDofMode x_mode, RimDofMode z_mode, RimDofMode spin_mode);

  /// Threads of the element and node loops (StepOptions::threads; 0: the default). Throws
  /// InputError if negative.
  void set_threads(int threads);
  static constexpr int kElementsPerThread = StepOptions::kElementsPerThread;
  /// The thread count the loops use.
  int threads() const { return ResolveThreads(step_options_, model_); }
  void set_assembly(Assembly assembly) { step_options_.assembly = assembly; }
  Assembly assembly() const { return step_options_.assembly; }
  /// The element loop's instruction set (default BestElementKernel()). Throws InputError if
  /// this machine does not support it.
  void set_element_kernel(ElementKernel kernel);
  ElementKernel element_kernel() const { return step_options_.kernel; }
  /// StepOptions::rim_sum_rotation: the rim's sums over its nodes begin at this node (round-off).
  void set_rim_sum_rotation(int rotation) { step_options_.rim_sum_rotation = rotation; }
  /// Number of element colours (no two elements of a colour share a node).
  int colours() const { return model_.colours(); }
  /// The elements of colour c, ascending.
  std::vector<int> ColourElements(int c) const { return model_.ColourElements(c); }

  /// Writes the whole state (SaveExplicitState) so that LoadState on a solver built from the
  /// same mesh, materials and options continues bit for bit.
  void SaveState(BinaryWriter& out) const { SaveExplicitState(model_, state_, out); }
  /// Reads what SaveState wrote. Throws InputError (via the reader) if it does not fit this
  /// solver (array sizes, time step); the solver is then unchanged.
  void LoadState(BinaryReader& in) { LoadExplicitState(model_, in, state_); }

  /// Mass-proportional damping, 1/s (quasi-static steps on, dynamic steps off).
  void set_mass_damping(double alpha_per_s) { state_.mass_damping_per_s = alpha_per_s; }
  /// Moves the nodes (a restart, or a test's chosen configuration), m.
  void SetPositions(const std::vector<Eigen::Vector3d>& x) { state_.x = x; }
  /// fe::CalcElementForces: the element forces at the current state, N.
  std::vector<Eigen::Vector3d> CalcElementForces() {
    return fe::CalcElementForces(model_, step_options_, state_, workspace_);
  }

  void set_pressure(double pressure_Pa) { state_.pressure_Pa = pressure_Pa; }
  /// Nodal forces held constant until changed, N.
  std::vector<Eigen::Vector3d>& applied_forces() { return state_.applied; }
  RimLoads& rim_loads() { return state_.rim_loads; }
  /// Velocity of the prescribed rim DOFs (translation m/s, spin rad/s).
  void SetRimVelocity(double vx_mps, double vz_mps, double spin_rad_per_s) {
    state_.rim_target = Eigen::Vector3d(vx_mps, vz_mps, spin_rad_per_s);
  }

  /// One central-difference step (AdvanceExplicit). Throws NumericalError on an inverted element
  /// or non-finite state.
  void Step() { AdvanceExplicit(model_, step_options_, state_, workspace_); }

  double time() const { return state_.time_s; }
  std::int64_t steps() const { return state_.steps; }
  double time_step() const { return model_.time_step_s; }
  const MassScalingReport& mass_scaling() const { return model_.mass_report; }
  const Energies& energies() const { return state_.energies; }
  const Mesh& mesh() const { return model_.mesh; }
  const std::vector<Eigen::Vector3d>& positions() const { return state_.x; }
  /// Lumped nodal masses (with cords and mass scaling), kg.
  const std::vector<double>& node_masses() const { return model_.mass; }
  /// Velocities at the last half step, m/s.
  const std::vector<Eigen::Vector3d>& velocities() const { return state_.v; }
  /// Reaction forces at prescribed dofs from the last step (zero elsewhere), N.
  const std::vector<Eigen::Vector3d>& reactions() const { return state_.reaction; }
  /// Road contact normal force per node from the last step (z), N.
  const std::vector<double>& contact_forces() const { return state_.contact_normal; }
  /// Extension x_t - anchor of each node's stick spring (tangential x, y) after the last step's
  /// return mapping, m; zero for a node off the road (road_contact.h, StickModel::kElasticSpring).
  const std::vector<Eigen::Vector2d>& stick_extensions() const { return state_.stick_extension; }
  /// Tangential stiffness k_t of each node's stick spring on the current road, N/m.
  std::vector<double> stick_stiffness() const;
  /// Sum of the road's force on the tyre from the last step (friction x, y; normal z), N.
  Eigen::Vector3d RoadForce() const { return CalcRoadForce(model_, state_); }
  const RimState& rim_state() const { return state_.rim; }
  /// Reaction loads of the prescribed rim DOFs from the last step.
  const RimLoads& rim_reactions() const { return state_.rim_reaction; }
  /// Cauchy stress of element `e` at the current positions (rubber plus cords), Pa.
  Eigen::Matrix3d ElementStress(int e) const { return CalcElementStress(model_, state_.x, e); }
  /// Number of element updates done so far (elements times steps).
  double element_updates() const { return double(state_.steps) * model_.mesh.elements.size(); }
  /// The stable step of the reference mesh before the safety factor, s.
  double StableStepEstimate() const { return model_.stable_step_s; }
  /// CalcMaxCordStrain at the current positions.
  double MaxCordStrain() const { return CalcMaxCordStrain(model_, state_.x); }

 private:
  ExplicitModel model_;
  ExplicitState state_;
  StepOptions step_options_;
  ExplicitWorkspace workspace_;
};

}  // namespace hotlap::fe
