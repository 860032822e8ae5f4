#pragma once
/// @file
/// Explicit dynamics of a hexahedral rubber mesh: lumped mass, central differences, one-point
/// hexahedra with Flanagan-Belytschko hourglass control, Yeoh rubber, smeared cords, bulk
/// viscosity, optional mass scaling and mass-proportional damping, a rigid road with friction,
/// a follower inflation pressure and a rigid rim driven by force and torque.
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
/// Central difference (velocities at half steps, positions at whole steps):
///   v(n+1/2) = v(n-1/2) + dt M^-1 f(x(n), v(n-1/2)),  x(n+1) = x(n) + dt v(n+1/2).
/// Velocity-dependent forces (bulk viscosity, viscous hourglass, damping, friction) use v(n-1/2).
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
/// mode at the cord strain E_max = kCordStrainAllowance (MaxCordStrain() reports the strain
/// reached). In a thin belt element whose cords run along its long sides it is several times
/// below the isotropic c^2 = (K + 4/3 mu0 + phi E) / rho used before. The bulk viscosity's rate
/// is exact at the reference state (it is rank one along B0); not counted: its quadratic term
/// (compression only), the growth of its rate as an element is squeezed thin, and mass damping
/// (set per step, a few hundred per second against some 1e4 per second), all left to the safety
/// factor. The bulk viscosity and the viscous hourglass use the rubber's c_d: the cords do not
/// stiffen the hourglass modes, nor the volumetric mode of a thin element (which squeezes its
/// thickness, across the cords).
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
///
/// Threads (OpenMP): the element loop (rubber, cords, hourglass, bulk viscosity), the pressure
/// faces and the node loop (contact, friction, damping, the update, the energy sums) run on
/// set_threads() threads in one parallel region per step; the rim is serial. Two assemblies:
/// Assembly::kThreadBuffers (the default, the faster one: docs/fe-tyre.md) gives each thread a
/// contiguous range of elements and its own force buffer, summed per node in thread order:
/// deterministic for a given thread count, and equal to the serial (one-thread) result to
/// round-off. Assembly::kColoured splits the elements into colours whose elements share no node;
/// each colour runs in parallel and adds straight to the nodes: the same bits for every thread
/// count, but slower (a barrier per colour, and each colour sweeps the whole mesh). Every sum
/// (energies) is taken over fixed blocks in a fixed order, so it does not depend on the thread
/// count.

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "hotlap/fe/hex8.h"
#include "hotlap/fe/mesh.h"
#include "hotlap/fe/rebar.h"
#include "hotlap/fe/road_contact.h"
#include "hotlap/fe/yeoh.h"

namespace hotlap::fe {

class BinaryReader;
class BinaryWriter;

/// How the parallel element loop adds element forces to the nodes (see the file comment).
enum class Assembly : std::uint8_t {
  kThreadBuffers,  ///< a force buffer per thread, summed after the loop in thread order (default)
  kColoured,       ///< colours of elements that share no node; independent of the thread count
};

/// OpenMP's default thread count (omp_get_max_threads(): the cores, or OMP_NUM_THREADS).
int DefaultThreadCount();

/// The instruction set the element loop is compiled for (docs/fe-tyre.md, "Speed"). The binary
/// carries both and picks at run time, so it runs on every x86-64 machine.
enum class ElementKernel : std::uint8_t {
  kPortable,  ///< the x86-64 baseline (SSE2), on every machine
  kAvx2,      ///< AVX2 with fused multiply-add: faster; results differ in the last bits
};

/// Whether this machine can run `kernel` (kAvx2: the CPU has AVX2 and FMA; x86-64 GCC builds).
bool ElementKernelSupported(ElementKernel kernel);
/// The kernel a new solver uses: kAvx2 where supported, unless the environment variable
/// HOTLAP_FE_KERNEL is "portable" (then kPortable; "avx2" asks for kAvx2 and throws InputError
/// where it is not supported; "auto" or unset is the default; anything else throws InputError).
ElementKernel DefaultElementKernel();
/// "portable" or "avx2".
const char* ElementKernelName(ElementKernel kernel);

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
  double mass_damping_per_s = 0.0;  ///< alpha of the damping force -alpha m v, 1/s (>= 0)
  double time_step_s = 0.0;         ///< fixed step if > 0 (must not exceed the stable one), s
};

/// What mass scaling did.
struct MassScalingReport {
  int scaled_elements = 0;
  double physical_mass_kg = 0.0;  ///< rubber + cords
  double added_mass_kg = 0.0;     ///< added by mass scaling
  double stable_step_unscaled_s = 0.0;
};

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

