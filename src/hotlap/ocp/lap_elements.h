#pragma once
/// @file
/// The elements of the lap problem (lap_problem.h), each a small function of a few node
/// variables written on the shared vehicle and thermal models. Internal to ocp/.

#include <array>
#include <cmath>
#include <type_traits>

#include "hotlap/brake/brake_thermal.h"
#include "hotlap/common/scalar.h"
#include "hotlap/tyre/compound.h"
#include "hotlap/tyre/tyre_thermal.h"
#include "hotlap/vehicle/vehicle_model.h"

namespace hotlap::ocp::internal {

/// Road data at a node (constants of its elements).
struct NodeRoad {
  double curvature = 0.0;  ///< kappa_h, 1/m
  double bank = 0.0;       ///< rad
  double grade = 0.0;      ///< rad
  double kappa_g() const { return curvature * std::cos(bank); }
  double kappa_n() const { return curvature * std::sin(bank); }
};

/// in (u, v, r, steer, alpha, vx) -> (alpha - atan(vy_w / vx_w), vx - vx_w) for one corner.
struct KinematicsFn {
  const vehicle::VehicleParams* p;
  Corner corner;
  template <class T>
  void operator()(const T* in, T* out) const {
    const vehicle::ChassisMotion<T> m{in[0], in[1], in[2], in[3]};
    const vehicle::WheelKinematics<T> w = vehicle::CalcCornerKinematics(*p, m, corner);
    out[0] = in[4] - w.slip_angle;
    out[1] = in[5] - w.vx;
  }
};

/// Rear wheel on the spool: the axle's speed omega R_mean = (1 + kappa_axle) u, so
/// in (kappa, vx, kappa_axle, u) -> (1 + kappa) vx - (1 + kappa_axle) u R / R_mean.
struct SpoolFn {
  double radius_ratio;
  template <class T>
  void operator()(const T* in, T* out) const {
    out[0] = (1.0 + in[0]) * in[1] - (1.0 + in[2]) * in[3] * radius_ratio;
  }
};

/// Rear axle torque balance (quasi-steady wheels): the rear tyres' force plus the rear brakes'
/// equals the drive force P / (omega R_mean):
/// in (fx_rl, fx_rr, B, u, kappa_axle, P) -> (fx_rl + fx_rr + rear_share B) (1 + kappa_axle) u - P.
struct RearDriveFn {
  double rear_share;
  template <class T>
  void operator()(const T* in, T* out) const {
    out[0] = (in[0] + in[1] + rear_share * in[2]) * (1.0 + in[4]) * in[3] - in[5];
  }
};

/// Body-axis totals of the tyre forces: in (steer, fx fl fr rl rr, fy fl fr rl rr) ->
/// (sum Fx_body, sum Fy_body, yaw moment about the CoG).
struct TotalsFn {
  const vehicle::VehicleParams* p;
  template <class T>
  void operator()(const T* in, T* out) const {
    T fx(0.0), fy(0.0), mz(0.0);
    for (Corner c : kAllCorners) {
      const int i = CornerIndex(c);
      T bx = in[1 + i], by = in[5 + i];
      if (IsFront(c)) {
        const std::array<T, 2> b = vehicle::SteeredToBody(in[0], in[1 + i], in[5 + i]);
        bx = b[0];
        by = b[1];
      }
      const auto [x, y] = p->CornerPosition(c);
      fx += bx;
      fy += by;
      mz += x * by - y * bx;
    }
    out[0] = fx;
    out[1] = fy;
    out[2] = mz;
  }
};

/// Normal loads from the totals: in (u, v, n, X, Y) -> Fz fl fr rl rr (vehicle::CalcNormalLoads
/// with the normal curvature of the car's path at offset n, kappa_n / (1 - n kappa_g)).
struct LoadsFn {
  const vehicle::VehicleParams* p;
  NodeRoad road;
  template <class T>
  void operator()(const T* in, T* out) const {
    const vehicle::ChassisMotion<T> m{in[0], in[1], T(0.0), T(0.0)};
    const vehicle::RoadGeometry<T> g{T(road.bank), T(road.grade),
                                     road.kappa_n() / (1.0 - in[2] * road.kappa_g())};
    const std::array<T, 4> fz = vehicle::CalcNormalLoads(*p, m, g, in[3], in[4]);
    for (int i = 0; i < 4; ++i) out[i] = fz[i];
  }
};

/// dt/ds: in (w, u, v, n, xi) -> w (u cos xi - v sin xi) - (1 - n kappa_g) (spec section 10);
/// also the F1 lap problem's, with its heading error for xi and its curvature for kappa_g.
struct TimeFn {
  double kappa_g;
  template <class T>
  void operator()(const T* in, T* out) const {
    using std::cos;
    using std::sin;
    out[0] = in[0] * (in[1] * cos(in[4]) - in[2] * sin(in[4])) - (1.0 - in[3] * kappa_g);
  }
};

/// du/ds: in (w, X, u, v, r, xi, fz fl fr rl rr) -> w du/dt, rolling resistance -c_i Fz_i.
struct LongitudinalFn {
  const vehicle::VehicleParams* p;
  NodeRoad road;
  std::array<double, 4> rolling;
  template <class T>
  void operator()(const T* in, T* out) const {
    T fx = in[1];
    for (int i = 0; i < 4; ++i) fx -= rolling[i] * in[6 + i];
    const vehicle::ChassisMotion<T> m{in[2], in[3], in[4], T(0.0)};
    const vehicle::RoadGeometry<T> g{T(road.bank), T(road.grade), T(0.0)};
    const auto a = vehicle::CalcChassisAccelerationsFromTotals(*p, m, g, in[5], fx, T(0.0), T(0.0));
    out[0] = in[0] * a.du;
  }
};

/// dv/ds: in (w, Y, u, r, xi) -> w dv/dt.
struct LateralFn {
  const vehicle::VehicleParams* p;
  NodeRoad road;
  template <class T>
  void operator()(const T* in, T* out) const {
    const vehicle::ChassisMotion<T> m{in[2], T(0.0), in[3], T(0.0)};
    const vehicle::RoadGeometry<T> g{T(road.bank), T(road.grade), T(0.0)};
    const auto a =
        vehicle::CalcChassisAccelerationsFromTotals(*p, m, g, in[4], T(0.0), in[1], T(0.0));
    out[0] = in[0] * a.dv;
  }
};

/// w times a variable times a constant: in (w, x) -> c w x. The yaw rate's dr/ds = w Mz / I_z
/// (c = 1 / I_z) and the heading error's dxi/ds + kappa_g = w r (c = 1; the road's -kappa_g is a
/// constant of the defect row), in both lap problems. Evaluated as (w x) c, the order the stock
/// car's own yaw element had: its 15 m solves from the QSS guess are sensitive to rounding (c (w x)
/// took the limited lap's from 92 iterations to 199; docs/validation/optimal-control.md, "Speed").
struct ScaledProductFn {
  double c;
  template <class T>
  void operator()(const T* in, T* out) const {
    out[0] = in[0] * in[1] * c;
  }
};

/// dn/ds: in (w, u, v, xi) -> w (u sin xi + v cos xi).
struct OffsetFn {
  template <class T>
  void operator()(const T* in, T* out) const {
    using std::cos;
    using std::sin;
    out[0] = in[0] * (in[1] * sin(in[3]) + in[2] * cos(in[3]));
  }
};

/// A tyre's thermal and wear model: in (w, T_t, T_c, wear, vx, fx, fy, fz, alpha, kappa) ->
/// w d(T_t, T_c, wear)/dt (000:7-8, 23).
struct TyreThermalFn {
  const tyre::TyreThermalParams<double>* params;
  const tyre::TyreThermalParams<SecondOrder<10>>* params_so;
  const tyre::TyreThermalParams<Jet10>* params_jet;
  const tyre::TyreCompound* compound;
  double ambient_temp, track_temp;

