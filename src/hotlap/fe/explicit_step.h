#pragma once
/// @file
/// One explicit time step: a function of the model (explicit_model.h), the step options and the
/// state (explicit_state.h), with a workspace of scratch buffers that carries nothing from one
/// step to the next but its allocations.
///
///   fe::StepOptions options;             // threads, assembly, element kernel
///   fe::ExplicitWorkspace workspace;
///   while (state.time_s < t_end) fe::AdvanceExplicit(model, options, state, workspace);
///
/// Central difference (velocities at half steps, positions at whole steps):
///   v(n+1/2) = v(n-1/2) + dt M^-1 f(x(n), v(n-1/2)),  x(n+1) = x(n) + dt v(n+1/2).
/// Velocity-dependent forces (bulk viscosity, viscous hourglass, damping, friction) use v(n-1/2).
/// The step is the model's (explicit_model.h explains the stable step); the energies are booked
/// as explicit_state.h says.
///
/// Threads (OpenMP): the element loop (rubber, cords, hourglass, bulk viscosity), the pressure
/// faces and the node loop (contact, friction, damping, the update, the energy sums) run on
/// StepOptions::threads threads in one parallel region per step; the rim is serial. Two
/// assemblies: Assembly::kThreadBuffers (the default, the faster one: docs/fe-tyre.md) gives each
/// thread a contiguous range of elements and its own force buffer, summed per node in thread
/// order: deterministic for a given thread count, and equal to the serial (one-thread) result to
/// round-off. Assembly::kColoured splits the elements into colours whose elements share no node;
/// each colour runs in parallel and adds straight to the nodes: the same bits for every thread
/// count, but slower (a barrier per colour, and each colour sweeps the whole mesh). Every sum
/// (energies) is taken over fixed blocks in a fixed order, so it does not depend on the thread
/// count.

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "hotlap/fe/element_kernel.h"
#include "hotlap/fe/explicit_model.h"
#include "hotlap/fe/explicit_state.h"

namespace hotlap::fe {

/// How the parallel element loop adds element forces to the nodes (see the file comment).
enum class Assembly : std::uint8_t {
  kThreadBuffers,  ///< a force buffer per thread, summed after the loop in thread order (default)
  kColoured,       ///< colours of elements that share no node; independent of the thread count
};

/// OpenMP's default thread count (omp_get_max_threads(): the cores, or OMP_NUM_THREADS).
int DefaultThreadCount();

/// How a step runs; none of it changes the physics (the kernel and the thread count with
/// per-thread buffers change the last bits).
struct StepOptions {
  /// Threads of the element and node loops; 0 is OpenMP's default (DefaultThreadCount()),
  /// capped at one thread per kElementsPerThread elements (small meshes run serially).
  int threads = 0;
  Assembly assembly = Assembly::kThreadBuffers;
  /// The element loop's instruction set; the two give the same results to round-off, not bit
  /// for bit (fused multiply-adds round once).
  ElementKernel kernel = BestElementKernel();
  /// The rim's force and torque are summed over its nodes starting at this index of
  /// mesh.rim_nodes (modulo their count) and wrapping round: another summation order, the same
  /// sum to round-off (an ensemble's perturbation, abs/fe_perturbation.h; 0 is the plain order).
  int rim_sum_rotation = 0;

  static constexpr int kElementsPerThread = 1000;
};

/// The thread count the loops use for `model` (StepOptions::threads, or the default).
int ResolveThreads(const StepOptions& options, const ExplicitModel& model);

/// Scratch of a step (force buffers per thread, per-element energies, partial sums); reused from
/// step to step, never read before written within a step. Not part of the state.
struct ExplicitWorkspace {
  /// Per-node sums of a step: work terms back (0-4) and ahead (5-9), kinetic, contact energy
  /// (normal and stick springs), friction dissipated by the anchors' moves over the last interval.
  static constexpr int kKineticSum = 10, kContactSum = 11, kSlipSum = 12;
  using NodeSums = std::array<double, 13>;

  std::vector<Eigen::Vector3d> v_old;                       ///< v(n-1/2) during the update
  std::vector<std::array<double, 2>> elem_energy;           ///< strain, hourglass per element
  std::vector<std::vector<Eigen::Vector3d>> thread_forces;  ///< kThreadBuffers: 3 per thread
  /// kThreadBuffers: bit t is set if buffer t's elements touch the node (for buffer_count
  /// buffers); only those entries are read, summed and zeroed.
  std::vector<std::uint64_t> node_thread_mask;
  int buffer_count = 0;
  std::vector<Eigen::Vector3d> face_force;       ///< a quarter of each face's pressure force
  std::vector<NodeSums> node_sums;               ///< per block of nodes
  std::vector<std::array<double, 2>> elem_sums;  ///< per block of elements
};

/// One central-difference step of `state`. Throws NumericalError on an inverted element or a
/// non-finite state (the state is then partly advanced), InputError if this machine cannot run
/// options.kernel.
void AdvanceExplicit(const ExplicitModel& model, const StepOptions& options, ExplicitState& state,
                     ExplicitWorkspace& workspace);

/// Forces of the elements (rubber, cords, hourglass, bulk viscosity) on each node at the state's
/// positions and velocities, N. Does not advance the state; sets its last forces and stored
/// energies to those of the current positions.
std::vector<Eigen::Vector3d> CalcElementForces(const ExplicitModel& model,
                                               const StepOptions& options, ExplicitState& state,
                                               ExplicitWorkspace& workspace);

/// Sum of the road's force on the tyre from the last step (friction x, y; normal z), N.
Eigen::Vector3d CalcRoadForce(const ExplicitModel& model, const ExplicitState& state);

/// Normal penalty stiffness of node `a` on the state's road, k = penalty_factor m / dt^2, N/m,
/// with dt the unscaled step (ExplicitModel::contact_step_s; the step itself at scale 1).
inline double ContactStiffness(const ExplicitModel& model, const ExplicitState& state, size_t a) {
  return state.road.penalty_factor * model.mass[a] / (model.contact_step_s * model.contact_step_s);
}
/// Tangential stiffness of node `a`'s stick spring, k_t = tangential_penalty_factor m / dt^2, N/m,
/// dt as ContactStiffness's.
inline double StickStiffness(const ExplicitModel& model, const ExplicitState& state, size_t a) {
  return state.road.tangential_penalty_factor * model.mass[a] /
         (model.contact_step_s * model.contact_step_s);
}

}  // namespace hotlap::fe
