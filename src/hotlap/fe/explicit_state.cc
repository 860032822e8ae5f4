#include "hotlap/fe/explicit_state.h"

namespace hotlap::fe {

namespace {

bool IsTiedToRim(const ExplicitModel& model, const ExplicitState& state, size_t a) {
  return state.rim_settings && model.is_rim_node[a];
}

}  // namespace

ExplicitState MakeInitialState(const ExplicitModel& model) {
  const size_t nn = model.mesh.nodes.size();
  ExplicitState s;
  s.mass_damping_per_s = model.options.mass_damping_per_s;
  s.x = model.mesh.nodes;
  s.v.assign(nn, Eigen::Vector3d::Zero());
  s.applied = s.reaction = s.fixed_velocity = s.v;
  s.f_stored = s.f_dissip_bv = s.f_dissip_hg = s.f_damp = s.f_contact = s.f_friction =
      s.f_external = s.v;
  s.fixed.assign(nn, {0, 0, 0});
  s.contact_normal.assign(nn, 0.0);
  s.stick_extension.assign(nn, Eigen::Vector2d::Zero());
  s.on_road.assign(nn, 0);
  return s;
}

void SetRoad(const RoadContact& road, ExplicitState& state) {
  state.road = road;
  std::fill(state.stick_extension.begin(), state.stick_extension.end(), Eigen::Vector2d::Zero());
  std::fill(state.on_road.begin(), state.on_road.end(), 0);
}

void SetRim(const ExplicitModel& model, const RimSettings& rim, ExplicitState& state) {
  state.rim_settings = rim;
  state.rim = RimState{};
  state.rim.centre = rim.centre;
  state.rim_mass_kg = rim.mass_kg;
  state.rim_inertia_kgm2 = rim.inertia_kgm2;
  for (int a : model.mesh.rim_nodes) {
    const Eigen::Vector3d r = model.mesh.nodes[a] - rim.centre;
    state.rim_mass_kg += model.mass[a];
    state.rim_inertia_kgm2 += model.mass[a] * (r.x() * r.x() + r.z() * r.z());
  }
}

void SetInitialVelocity(const ExplicitModel& model, const std::vector<Eigen::Vector3d>& v,
                        ExplicitState& state) {
  double before = 0.0, after = 0.0;
  for (size_t a = 0; a < state.v.size(); ++a) {
    if (IsTiedToRim(model, state, a)) continue;
    before += 0.5 * model.mass[a] * state.v[a].squaredNorm();
    state.v[a] = v[a];
    after += 0.5 * model.mass[a] * state.v[a].squaredNorm();
  }
  if (state.steps == 0) {
    state.energies.initial_kinetic = after;
  } else {
    state.work_to_midstep[0] += after - before;
  }
}

void SetRimMotion(const ExplicitModel& model, double vx_mps, double vz_mps, double spin_rad_per_s,
                  ExplicitState& state) {
  RimState& rim = state.rim;
  const double before = 0.5 * state.rim_mass_kg * rim.velocity.squaredNorm() +
                        0.5 * state.rim_inertia_kgm2 * rim.spin_rad_per_s * rim.spin_rad_per_s;
  rim.velocity = Eigen::Vector3d(vx_mps, 0.0, vz_mps);
  rim.spin_rad_per_s = spin_rad_per_s;
  state.rim_target = Eigen::Vector3d(vx_mps, vz_mps, spin_rad_per_s);
  const double after = 0.5 * state.rim_mass_kg * rim.velocity.squaredNorm() +
                       0.5 * state.rim_inertia_kgm2 * spin_rad_per_s * spin_rad_per_s;
  for (int a : model.mesh.rim_nodes) {
    state.v[a] = rim.velocity + SpinVelocity(spin_rad_per_s, state.x[a] - rim.centre);
  }
  if (state.steps > 0) state.work_to_midstep[0] += after - before;
}

void AddRimTranslationalMass(double mass_kg, ExplicitState& state) {
  state.rim_mass_kg += mass_kg;
  if (state.steps > 0) {
    state.work_to_midstep[0] += 0.5 * mass_kg * state.rim.velocity.squaredNorm();
  }
}

}  // namespace hotlap::fe
