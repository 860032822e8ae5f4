#include "hotlap/fe/explicit_step.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <string>
#include <utility>

#include <Eigen/Geometry>

#include "hotlap/common/error.h"

#ifdef _OPENMP
#include <omp.h>
#endif

namespace hotlap::fe {

namespace {

using NodeSums = ExplicitWorkspace::NodeSums;
constexpr int kKineticSum = ExplicitWorkspace::kKineticSum;
constexpr int kContactSum = ExplicitWorkspace::kContactSum;
constexpr int kSlipSum = ExplicitWorkspace::kSlipSum;

// Sums over nodes and elements are taken over blocks of this many terms (each block in order,
// then the blocks in order), so that they do not depend on the thread count.
constexpr long kSumBlock = 512;
// Per-thread force buffers beyond this count are not used (node_thread_mask is 64 bits).
constexpr int kMaxBuffers = 64;

Eigen::Vector3d Vec3Zero() { return Eigen::Vector3d::Zero(); }

long Blocks(size_t n) { return (static_cast<long>(n) + kSumBlock - 1) / kSumBlock; }

Eigen::Matrix3d RotationY(double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  Eigen::Matrix3d r;
  r << c, 0, s, 0, 1, 0, -s, 0, c;
  return r;
}

// What a step's loops need: the counts, the thread count and how the elements are assembled.
struct StepPlan {
  long nn = 0, ne = 0, nf = 0, node_blocks = 0, elem_blocks = 0;
  int nt = 1;
  bool coloured = false, direct = false;
  int buffers = 0;
};

// One step (or, without `advance`, the forces at the current state) of a model's state.
class Stepper {
 public:
  Stepper(const ExplicitModel& model, const StepOptions& options, ExplicitState& state,
          ExplicitWorkspace& workspace)
      : m_(model), o_(options), s_(state), w_(workspace), dt_(model.time_step_s) {}

  void Run(bool advance);

 private:
  // Counts, threads and assembly of this step; sizes the workspace.
  StepPlan MakePlan();
  // The loops of the step's parallel region (each a worksharing part of it).
  void FaceForces(const StepPlan& plan);
  void ElementForces(const StepPlan& plan, long& bad);
  void NodeLoop(const StepPlan& plan, bool advance);
  [[noreturn]] void ThrowInverted(long bad);
  // The energies stored, summed over the blocks in order; the node sums' total.
  NodeSums SumBlocks();
  // The work, kinetic and stored energies of the step (explicit_state.h), and the clock.
  void BookEnergies(const NodeSums& total, const Eigen::Vector3d& rim_v_old, double rim_w_old);
  // Node a's external, damping and contact forces (and the sum of the thread buffers if
  // `buffers` > 0, which zeroes their entries for the next step); with `advance`, its new
  // velocity and position and its energy terms.
  void NodeUpdate(long a, int buffers, const Eigen::Vector3d& road_velocity, bool advance,
                  NodeSums& sum);
  // Node a's work terms f . v(n-1/2) and f . v(n+1/2).
  void AddWorkTerms(long a, NodeSums& sum) const;
  void AdvanceRim();
  // Sizes the per-thread force buffers (zeroed) and node_thread_mask for `buffers` buffers.
  void PrepareThreadBuffers(int buffers);
  // Elements [first, last) of buffer t out of `buffers` (contiguous, in order).
  std::pair<long, long> BufferElements(int t, int buffers) const {
    const long ne = static_cast<long>(m_.mesh.elements.size());
    return {ne * t / buffers, ne * (t + 1) / buffers};
  }
  long AddElementRange(const int* list, long k0, long k1, Eigen::Vector3d* f_stored,
                       Eigen::Vector3d* f_bulk, Eigen::Vector3d* f_hourglass) {
    const internal::ElementLoopData data =
        internal::MakeElementLoopData(m_, s_.x.data(), s_.v.data(), w_.elem_energy.data());
    return internal::AddElementRange(o_.kernel, data, list, k0, k1, f_stored, f_bulk, f_hourglass);
  }
  bool TiedToRim(long a) const { return s_.rim_settings && m_.is_rim_node[a]; }