/// The explicit solver. Holds copies of the model and the state.
class ExplicitSolver {
 public:
  ExplicitSolver(Mesh mesh, std::vector<YeohMaterial> materials, std::vector<RebarMaterial> rebars,
                 const SolverOptions& options);

  /// Sets the road; drops every stick anchor (no node has touched this road yet).
  void SetRoad(const RoadContact& road);
  /// Ties mesh.rim_nodes to a rigid rim. Prescribed rim DOFs start at zero velocity.
  void SetRim(const RimSettings& rim);
  /// Velocity boundary condition on one node's dof (0 x, 1 y, 2 z), m/s. Call again to change.
  void Prescribe(int node, int dof, double velocity_mps);
  /// Sets the velocity of every free node, m/s. Before the first step this is the initial
  /// condition; later (a step that starts rolling) the change of kinetic energy is booked as
  /// external work.
  void SetInitialVelocity(const std::vector<Eigen::Vector3d>& v);
  /// Sets the rim's velocity and spin (translation m/s, spin rad/s), e.g. to start rolling; the
  /// change of its kinetic energy is booked as external work after the first step.
  void SetRimMotion(double vx_mps, double vz_mps, double spin_rad_per_s);
  /// Adds translational mass to the rim (a quarter car for braking), kg; its spin inertia stays.
  /// The added mass's kinetic energy at the rim's speed is booked as external work.
  void AddRimTranslationalMass(double mass_kg);
  /// Translational mass of the rim with its tied nodes, kg.
  double rim_mass() const { return rim_mass_; }
  /// Changes how the rim's DOFs move (e.g. free spin for rolling).
  void SetRimModes(RimDofMode x_mode, RimDofMode z_mode, RimDofMode spin_mode);
  /// Threads of the element and node loops; 0 (the default) is OpenMP's default
  /// (omp_get_max_threads(): all cores unless OMP_NUM_THREADS says otherwise), capped at one
  /// thread per kElementsPerThread elements (small meshes run serially).
  void set_threads(int threads);
  static constexpr int kElementsPerThread = 1000;
  /// The thread count the loops use.
  int threads() const;
  void set_assembly(Assembly assembly) { assembly_ = assembly; }
  /// The element loop's instruction set (default DefaultElementKernel()). Throws InputError if
  /// this machine does not support it. The two give the same results to round-off, not bit for
  /// bit (fused multiply-adds round once).
  void set_element_kernel(ElementKernel kernel);
  ElementKernel element_kernel() const { return kernel_; }
  Assembly assembly() const { return assembly_; }
  /// Number of element colours (no two elements of a colour share a node).
  int colours() const { return static_cast<int>(colour_start_.size()) - 1; }
  /// The elements of colour c, ascending.
  std::vector<int> ColourElements(int c) const {
    return {colour_elements_.begin() + colour_start_.at(c),
            colour_elements_.begin() + colour_start_.at(c + 1)};
  }

  /// Writes everything that changes while the solver runs (time, step count, nodal positions,
  /// velocities and last forces, rim, road, stick anchors, loads, energy accumulators) so that
  /// LoadState on a solver built from the same mesh, materials and options continues bit for bit.
  void SaveState(BinaryWriter& out) const;
  /// Reads what SaveState wrote. Throws InputError (via the reader) if it does not fit this
  /// solver (array sizes, time step).
  void LoadState(BinaryReader& in);

  /// Mass-proportional damping, 1/s (quasi-static steps on, dynamic steps off).
  void set_mass_damping(double alpha_per_s) { options_.mass_damping_per_s = alpha_per_s; }

  /// Moves the nodes (a restart, or a test's chosen configuration), m.
  void SetPositions(const std::vector<Eigen::Vector3d>& x) { x_ = x; }
  /// Forces of the elements (rubber, cords, hourglass, bulk viscosity) on each node at the
  /// current positions and velocities, N. Does not advance the state.
  std::vector<Eigen::Vector3d> CalcElementForces();

  void set_pressure(double pressure_Pa) { pressure_Pa_ = pressure_Pa; }
  /// Nodal forces held constant until changed, N.
  std::vector<Eigen::Vector3d>& applied_forces() { return applied_; }
  RimLoads& rim_loads() { return rim_loads_; }
  /// Velocity of the prescribed rim DOFs (translation m/s, spin rad/s).
  void SetRimVelocity(double vx_mps, double vz_mps, double spin_rad_per_s);