  template <class T>
  const tyre::TyreThermalParams<T>& Params() const {
    if constexpr (std::is_same_v<T, double>) {
      return *params;
    } else if constexpr (std::is_same_v<T, SecondOrder<10>>) {
      return *params_so;
    } else {
      return *params_jet;
    }
  }
  template <class T>
  void operator()(const T* in, T* out) const {
    const tyre::TyreState<T> x{in[1], in[2], in[3]};
    const tyre::TyreInput<T> input{in[4], in[5], in[6],           in[7],
                                   in[8], in[9], T(ambient_temp), T(track_temp)};
    const tyre::TyreState<T> d = tyre::CalcTyreDerivatives(Params<T>(), *compound, x, input);
    out[0] = in[0] * d.tread_temp;
    out[1] = in[0] * d.carcass_temp;
    out[2] = in[0] * d.wear;
  }
};

/// A brake's thermal model: in (w, T_d, T_k, vx, B) -> w d(T_d, T_k)/dt with braking force
/// share * B at this corner (000:24-25).
struct BrakeFn {
  const brake::BrakeThermalParams<double>* params;
  const brake::BrakeThermalParams<SecondOrder<5>>* params_so;
  const brake::BrakeThermalParams<Jet5>* params_jet;
  double share;
  double cooling_air_temp;

