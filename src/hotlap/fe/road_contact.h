#pragma once
/// @file
/// A flat rigid road z = height with node-to-surface penalty contact and the FE/ABS paper's
/// exponential-decay friction law (002:1),
///   mu = mu_k + (mu_s - mu_k) exp(-d_c * slip_speed),
/// with mu_s 0.90, mu_k 0.45, d_c 0.5 s/m in the paper.
///
/// Normal: a node below the road is pushed up by f_n = k g, g the penetration, k = penalty_factor
/// times the node's mass over dt^2 (a stiffness the explicit step can carry: penalty_factor well
/// below 1). Stored energy k g^2 / 2.
///
/// Tangential (the default, StickModel::kElasticSpring): penalty Coulomb friction with an elastic
/// stick, as Abaqus/Explicit's penalty friction. A node in contact is tied to an anchor on the road
/// (moving with the road) by a tangential spring of stiffness
///   k_t = tangential_penalty_factor m_node / dt^2,
/// set where the node touched down. Each step the spring's trial force -k_t (x_t - anchor) is
/// returned to the Coulomb limit (ReturnMapFriction): if its magnitude is at most mu(s) f_n, s the
/// node's slip speed relative to the road, the node sticks and the spring's force acts; otherwise
/// the node slips, the force is mu(s) f_n along the trial force, and the anchor moves so that the
/// spring carries exactly that force. When the node leaves the road the anchor is dropped. A
/// static tangential load below mu_s f_n is therefore held with an elastic slip of at most
/// mu_s f_n / k_t (= mu_s times the normal penetration when both factors are equal). The energy
/// of the springs, k_t |x_t - anchor|^2 / 2, is stored (Energies::contact_stored); the work of the
/// limit force over the anchor's moves is the friction dissipation (Energies::friction).
/// Stability: with the step dt = s dt_crit (s = time_step_safety, dt_crit <= 2 / omega_elements),
/// the stiffest mode of mesh plus contact springs obeys (omega dt)^2 <= (2 s)^2 + max(penalty
/// factors), so central differences stay stable if every penalty factor is at most 4 (1 - s^2)
/// (0.76 at s = 0.9; MaxStablePenaltyFactor); above 4 a stuck node alone is unstable.
///
/// The old law (StickModel::kViscous): the force is
///   f_t = -min(mu(s) f_n / s, c_stick) v_t,  s = |v_t|,  c_stick = m_node / dt,
/// sliding friction against the slip, capped by the force that brings the node's slip velocity to
/// rest in one step. It has no elastic stick: all friction work is dissipated, and a node held by
/// static friction creeps at a slip speed of order (tangential load) dt / m_node, so a static
/// tangential load below mu_s f_n is not held. Kept for comparison.

#include <cstdint>

#include <Eigen/Core>

#include "hotlap/fe/visit_fields.h"

namespace hotlap::fe {

/// The exponential-decay friction law (002:1) with its regularisation.
struct FrictionLaw {
  double static_coefficient = 0.0;   ///< mu_s, 1
  double kinetic_coefficient = 0.0;  ///< mu_k, 1
  double decay_s_per_m = 0.0;        ///< d_c, s/m
};

/// mu at `slip_speed_mps` (>= 0), (002:1).
double CalcFrictionCoefficient(const FrictionLaw& law, double slip_speed_mps);

/// The return mapping of penalty Coulomb friction: a tangential spring of stiffness
/// `stiffness_N_per_m` stretched by `extension` = x_t - anchor (m; on entry the trial extension,
/// the anchor where the node last stuck). Its trial force is -k extension; if that is at most
/// `limit_N` (mu f_n) in magnitude the node sticks and `extension` is kept; otherwise `extension`
/// is scaled so that k |extension| = limit_N (the anchor moves towards the node along the trial
/// force). Returns the friction force -k extension (after the mapping), N.
Eigen::Vector2d ReturnMapFriction(double stiffness_N_per_m, double limit_N,
                                  Eigen::Vector2d& extension);

/// The viscous-stick friction force (StickModel::kViscous) on a node with normal force
/// `normal_force_N` (>= 0), tangential slip velocity `slip_velocity` (relative to the road, z
/// component ignored) and stick damping `stick_coefficient_N_s_per_m` (node mass over time
/// step), N.
Eigen::Vector3d CalcFrictionForce(const FrictionLaw& law, double normal_force_N,
                                  const Eigen::Vector3d& slip_velocity,
                                  double stick_coefficient_N_s_per_m);

/// The largest penalty factor (normal or tangential) that keeps central differences stable with
/// time_step_safety `safety`, whatever the mesh: 4 (1 - safety^2) (see the file comment).
double MaxStablePenaltyFactor(double safety);

/// How a node held by static friction is modelled.
enum class StickModel : std::uint8_t {
  kElasticSpring,  ///< penalty spring to an anchor, returned to the Coulomb limit (default)
  kViscous,        ///< the old viscous stick, -min(mu f_n / s, m / dt) v_t: creeps
};
/// The largest StickModel (checkpoint readers refuse anything above; field_io.h).
constexpr std::uint64_t EnumMax(StickModel) { return std::uint64_t(StickModel::kViscous); }

/// The road. Its normal is +z.
struct RoadContact {
  bool enabled = false;
  double height_m = 0.0;        ///< road plane z, m
  double penalty_factor = 0.0;  ///< k = penalty_factor m_node / dt^2, 1 (in (0, 1))
  /// k_t = tangential_penalty_factor m_node / dt^2, 1 (in (0, MaxStablePenaltyFactor]).
  double tangential_penalty_factor = 0.1;
  double road_speed_x_mps = 0.0;  ///< road surface velocity along x, m/s (a rolling drum)
  StickModel stick = StickModel::kElasticSpring;
  FrictionLaw friction;
};

/// The fields of a FrictionLaw (visit_fields.h; the FE checkpoint saves them).
HOTLAP_VISIT_FIELDS(FrictionLaw, static_coefficient, kinetic_coefficient, decay_s_per_m)

/// The fields of a RoadContact (visit_fields.h; the FE checkpoint saves them).
HOTLAP_VISIT_FIELDS(RoadContact, enabled, height_m, penalty_factor, tangential_penalty_factor,
                    road_speed_x_mps, stick, friction)

}  // namespace hotlap::fe