  /// One central-difference step. Throws NumericalError on an inverted element or non-finite
  /// state.
  void Step();

  double time() const { return time_; }
  long steps() const { return steps_; }
  double time_step() const { return dt_; }
  const MassScalingReport& mass_scaling() const { return mass_report_; }
  const Energies& energies() const { return energies_; }
  const Mesh& mesh() const { return mesh_; }
  const std::vector<Eigen::Vector3d>& positions() const { return x_; }
  /// Lumped nodal masses (with cords and mass scaling), kg.
  const std::vector<double>& node_masses() const { return mass_; }
  /// Velocities at the last half step, m/s.
  const std::vector<Eigen::Vector3d>& velocities() const { return v_; }
  /// Reaction forces at prescribed dofs from the last step (zero elsewhere), N.
  const std::vector<Eigen::Vector3d>& reactions() const { return reaction_; }
  /// Road contact normal force per node from the last step (z), N.
  const std::vector<double>& contact_forces() const { return contact_normal_; }
  /// Extension x_t - anchor of each node's stick spring (tangential x, y) after the last step's
  /// return mapping, m; zero for a node off the road (road_contact.h, StickModel::kElasticSpring).
  const std::vector<Eigen::Vector2d>& stick_extensions() const { return stick_extension_; }
  /// Tangential stiffness k_t of each node's stick spring, N/m.
  const std::vector<double>& stick_stiffness() const { return stick_stiffness_; }
  /// Sum of the road's force on the tyre from the last step (friction x, y; normal z), N.
  Eigen::Vector3d RoadForce() const;
  const RimState& rim_state() const { return rim_; }
  /// Reaction loads of the prescribed rim DOFs from the last step.
  const RimLoads& rim_reactions() const { return rim_reaction_; }
  /// Cauchy stress of element `e` at the current positions (rubber plus cords), Pa.
  Eigen::Matrix3d ElementStress(int e) const;
  /// Number of element updates done so far (elements times steps).
  double element_updates() const { return double(steps_) * mesh_.elements.size(); }
  /// The stable step of the current (reference) mesh before the safety factor, s.
  double StableStepEstimate() const { return stable_step_; }
  /// The largest Green-Lagrange strain of any cord now (0 without cords or if none is
  /// stretched). The stable step counts a cord's stiffness at kCordStrainAllowance; the safety
  /// factor covers a cord-dominated element to about 11%.
  double MaxCordStrain() const;

 private:
  // Per-node sums of a step: work terms back (0-4) and ahead (5-9), kinetic, contact energy
  // (normal and stick springs), friction dissipated by the anchors' moves over the last interval.
  static constexpr int kKineticSum = 10, kContactSum = 11, kSlipSum = 12;
  using NodeSums = std::array<double, 13>;
  // Per-thread force buffers beyond this count are not used (node_thread_mask_ is 64 bits).
  static constexpr int kMaxBuffers = 64;

  /// Forces at the current state; with `advance`, also one central-difference step.
  void RunStep(bool advance);
  /// Node a's external, damping and contact forces (and the sum of the thread buffers if
  /// `buffers` > 0, which zeroes their entries for the next step); with `advance`, its new velocity
  /// and position and its energy terms.
  void NodeUpdate(long a, int buffers, const Eigen::Vector3d& road_velocity, bool advance,
                  NodeSums& sum);
  /// Node a's work terms f . v(n-1/2) and f . v(n+1/2).
  void AddWorkTerms(long a, NodeSums& sum) const;
  void AdvanceRim();
  /// Sizes the per-thread force buffers (zeroed) and node_thread_mask_ for `buffers` buffers.
  void PrepareThreadBuffers(int buffers);
  /// Elements [first, last) of buffer t out of `buffers` (contiguous, in order).
  std::pair<long, long> BufferElements(int t, int buffers) const;
  /// Forces of element e added to the three arrays (indexed by node); its strain and hourglass
  /// energies to elem_energy_[e]. False (nothing added) if the element is inverted.
  bool AddElementForces(size_t e, Eigen::Vector3d* f_stored, Eigen::Vector3d* f_bulk,
                        Eigen::Vector3d* f_hourglass);
  /// AddElementForces for elements list[k] (or k if list is null), k in [k0, k1), in order, up
  /// to the first inverted one: returns its index, or -1. Runs the kernel_ variant.
  long AddElementRange(const int* list, long k0, long k1, Eigen::Vector3d* f_stored,
                       Eigen::Vector3d* f_bulk, Eigen::Vector3d* f_hourglass);
  // The two compilations of the same loop (AddElementForces inlined into each).
  long AddElementRangePortable(const int* list, long k0, long k1, Eigen::Vector3d* f_stored,
                               Eigen::Vector3d* f_bulk, Eigen::Vector3d* f_hourglass);
#if defined(__GNUC__) && defined(__x86_64__)
  __attribute__((target("avx2,fma"))) long AddElementRangeAvx2(const int* list, long k0, long k1,
                                                               Eigen::Vector3d* f_stored,
                                                               Eigen::Vector3d* f_bulk,
                                                               Eigen::Vector3d* f_hourglass);
#endif