  template <class T>
  const brake::BrakeThermalParams<T>& Params() const {
    if constexpr (std::is_same_v<T, double>) {
      return *params;
    } else if constexpr (std::is_same_v<T, SecondOrder<5>>) {
      return *params_so;
    } else {
      return *params_jet;
    }
  }
  template <class T>
  void operator()(const T* in, T* out) const {
    const brake::BrakeState<T> x{in[1], in[2]};
    const brake::BrakeInput<T> input{in[3], -share * in[4], T(cooling_air_temp)};
    const brake::BrakeState<T> d = brake::CalcBrakeDerivatives(Params<T>(), x, input);
    out[0] = in[0] * d.disc_temp;
    out[1] = in[0] * d.calliper_temp;
  }
};

/// A parameter set `P<double>` with its copies on the scalars of an element of N inputs (cast
/// once, kept beside the elements that point to them).
template <template <Scalar> class P, int N>
struct ParamsOn {
  P<double> d;
  P<SecondOrder<N>> so;
  P<ceres::Jet<double, N>> jet;

  ParamsOn() = default;
  explicit ParamsOn(const P<double>& p)
      : d(p),
        so(p.template Cast<SecondOrder<N>>()),
        jet(p.template Cast<ceres::Jet<double, N>>()) {}
  template <class T>
  const P<T>& Get() const {
    if constexpr (std::is_same_v<T, double>) {
      return d;
    } else if constexpr (std::is_same_v<T, SecondOrder<N>>) {
      return so;
    } else {
      return jet;
    }
  }
};

/// A wheel's tyre, rim and brake together, for the gas-and-rim tyre and the surface-and-bulk disc
/// (whose heat meets in the rim): in (w, T_t, T_c, wear, T_rim, vx, fx, fy, fz, alpha, kappa, T_d,
/// T_k, T_bulk, B) -> w d(T_t, T_c, wear, T_rim, T_d, T_k, T_bulk)/dt, the brake's force share * B.
/// The brake's heat into the rim (hub conduction and the disc's radiation) is the tyre's
/// `brake_to_rim`, as in replay (sim/replay.cc); a paper tyre's rim and a lumped disc's bulk have
/// no rate (0).
struct WheelThermalFn {
  static constexpr int kInputs = 15;
  const ParamsOn<tyre::TyreThermalParams, kInputs>* tyre;
  const ParamsOn<brake::BrakeThermalParams, kInputs>* brake;
  const tyre::TyreCompound* compound;
  double share;
  double ambient_temp, track_temp;