  const ExplicitModel& m_;
  const StepOptions& o_;
  ExplicitState& s_;
  ExplicitWorkspace& w_;
  const double dt_;
};

void Stepper::PrepareThreadBuffers(int buffers) {
  const size_t nn = s_.x.size();
  w_.thread_forces.assign(3 * static_cast<size_t>(buffers),
                          std::vector<Eigen::Vector3d>(nn, Vec3Zero()));
  w_.node_thread_mask.assign(nn, 0);
  for (int t = 0; t < buffers; ++t) {
    const auto [e0, e1] = BufferElements(t, buffers);
    for (long e = e0; e < e1; ++e) {
      for (int n : m_.mesh.elements[e]) w_.node_thread_mask[n] |= std::uint64_t{1} << t;
    }
  }
  w_.buffer_count = buffers;
}

void Stepper::AdvanceRim() {
  const RimSettings& settings = *s_.rim_settings;
  RimState& rim = s_.rim;
  Eigen::Vector3d force(s_.rim_loads.force_x_N, 0.0, s_.rim_loads.force_z_N);
  double torque = s_.rim_loads.torque_Nm;
  const std::vector<int>& nodes = m_.mesh.rim_nodes;
  const size_t n_rim = nodes.size();
  const size_t first =
      n_rim > 0 ? static_cast<size_t>(std::max(0, o_.rim_sum_rotation)) % n_rim : 0;
  for (size_t k = 0; k < n_rim; ++k) {
    const int a = nodes[(first + k) % n_rim];
    const Eigen::Vector3d f = s_.f_stored[a] + s_.f_dissip_bv[a] + s_.f_dissip_hg[a] +
                              s_.f_damp[a] + s_.f_contact[a] + s_.f_friction[a] + s_.f_external[a];
    const Eigen::Vector3d r = s_.x[a] - rim.centre;
    force += f;
    torque += r.z() * f.x() - r.x() * f.z();
  }
  s_.rim_reaction = RimLoads{};
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
  advance(settings.x_mode, rim.velocity.x(), s_.rim_target(0), force.x(), s_.rim_mass_kg,
          s_.rim_reaction.force_x_N);
  advance(settings.z_mode, rim.velocity.z(), s_.rim_target(1), force.z(), s_.rim_mass_kg,
          s_.rim_reaction.force_z_N);
  advance(settings.spin_mode, rim.spin_rad_per_s, s_.rim_target(2), torque, s_.rim_inertia_kgm2,
          s_.rim_reaction.torque_Nm);
  rim.centre += dt_ * rim.velocity;
  rim.angle_rad += dt_ * rim.spin_rad_per_s;
  const Eigen::Matrix3d rot = RotationY(rim.angle_rad);
  for (int a : m_.mesh.rim_nodes) {
    // The node's reference offset from the rim's reference centre, turned.
    const Eigen::Vector3d offset = m_.mesh.nodes[a] - settings.centre;
    const Eigen::Vector3d r = rot * offset;
    s_.x[a] = rim.centre + r;
    s_.v[a] = rim.velocity + SpinVelocity(rim.spin_rad_per_s, r);
  }
}

void Stepper::AddWorkTerms(long a, NodeSums& sum) const {
  const Eigen::Vector3d fe = s_.f_external[a] + s_.reaction[a];
  const Eigen::Vector3d* f[5] = {&fe, &s_.f_dissip_bv[a], &s_.f_dissip_hg[a], &s_.f_damp[a],
                                 &s_.f_friction[a]};
  for (int k = 0; k < 5; ++k) {
    sum[k] += f[k]->dot(w_.v_old[a]);
    sum[5 + k] += f[k]->dot(s_.v[a]);
  }
  // A moving road works on the friction force: external work; the friction term is the work
  // relative to the road.
  const double road_power = s_.f_friction[a].x() * s_.road.road_speed_x_mps;
  sum[0] += road_power;
  sum[5] += road_power;
  sum[4] -= road_power;
  sum[9] -= road_power;
}

void Stepper::NodeUpdate(long a, int buffers, const Eigen::Vector3d& road_velocity, bool advance,
                         NodeSums& sum) {
  if (buffers > 0) {
    // Sum the buffers in thread order, reading (and zeroing for the next step) only those whose
    // elements touch this node: the others hold zeros, and at the paper's mesh size the memory
    // traffic of reading and clearing them all is a large part of the step.
    Eigen::Vector3d fs = Vec3Zero(), fb = Vec3Zero(), fh = Vec3Zero();
    for (std::uint64_t mask = w_.node_thread_mask[a]; mask != 0; mask &= mask - 1) {
      const int t = std::countr_zero(mask);
      Eigen::Vector3d& bs = w_.thread_forces[3 * t][a];
      Eigen::Vector3d& bb = w_.thread_forces[3 * t + 1][a];
      fs += bs;
      fb += bb;
      bs.setZero();
      bb.setZero();
      if (m_.viscous_hourglass) {  // else no element adds to the hourglass buffers
        Eigen::Vector3d& bh = w_.thread_forces[3 * t + 2][a];
        fh += bh;
        bh.setZero();
      }
    }
    s_.f_stored[a] = fs;
    s_.f_dissip_bv[a] = fb;
    s_.f_dissip_hg[a] = fh;
  }
  Eigen::Vector3d fe = s_.applied[a];
  if (s_.pressure_Pa != 0.0) {
    for (int k = m_.node_face_start[a]; k < m_.node_face_start[a + 1]; ++k) {
      fe += w_.face_force[m_.node_faces[k]];
    }
  }
  const RoadContact& road = s_.road;
  const double mass = m_.mass[a];
  s_.f_external[a] = fe;
  s_.f_damp[a] = -s_.mass_damping_per_s * mass * s_.v[a];
  s_.f_contact[a].setZero();
  s_.f_friction[a].setZero();
  s_.contact_normal[a] = 0.0;
  // Road: penalty normal force and friction (002:1); road_contact.h.
  if (road.enabled && m_.is_contact_node[a]) {
    const double g = road.height_m - s_.x[a].z();
    const bool on_road = g > 0.0;
    double fn = 0.0;
    if (on_road) {
      const double k = ContactStiffness(m_, s_, a);
      fn = k * g;
      s_.contact_normal[a] = fn;
      s_.f_contact[a].z() = fn;
      sum[kContactSum] += 0.5 * k * g * g;
    }
    const Eigen::Vector3d slip = s_.v[a] - road_velocity;  // v(n-1/2) relative to the road
    if (road.stick == StickModel::kViscous) {
      if (on_road) s_.f_friction[a] = CalcFrictionForce(road.friction, fn, slip, mass / dt_);
    } else if (on_road || s_.on_road[a]) {
      // The stick spring's trial extension x_t(n) - anchor(n-1): the last extension plus the
      // node's move relative to the road over the last step, dt v_slip(n-1/2) (the anchor moves
      // with the road). A node touching down anchors where it crossed the road plane during the
      // last step (linearly; where it is if it was below the plane already, e.g. a road just
      // set); one leaving the road lets go (limit 0).
      const Eigen::Vector2d slip_t(slip.x(), slip.y());
      const bool was_on_road = s_.on_road[a] != 0;
      const Eigen::Vector2d last = was_on_road ? s_.stick_extension[a] : Eigen::Vector2d::Zero();
      const Eigen::Vector2d moved = last + dt_ * slip_t;  // with the anchor carried along
      Eigen::Vector2d trial = moved;
      if (!was_on_road) {
        const double g_last = g + dt_ * s_.v[a].z();  // the penetration a step ago
        trial *= g_last < 0.0 && s_.steps > 0 ? g / (g - g_last) : 0.0;
      }
      const double k = StickStiffness(m_, s_, a);
      const double limit =
          on_road ? CalcFrictionCoefficient(road.friction, slip_t.norm()) * fn : 0.0;
      Eigen::Vector2d ext = trial;
      const Eigen::Vector2d f = ReturnMapFriction(k, limit, ext);
      s_.f_friction[a] = Eigen::Vector3d(f.x(), f.y(), 0.0);
      sum[kContactSum] += 0.5 * k * ext.squaredNorm();
      if (advance) {
        // Dissipated over [t(n-1), t(n)]: (f(n-1) + f(n)) / 2 against the anchor's move relative
        // to the road, moved - ext (zero in stick; before touch-down the anchor is taken as
        // carried with the node, f(n-1) being zero); with the spring energy this closes the
        // node's friction work exactly (explicit_state.h, Energies).
        sum[kSlipSum] += 0.5 * k * (last + ext).dot(moved - ext);
        s_.stick_extension[a] = ext;
        s_.on_road[a] = on_road;
      }
    }
  }
  if (!advance) return;
  w_.v_old[a] = s_.v[a];
  s_.reaction[a].setZero();
  if (TiedToRim(a)) return;  // moved with the rim, after the node loop
  const Eigen::Vector3d f = s_.f_stored[a] + s_.f_dissip_bv[a] + s_.f_dissip_hg[a] + s_.f_damp[a] +
                            s_.f_contact[a] + s_.f_friction[a] + s_.f_external[a];
  for (int d = 0; d < 3; ++d) {
    if (s_.fixed[a][d]) {
      s_.v[a](d) = s_.fixed_velocity[a](d);
      s_.reaction[a](d) = mass * (s_.v[a](d) - w_.v_old[a](d)) / dt_ - f(d);
    } else {
      s_.v[a](d) += dt_ * f(d) / mass;
    }
  }
  s_.x[a] += dt_ * s_.v[a];
  AddWorkTerms(a, sum);
  sum[kKineticSum] += 0.5 * mass * w_.v_old[a].dot(s_.v[a]);
}

StepPlan Stepper::MakePlan() {
  StepPlan plan;
  plan.nn = static_cast<long>(s_.x.size());
  plan.ne = static_cast<long>(m_.mesh.elements.size());
  plan.nf = static_cast<long>(m_.mesh.pressure_faces.size());
  plan.nt = ResolveThreads(o_, m_);
  plan.coloured = o_.assembly == Assembly::kColoured;
  // Per-thread buffers on one thread: the elements add straight to the nodes, in element order
  // (the same bits as one buffer).
  plan.direct = !plan.coloured && plan.nt == 1;
  plan.buffers = plan.coloured || plan.direct ? 0 : std::min(plan.nt, kMaxBuffers);
  if (plan.buffers > 0 && plan.buffers != w_.buffer_count) PrepareThreadBuffers(plan.buffers);
  plan.node_blocks = Blocks(plan.nn);
  plan.elem_blocks = Blocks(plan.ne);
  w_.node_sums.resize(plan.node_blocks);
  w_.elem_sums.resize(plan.elem_blocks);
  w_.face_force.resize(plan.nf);
  w_.elem_energy.resize(plan.ne);
  w_.v_old.resize(plan.nn);
  return plan;
}

void Stepper::FaceForces(const StepPlan& plan) {
  // Inflation pressure: a follower load on each face, a quarter of p times the area vector on
  // each of its nodes, pushing into the solid (gathered per node in the node loop).
  const double p = s_.pressure_Pa;
#pragma omp for schedule(static) nowait
  for (long k = 0; k < plan.nf; ++k) {
    const auto& face = m_.mesh.pressure_faces[k];
    const std::vector<Eigen::Vector3d>& x = s_.x;
    w_.face_force[k] = -0.125 * p * (x[face[2]] - x[face[0]]).cross(x[face[3]] - x[face[1]]);
  }
}

void Stepper::ElementForces(const StepPlan& plan, long& bad) {
#ifdef _OPENMP
  const int team = omp_get_num_threads(), rank = omp_get_thread_num();
#else
  const int team = 1, rank = 0;
#endif
  const long ne = plan.ne;
  if (plan.coloured || plan.direct) {
#pragma omp for schedule(static)
    for (long a = 0; a < plan.nn; ++a) {
      s_.f_stored[a].setZero();
      s_.f_dissip_bv[a].setZero();
      s_.f_dissip_hg[a].setZero();
    }
    // Elements of one colour share no node: they add to the nodes without a race. Each thread
    // takes a contiguous share of each colour (as schedule(static)); the barrier after each
    // colour separates the colours.
    const bool direct = plan.direct;
    const int n_loops = direct ? 1 : m_.colours();
    for (int c = 0; c < n_loops; ++c) {
      const long k0 = direct ? 0 : m_.colour_start[c], k1 = direct ? ne : m_.colour_start[c + 1];
      const long n = k1 - k0;
      // The lowest inverted element of this share (a colour lists its elements ascending).
      const long e =
          AddElementRange(direct ? nullptr : m_.colour_elements.data(), k0 + n * rank / team,
                          k0 + n * (rank + 1) / team, s_.f_stored.data(), s_.f_dissip_bv.data(),
                          s_.f_dissip_hg.data());
      if (e >= 0) {
#pragma omp critical(hotlap_fe_inverted)
        bad = std::min(bad, e);
      }
#pragma omp barrier
    }
  } else {
    // The buffers are zero here (the node loop zeroes what it sums). Buffer t takes a fixed
    // range of elements, so node_thread_mask holds; a smaller team than asked for takes
    // several buffers per thread.
    for (int t = rank; t < plan.buffers; t += team) {
      Eigen::Vector3d* fs = w_.thread_forces[3 * t].data();
      Eigen::Vector3d* fb = w_.thread_forces[3 * t + 1].data();
      Eigen::Vector3d* fh = w_.thread_forces[3 * t + 2].data();
      const auto [e0, e1] = BufferElements(t, plan.buffers);
      const long e = AddElementRange(nullptr, e0, e1, fs, fb, fh);
      if (e >= 0) {
#pragma omp critical(hotlap_fe_inverted)
        bad = std::min(bad, e);
      }
    }
#pragma omp barrier
  }
}

void Stepper::NodeLoop(const StepPlan& plan, bool advance) {
  const Eigen::Vector3d road_velocity(s_.road.road_speed_x_mps, 0.0, 0.0);
  const long ne = plan.ne, nn = plan.nn;
#pragma omp for schedule(static) nowait
  for (long b = 0; b < plan.elem_blocks; ++b) {
    std::array<double, 2> sum{0.0, 0.0};
    for (long e = b * kSumBlock; e < std::min(ne, (b + 1) * kSumBlock); ++e) {
      sum[0] += w_.elem_energy[e][0];
      sum[1] += w_.elem_energy[e][1];
    }
    w_.elem_sums[b] = sum;
  }
#pragma omp for schedule(static)
  for (long b = 0; b < plan.node_blocks; ++b) {
    NodeSums sum{};
    for (long a = b * kSumBlock; a < std::min(nn, (b + 1) * kSumBlock); ++a) {
      NodeUpdate(a, plan.buffers, road_velocity, advance, sum);
    }
    w_.node_sums[b] = sum;
  }
}

void Stepper::ThrowInverted(long bad) {
  // The node loop did not run: zero the buffers for a later step.
  for (auto& buffer : w_.thread_forces) std::fill(buffer.begin(), buffer.end(), Vec3Zero());
  Eigen::Matrix3d F = Eigen::Matrix3d::Zero();
  for (int a = 0; a < 8; ++a) {
    F.noalias() += s_.x[m_.mesh.elements[bad][a]] * m_.refs[bad].grad.row(a);
  }
  throw NumericalError("fe: element " + std::to_string(bad) +
                       " inverted (J = " + std::to_string(F.determinant()) +
                       ") at t = " + std::to_string(s_.time_s) + " s");
}

NodeSums Stepper::SumBlocks() {
  // Sums in block order: the same for every thread count.
  s_.stored_internal = s_.stored_hourglass = s_.stored_contact = 0.0;
  for (const auto& b : w_.elem_sums) {
    s_.stored_internal += b[0];
    s_.stored_hourglass += b[1];
  }
  NodeSums total{};
  for (const NodeSums& b : w_.node_sums) {
    for (size_t k = 0; k < total.size(); ++k) total[k] += b[k];
  }
  s_.stored_contact = total[kContactSum];
  return total;
}

void Stepper::Run(bool advance) {
  CheckElementKernelSupported(o_.kernel);
  const StepPlan plan = MakePlan();
  long bad = plan.ne;  // the lowest inverted element, if any

  // One parallel region per step. Its synchronisation points: the end of the element loop
  // (every colour's loop with the coloured assembly) and the end of the node loop; few, because
  // on a loaded machine each one can cost a scheduler time slice.
#pragma omp parallel num_threads(plan.nt)
  {
    if (s_.pressure_Pa != 0.0) FaceForces(plan);
    ElementForces(plan, bad);
    // Past the barrier: every element and face force is known, and so is `bad`.
    if (bad == plan.ne) NodeLoop(plan, advance);
  }
  if (bad < plan.ne) ThrowInverted(bad);
  NodeSums total = SumBlocks();
  if (!advance) return;

  // The rim: its applied loads and constraint reactions do work at its mean velocity.
  RimState& rim = s_.rim;
  const Eigen::Vector3d rim_v_old = rim.velocity;
  const double rim_w_old = rim.spin_rad_per_s;
  if (s_.rim_settings) {
    AdvanceRim();
    // The rim nodes' force terms, now that their new velocities are known.
    for (int a : m_.mesh.rim_nodes) AddWorkTerms(a, total);
  }
  BookEnergies(total, rim_v_old, rim_w_old);
}

void Stepper::BookEnergies(const NodeSums& total, const Eigen::Vector3d& rim_v_old,
                           double rim_w_old) {
  const RimState& rim = s_.rim;
  // Energy accounting. The work of f(n) is f(n) . (x(n+1) - x(n-1)) / 2 (trapezoidal in the
  // forces), of which the second half lies beyond t(n) and is held back from the energies
  // reported at t(n); the kinetic energy at t(n) is m v(n-1/2) . v(n+1/2) / 2. For a linear
  // system this balance is exact under central differences; with the mean velocity squared, or
  // with the look-ahead half counted, it is off by terms of order omega dt, large for the
  // highest modes.
  // Work terms (AddWorkTerms): external (with reactions), bulk viscosity, viscous hourglass,
  // damping, friction; each as the sum of f . v(n-1/2) ("back") and of f . v(n+1/2) ("ahead").
  const bool first = s_.steps == 0;
  std::array<double, 5> back{}, ahead{};
  for (int k = 0; k < 5; ++k) {
    back[k] = first ? 0.0 : total[k];
    ahead[k] = total[5 + k];
  }
  double ke = total[kKineticSum];
  if (s_.rim_settings) {
    const RimLoads& loads = s_.rim_loads;
    const RimLoads& reaction = s_.rim_reaction;
    const Eigen::Vector3d f(loads.force_x_N + reaction.force_x_N,
                            loads.torque_Nm + reaction.torque_Nm,
                            loads.force_z_N + reaction.force_z_N);
    const Eigen::Vector3d vo(rim_v_old.x(), rim_w_old, rim_v_old.z());
    const Eigen::Vector3d vn(rim.velocity.x(), rim.spin_rad_per_s, rim.velocity.z());
    if (!first) back[0] += f.dot(vo);
    ahead[0] += f.dot(vn);
    ke += 0.5 * s_.rim_mass_kg * rim_v_old.dot(rim.velocity) +
          0.5 * s_.rim_inertia_kgm2 * rim_w_old * rim.spin_rad_per_s;
  }
  Energies& energies = s_.energies;
  if (first) energies.initial_kinetic = ke;
  std::array<double, 5> now{};
  for (int k = 0; k < 5; ++k) {
    s_.work_to_midstep[k] += 0.5 * dt_ * (back[k] + ahead[k]);
    now[k] = s_.work_to_midstep[k] - 0.5 * dt_ * ahead[k];
  }
  energies.external_work = now[0];
  energies.bulk_viscous = -now[1];
  energies.hourglass_dissipated = -now[2];
  energies.damping = -now[3];
  s_.slip_dissipation += total[kSlipSum];
  energies.friction = s_.road.stick == StickModel::kViscous ? -now[4] : s_.slip_dissipation;
  energies.kinetic = ke;
  energies.internal = s_.stored_internal;
  energies.hourglass_stored = s_.stored_hourglass;
  energies.contact_stored = s_.stored_contact;
  if (!std::isfinite(ke) || !std::isfinite(s_.stored_internal)) {
    throw NumericalError("fe: non-finite energy at t = " + std::to_string(s_.time_s) + " s");
  }
  s_.time_s += dt_;
  ++s_.steps;
}

}  // namespace

int DefaultThreadCount() {
#ifdef _OPENMP
  return omp_get_max_threads();
#else
  return 1;
#endif
}

int ResolveThreads(const StepOptions& options, const ExplicitModel& model) {
  if (options.threads > 0) return options.threads;
  // The default: all cores, but no more threads than the mesh keeps busy (a thread per
  // kElementsPerThread elements), since each step synchronises the threads twice.
  const int useful = static_cast<int>(model.mesh.elements.size() / StepOptions::kElementsPerThread);
  return std::max(1, std::min(DefaultThreadCount(), useful));
}

void AdvanceExplicit(const ExplicitModel& model, const StepOptions& options, ExplicitState& state,
                     ExplicitWorkspace& workspace) {
  Stepper(model, options, state, workspace).Run(/*advance=*/true);
}

std::vector<Eigen::Vector3d> CalcElementForces(const ExplicitModel& model,
                                               const StepOptions& options, ExplicitState& state,
                                               ExplicitWorkspace& workspace) {
  Stepper(model, options, state, workspace).Run(/*advance=*/false);
  std::vector<Eigen::Vector3d> f(state.x.size());
  for (size_t a = 0; a < f.size(); ++a) {
    f[a] = state.f_stored[a] + state.f_dissip_bv[a] + state.f_dissip_hg[a];
  }
  return f;
}

Eigen::Vector3d CalcRoadForce(const ExplicitModel& model, const ExplicitState& state) {
  Eigen::Vector3d f = Eigen::Vector3d::Zero();
  for (int a : model.mesh.contact_nodes) f += state.f_contact[a] + state.f_friction[a];
  return f;
}

}  // namespace hotlap::fe