  Mesh mesh_;
  std::vector<YeohMaterial> materials_;
  std::vector<RebarMaterial> rebars_;
  SolverOptions options_;
  RoadContact road_;
  bool has_rim_ = false;
  RimSettings rim_settings_;
  RimState rim_;
  RimLoads rim_loads_, rim_reaction_;
  Eigen::Vector3d rim_target_ = Eigen::Vector3d::Zero();  // prescribed vx, vz, spin
  double rim_mass_ = 0.0, rim_inertia_ = 0.0;
  std::vector<Eigen::Vector3d> rim_offsets_;  // reference X - centre of each rim node
  std::vector<char> is_rim_node_;

  std::vector<Hex8Reference> refs_;
  std::vector<double> elem_density_;     // with cords and mass scaling, kg/m^3
  std::vector<double> elem_wave_speed_;  // c_d with the cords, m/s
  std::vector<double> hg_stiffness_, hg_viscous_;
  bool viscous_hourglass_ = false;  // any hg_viscous_ > 0
  std::vector<int> fibre_start_;    // CSR over fibres_sorted_
  std::vector<FibreLayer> fibres_sorted_;
  std::vector<double> mass_;
  std::vector<double> contact_stiffness_;
  std::vector<double> stick_stiffness_;  // k_t of each node's stick spring, N/m
  // The stick springs: the extension x_t - anchor of each node in contact (the anchor moves with
  // the road), and whether the node was on the road at the last step (its anchor is set).
  std::vector<Eigen::Vector2d> stick_extension_;
  std::vector<char> on_road_;

  // Parallel loops.
  int threads_ = 0;
  Assembly assembly_ = Assembly::kThreadBuffers;
  ElementKernel kernel_ = ElementKernel::kPortable;
  std::vector<int> colour_start_;                            // CSR over colour_elements_
  std::vector<int> colour_elements_;                         // ascending within a colour
  std::vector<std::array<double, 2>> elem_energy_;           // strain, hourglass of each element
  std::vector<std::vector<Eigen::Vector3d>> thread_forces_;  // kThreadBuffers: 3 per thread
  // kThreadBuffers: bit t of node_thread_mask_[a] is set if buffer t's elements touch node a
  // (for buffer_count_ buffers); only those entries are read, summed and zeroed.
  std::vector<std::uint64_t> node_thread_mask_;
  int buffer_count_ = 0;
  std::vector<int> node_face_start_, node_faces_;  // pressure faces of each node (CSR)
  std::vector<char> is_contact_node_;
  std::vector<Eigen::Vector3d> face_force_;       // a quarter of each face's pressure force
  std::vector<NodeSums> node_sums_;               // per block of nodes
  std::vector<std::array<double, 2>> elem_sums_;  // per block of elements

  std::vector<Eigen::Vector3d> X_, x_, v_, v_old_, applied_, reaction_;
  std::vector<std::array<char, 3>> fixed_;
  std::vector<Eigen::Vector3d> fixed_velocity_;
  // Forces by kind at the current step.
  std::vector<Eigen::Vector3d> f_stored_, f_dissip_bv_, f_dissip_hg_, f_damp_, f_contact_,
      f_friction_, f_external_;
  std::vector<double> contact_normal_;

  double pressure_Pa_ = 0.0;
  double dt_ = 0.0, stable_step_ = 0.0, time_ = 0.0;
  long steps_ = 0;
  MassScalingReport mass_report_;
  Energies energies_;
  double stored_internal_ = 0.0, stored_hg_ = 0.0, stored_contact_ = 0.0;
  // External, bulk viscosity, hourglass, damping, friction (relative to the road; the road's own
  // work on the friction forces is external).
  std::array<double, 5> work_to_midstep_{};
  double slip_dissipation_ = 0.0;  // friction dissipated by the anchors' moves, J
};

}  // namespace hotlap::fe