  template <class T>
  void operator()(const T* in, T* out) const {
    const tyre::TyreThermalParams<T>& tp = tyre->template Get<T>();
    const brake::BrakeThermalParams<T>& bp = brake->template Get<T>();
    const brake::BrakeState<T> bx{in[11], in[12], in[13]};
    const brake::BrakeInput<T> b_in{in[5], -share * in[14], T(ambient_temp)};
    brake::BrakeHeatFlows<T> bq;
    const brake::BrakeState<T> bd =
        brake::CalcBrakeDerivatives(bp, bx, brake::CalcBrakeInputTerms(bp, b_in), &bq, in[4]);
    const tyre::TyreState<T> tx{in[1], in[2], in[3], in[4]};
    const tyre::TyreInput<T> t_in{in[5], in[6],  in[7],           in[8],
                                  in[9], in[10], T(ambient_temp), T(track_temp)};
    tyre::TyreHeatFlows<T>* no_flows = nullptr;
    const tyre::TyreState<T> td = tyre::CalcTyreDerivatives(
        tp, *compound, tx, tyre::CalcTyreInputTerms(tp, *compound, t_in), no_flows, bq.ToRim());
    out[0] = in[0] * td.tread_temp;
    out[1] = in[0] * td.carcass_temp;
    out[2] = in[0] * td.wear;
    out[3] = in[0] * td.rim_temp;
    out[4] = in[0] * bd.disc_temp;
    out[5] = in[0] * bd.calliper_temp;
    out[6] = in[0] * bd.bulk_temp;
  }
};

/// A gas-and-rim tyre's rolling-resistance force: in (T_c, T_rim, vx, Fz, F_rr) ->
/// F_rr - c_rr(T_c, p) Fz, c_rr at the carcass temperature and the hot pressure of the gas
/// between carcass and rim (tyre::CalcTyreGas): the force the car pays for the hysteresis heat the
/// thermal model books (its `rolling_power` = u F_rr). Fz >= 0 in the programme.
struct RollingForceFn {
  const ParamsOn<tyre::TyreThermalParams, 5>* tyre;
  template <class T>
  void operator()(const T* in, T* out) const {
    const tyre::TyreGas<T> gas = tyre::CalcTyreGas(tyre->template Get<T>(), in[0], in[1], in[2]);
    out[0] = in[4] - gas.rolling_resistance * in[3];
  }
};

/// The driver's one signed longitudinal control, the pedal p in [-1, 1]: drive when positive,
/// brake when negative, never both (the paper's bang-bang drive power, 000 section 4). in (p, P, B)
/// -> (P - P_max pos(p), B - B_max pos(-p)) with the smooth positive part
/// pos(x) = (x + sqrt(x^2 + eps^2)) / 2: exact derivatives, and where one side is on the other
/// is at most B_max eps^2 / (4 |p|) (below a newton past |p| = 0.02 with eps = 5e-3).
struct PedalSplitFn {
  double max_power;        ///< W at p = 1
  double max_brake_force;  ///< N at p = -1
  double eps;
  template <class T>
  static T Pos(const T& x, double eps) {
    using std::sqrt;
    return 0.5 * (x + sqrt(x * x + eps * eps));
  }
  template <class T>
  void operator()(const T* in, T* out) const {
    out[0] = in[1] - max_power * Pos(in[0], eps);
    out[1] = in[2] - max_brake_force * Pos(T(-in[0]), eps);
  }
};

/// A control's smoothness penalty: in (a, b) -> weight (b - a)^2.
struct RateFn {
  double weight;
  template <class T>
  void operator()(const T* in, T* out) const {
    const T d = in[1] - in[0];
    out[0] = weight * d * d;
  }
};

}  // namespace hotlap::ocp::internal
