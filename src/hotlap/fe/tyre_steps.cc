#include "hotlap/fe/tyre_steps.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <Eigen/Geometry>

#include "hotlap/common/error.h"
#include "hotlap/fe/field_io.h"

namespace hotlap::fe {

namespace {

constexpr double kGravity = 9.80665;
// Brake torque opposes the spin; below this spin it is scaled down smoothly (tanh) so that a
// locked wheel is held without chatter, rad/s.
constexpr double kBrakeSpinRegularisation = 0.5;

SolverOptions InitialOptions(const FeConfig& c) {
  SolverOptions o = c.solver;
  o.mass_damping_per_s = c.inflate.damping_per_s;
  return o;
}

}  // namespace

TyreRun::TyreRun(const FeConfig& config)
    : config_(config),
      tyre_(MakeTyreMesh(config.size, config.mesh, config.cords)),
      solver_(tyre_.mesh, config.rubber, config.cords, InitialOptions(config)) {
  RimSettings rim;
  rim.mass_kg = config.rim_mass_kg;
  rim.inertia_kgm2 = config.rim_inertia_kgm2;
  rim.x_mode = rim.z_mode = rim.spin_mode = RimDofMode::kPrescribedVelocity;
  solver_.SetRim(rim);
}

double TyreRun::OuterRadiusMean() const {
  double sum = 0.0;
  for (int n : tyre_.crown_centre_nodes) {
    const Eigen::Vector3d r = solver_.positions()[n] - solver_.rim_state().centre;
    sum += std::hypot(r.x(), r.z());
  }
  return sum / tyre_.crown_centre_nodes.size();
}

HistoryRow TyreRun::Row(double torque) const {
  HistoryRow r;
  const RimState& rim = solver_.rim_state();
  r.time_s = solver_.time();
  r.rim_x_m = rim.centre.x();
  r.rim_z_m = rim.centre.z();
  r.rim_vx_mps = rim.velocity.x();
  r.spin_rad_per_s = rim.spin_rad_per_s;
  r.brake_torque_Nm = torque;
  const Eigen::Vector3d f = solver_.RoadForce();
  r.road_fx_N = f.x();
  r.road_fz_N = f.z();
  if (std::abs(r.rim_vx_mps) > 0.1 && slip_radius_m() > 0.0) {
    r.slip = (r.rim_vx_mps - slip_radius_m() * r.spin_rad_per_s) / r.rim_vx_mps;  // (002:2)
  }
  r.energies = solver_.energies();
  return r;
}

void TyreRun::RunUntil(const std::string& step, double t_end, const StepHooks& hooks,
                       const std::function<void()>& each, std::vector<HistoryRow>& history,
                       const double* torque, bool resume) {
  const double dt = solver_.time_step();
  if (!resume) {
    state_.cursor = StepCursor{};
    state_.cursor.t0 = state_.cursor.next_history = solver_.time();
    history.push_back(Row(torque ? *torque : 0.0));
    state_.cursor.max_cord_strain = solver_.MaxCordStrain();
  }
  const double t0 = state_.cursor.t0;
  const int frames = std::max(1, hooks.frames);
  // Checkpoints at t0 + m * interval (the first one after now), and at the end.
  const double interval = hooks.checkpoint ? hooks.checkpoint_interval_s : 0.0;
  double next_checkpoint = std::numeric_limits<double>::infinity();
  if (interval > 0.0) {
    next_checkpoint = t0 + interval * (std::floor((solver_.time() - t0) / interval + 0.5) + 1.0);
  }
  bool checkpoint_now = false;
  while (solver_.time() < t_end - 0.5 * dt) {
    if (each) each();
    solver_.Step();
    if (solver_.time() >= state_.cursor.next_history + hooks.history_interval_s - 0.5 * dt) {
      state_.cursor.next_history = solver_.time();
      history.push_back(Row(torque ? *torque : 0.0));
      state_.cursor.max_cord_strain =
          std::max(state_.cursor.max_cord_strain, solver_.MaxCordStrain());
    }
    const double frame_time = t0 + (t_end - t0) * (state_.cursor.next_frame + 1) / frames;
    if (state_.cursor.next_frame < frames - 1 && solver_.time() >= frame_time - 0.5 * dt) {
      if (hooks.frame) hooks.frame(step, static_cast<int>(state_.cursor.next_frame));
      ++state_.cursor.next_frame;
    }
    if (hooks.progress && (++state_.cursor.calls % 2000 == 0)) {
      hooks.progress(step, solver_.time(), t_end);
    }
    checkpoint_now = solver_.time() >= next_checkpoint - 0.5 * dt;
    if (checkpoint_now) {
      hooks.checkpoint();
      if (hooks.checkpoint_written) hooks.checkpoint_written(solver_.time());
      while (next_checkpoint < solver_.time() + 0.5 * dt) next_checkpoint += interval;
    }
  }
  if (hooks.frame) hooks.frame(step, frames - 1);
  if (hooks.progress) hooks.progress(step, solver_.time(), t_end);
  if (hooks.checkpoint && !checkpoint_now) {
    hooks.checkpoint();
    if (hooks.checkpoint_written) hooks.checkpoint_written(solver_.time());
  }
}

InflateResult TyreRun::Inflate(const StepHooks& hooks) {
  InflateResult r;
  r.pressure_Pa = config_.inflation_pressure_Pa;
  r.outer_radius_before_m = OuterRadiusMean();
  double w0 = 0.0;
  for (int a = 0; a < tyre_.section_nodes; ++a)
    w0 = std::max(w0, std::abs(tyre_.mesh.nodes[a].y()));
  r.section_width_before_m = 2.0 * w0;
  solver_.set_mass_damping(config_.inflate.damping_per_s);
  const double t0 = solver_.time();
  const double ramp = config_.inflate.ramp_s;
  RunUntil(
      "inflate", t0 + ramp + config_.inflate.hold_s, hooks,
      [&] {
        solver_.set_pressure(config_.inflation_pressure_Pa *
                             std::min(1.0, (solver_.time() - t0) / ramp));
      },
      r.history, nullptr);
  r.max_cord_strain = state_.cursor.max_cord_strain;
  r.outer_radius_after_m = OuterRadiusMean();
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  for (int n : tyre_.crown_centre_nodes) {
    const Eigen::Vector3d& p = solver_.positions()[n];
    lo = std::min(lo, std::hypot(p.x(), p.z()));
    hi = std::max(hi, std::hypot(p.x(), p.z()));
  }
  r.max_roundness_error_m = hi - lo;
  double w1 = 0.0;
  for (int a = 0; a < tyre_.section_nodes; ++a) {
    w1 = std::max(w1, std::abs(solver_.positions()[a].y()));
  }
  r.section_width_after_m = 2.0 * w1;
  state_.inflated_radius_m = r.outer_radius_after_m;
  return r;
}

FootprintResult TyreRun::Footprint(const StepHooks& hooks) {
  if (state_.inflated_radius_m <= 0.0) {
    throw InputError("fe: footprint needs the inflation step first");
  }
  FootprintResult r;
  r.vertical_load_N = config_.vertical_load_N;
  // The road touches the lowest tread node.
  state_.road_z_m = std::numeric_limits<double>::infinity();
  for (int a : tyre_.mesh.contact_nodes) {
    state_.road_z_m = std::min(state_.road_z_m, solver_.positions()[a].z());
  }
  RoadContact road = config_.road;
  road.enabled = true;
  road.height_m = state_.road_z_m;
  solver_.SetRoad(road);
  solver_.SetRimModes(RimDofMode::kPrescribedVelocity, RimDofMode::kFree,
                      RimDofMode::kPrescribedVelocity);
  solver_.SetRimVelocity(0.0, 0.0, 0.0);
  solver_.set_mass_damping(config_.footprint.damping_per_s);
  const double t0 = solver_.time(), ramp = config_.footprint.ramp_s;
  RunUntil(
      "footprint", t0 + ramp + config_.footprint.hold_s, hooks,
      [&] {
        solver_.rim_loads().force_z_N =
            -config_.vertical_load_N * std::min(1.0, (solver_.time() - t0) / ramp);
      },
      r.history, nullptr);
  r.max_cord_strain = state_.cursor.max_cord_strain;
  r.road_force_z_N = solver_.RoadForce().z();
  r.loaded_radius_m = solver_.rim_state().centre.z() - state_.road_z_m;
  state_.loaded_radius_m = r.loaded_radius_m;
  r.deflection_m = state_.inflated_radius_m - r.loaded_radius_m;
  r.vertical_stiffness_N_per_m = r.deflection_m > 0 ? config_.vertical_load_N / r.deflection_m : 0;

  // Each node's share of the outer surface, for the pressure map.
  const auto& x = solver_.positions();
  std::vector<double> area(x.size(), 0.0);
  for (const auto& f : tyre_.outer_faces) {
    const double a = 0.5 * (x[f[2]] - x[f[0]]).cross(x[f[3]] - x[f[1]]).norm();
    for (int n : f) area[n] += 0.25 * a;
  }
  double xmin = 1e9, xmax = -1e9, ymin = 1e9, ymax = -1e9;
  for (int a : tyre_.mesh.contact_nodes) {
    const double f = solver_.contact_forces()[a];
    if (f <= 0.0) continue;
    ContactPoint p{x[a].x() - solver_.rim_state().centre.x(), x[a].y(), f, f / area[a]};
    r.contact.push_back(p);
    r.contact_area_m2 += area[a];
    r.peak_pressure_Pa = std::max(r.peak_pressure_Pa, p.pressure_Pa);
    xmin = std::min(xmin, p.x_m);
    xmax = std::max(xmax, p.x_m);
    ymin = std::min(ymin, p.y_m);
    ymax = std::max(ymax, p.y_m);
  }
  if (!r.contact.empty()) {
    r.contact_length_m = xmax - xmin;
    r.contact_width_m = ymax - ymin;
    r.mean_pressure_Pa = r.road_force_z_N / r.contact_area_m2;
  }
  return r;
}

RollResult TyreRun::Roll(const StepHooks& hooks) {
  if (state_.loaded_radius_m <= 0.0) throw InputError("fe: roll needs the footprint step first");
  RollResult r;
  r.speed_mps = config_.roll_speed_mps;
  solver_.set_mass_damping(0.0);
  solver_.SetRimModes(RimDofMode::kPrescribedVelocity, RimDofMode::kFree, RimDofMode::kFree);
  // Start from rigid rolling about the rim centre at the rule-of-thumb rolling radius
  // R - deflection / 3 (the measured effective radius is within 0.1% of it: docs/fe-tyre.md).
  // Until issue 27 the spin was speed / loaded radius, 4% fast: the belt and rim then had to
  // lose 1.2 rad/s through the contact, which set the rim-tyre torsional modes (20-70 Hz,
  // lightly damped) ringing at 0.5-0.8 rad/s for the whole roll step, into the braking.
  const double rolling_radius =
      state_.inflated_radius_m - (state_.inflated_radius_m - state_.loaded_radius_m) / 3.0;
  const double spin0 = r.speed_mps / rolling_radius;
  const Eigen::Vector3d c = solver_.rim_state().centre;
  std::vector<Eigen::Vector3d> v(solver_.positions().size());
  for (size_t a = 0; a < v.size(); ++a) {
    const Eigen::Vector3d d = solver_.positions()[a] - c;
    v[a] = Eigen::Vector3d(r.speed_mps + spin0 * d.z(), 0.0, -spin0 * d.x());
  }
  solver_.SetInitialVelocity(v);
  solver_.SetRimMotion(r.speed_mps, 0.0, spin0);
  const double t0 = solver_.time();
  RunUntil(
      "roll", t0 + config_.roll_duration_s, hooks,
      [&] { solver_.rim_loads().force_z_N = -config_.vertical_load_N; }, r.history, nullptr);
  r.max_cord_strain = state_.cursor.max_cord_strain;
  // Means over the second half.
  const double t_half = t0 + 0.5 * config_.roll_duration_s;
  int n = 0;
  for (const HistoryRow& h : r.history) {
    if (h.time_s < t_half) continue;
    r.spin_rad_per_s += h.spin_rad_per_s;
    r.loaded_radius_m += h.rim_z_m - state_.road_z_m;
    r.road_fx_N += h.road_fx_N;
    r.road_fz_N += h.road_fz_N;
    ++n;
  }
  if (n > 0) {
    r.spin_rad_per_s /= n;
    r.loaded_radius_m /= n;
    r.road_fx_N /= n;
    r.road_fz_N /= n;
  }
  r.effective_radius_m = r.spin_rad_per_s > 0 ? r.speed_mps / r.spin_rad_per_s : 0.0;
  state_.rolling_radius_m = r.effective_radius_m;
  return r;
}

BrakeResult TyreRun::Brake(double duration_s, const BrakeTorqueFn& torque, const StepHooks& hooks) {
  if (state_.loaded_radius_m <= 0.0) throw InputError("fe: braking needs the roll step first");
  // Quarter car: the translating mass is load / g (spec section 8), the tyre's included.
  const double quarter = config_.vertical_load_N / kGravity;
  double tyre_mass = 0.0;
  for (size_t a = 0; a < solver_.node_masses().size(); ++a) tyre_mass += solver_.node_masses()[a];
  solver_.AddRimTranslationalMass(std::max(0.0, quarter - tyre_mass - config_.rim_mass_kg));
  solver_.SetRimModes(RimDofMode::kFree, RimDofMode::kFree, RimDofMode::kFree);
  state_.brake = BrakeStep{};
  state_.brake.active = true;
  state_.brake.t0 = solver_.time();
  state_.brake.x0 = solver_.rim_state().centre.x();
  return RunBrake(duration_s, torque, hooks, /*resume=*/false);
}

BrakeResult TyreRun::ResumeBrake(double duration_s, const BrakeTorqueFn& torque,
                                 const StepHooks& hooks) {
  if (!state_.brake.active) throw InputError("fe: no braking step to resume");
  return RunBrake(duration_s, torque, hooks, /*resume=*/true);
}

BrakeResult TyreRun::RunBrake(double duration_s, const BrakeTorqueFn& torque,
                              const StepHooks& hooks, bool resume) {
  const double t0 = state_.brake.t0;
  RunUntil(
      "abs", t0 + duration_s, hooks,
      [&] {
        const RimState& rim = solver_.rim_state();
        const double capacity =
            std::max(0.0, torque(solver_.time() - t0, rim.velocity.x(), rim.spin_rad_per_s));
        state_.brake.applied = -capacity * std::tanh(rim.spin_rad_per_s / kBrakeSpinRegularisation);
        solver_.rim_loads().torque_Nm = state_.brake.applied;
        solver_.rim_loads().force_z_N = -config_.vertical_load_N;
      },
      state_.brake.history, &state_.brake.applied, resume);
  BrakeResult r;
  r.history = state_.brake.history;
  r.max_cord_strain = state_.cursor.max_cord_strain;
  r.initial_speed_mps = r.history.front().rim_vx_mps;
  for (const HistoryRow& h : r.history) {
    r.max_slip = std::max(r.max_slip, h.slip);
    r.max_brake_torque_Nm = std::max(r.max_brake_torque_Nm, std::abs(h.brake_torque_Nm));
  }
  r.final_speed_mps = solver_.rim_state().velocity.x();
  r.distance_m = solver_.rim_state().centre.x() - state_.brake.x0;
  return r;
}

void TyreRun::SaveState(BinaryWriter& out) const {
  if (!state_.brake.active) throw InputError("fe: a checkpoint needs a braking step");
  out.PutTag("TYRE");
  PutFields(out, state_);
  solver_.SaveState(out);
}

void TyreRun::LoadState(BinaryReader& in) {
  in.ExpectTag("TYRE");
  TyreRunState read;  // its history empty: it takes the file's length
  GetFields(in, read);
  if (!read.brake.active) in.Damaged("no braking step");
  if (read.brake.history.empty()) in.Damaged("an empty braking history");
  solver_.LoadState(in);
  state_ = std::move(read);
}

}  // namespace hotlap::fe
