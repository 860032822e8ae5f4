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
/// Tangential: Coulomb with a regularised stick that an explicit step can carry. The force is
///   f_t = -min(mu(s) f_n / s, c_stick) v_t,  s = |v_t|,  c_stick = m_node / dt,
/// i.e. sliding friction mu f_n against the slip, capped by the force that would bring the node's
/// slip velocity to rest in one step (a stiffer viscous stick would be unstable in explicit time:
/// it needs c dt / m < 2). No elastic stick spring: all friction work is dissipated, and a node
/// held by static friction creeps at a slip speed of order (tangential load) dt / m_node.

#include <Eigen/Core>

namespace hotlap::fe {

/// The exponential-decay friction law (002:1) with its regularisation.
struct FrictionLaw {
  double static_coefficient = 0.0;   ///< mu_s, 1
  double kinetic_coefficient = 0.0;  ///< mu_k, 1
  double decay_s_per_m = 0.0;        ///< d_c, s/m
};

/// mu at `slip_speed_mps` (>= 0), (002:1).
double CalcFrictionCoefficient(const FrictionLaw& law, double slip_speed_mps);

/// Friction force on a node with normal force `normal_force_N` (>= 0), tangential slip
/// velocity `slip_velocity` (relative to the road, z component ignored) and stick damping
/// `stick_coefficient_N_s_per_m` (node mass over time step), N.
Eigen::Vector3d CalcFrictionForce(const FrictionLaw& law, double normal_force_N,
                                  const Eigen::Vector3d& slip_velocity,
                                  double stick_coefficient_N_s_per_m);

/// The road. Its normal is +z.
struct RoadContact {
  bool enabled = false;
  double height_m = 0.0;          ///< road plane z, m
  double penalty_factor = 0.0;    ///< k = penalty_factor m_node / dt^2, 1 (in (0, 1))
  double road_speed_x_mps = 0.0;  ///< road surface velocity along x, m/s (a rolling drum)
  FrictionLaw friction;
};

}  // namespace hotlap::fe
