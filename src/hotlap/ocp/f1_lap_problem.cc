#include "hotlap/ocp/f1_lap_problem.h"
#include "hotlap/common/special_values.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/ocp/element_nlp.h"
#include "hotlap/ocp/lap_elements.h"

namespace hotlap::ocp {

namespace {

using vehicle::F1CarParams;

constexpr double kKmh = 1.0 / 3.6;

// ---- Elements (ocp/element.h): each a small function of a few node variables. ----

// Contact-patch velocity of corner c in the wheel frame, ISO axes.
template <class T>
std::array<T, 2> WheelVelocity(const F1CarParams& p, int corner, const T& u, const T& v, const T& r,
                               const T* steer) {
  using std::cos;
  using std::sin;
  const auto [x, y] = p.CornerPosition(corner);
  const T vx = u - r * y;
  const T vy = v + r * x;
  if (steer == nullptr) return {vx, vy};
  const T c = cos(*steer), s = sin(*steer);
  return {c * vx + s * vy, c * vy - s * vx};
}

// One tyre at a node: its normal load (from the chassis motion and the body-axis tyre totals
// X, Y), lateral slip lambda = -vy / vx in the wheel frame, and wheel-frame forces.
template <class T>
struct TyreState {
  T fz, lambda, fx, fy;
};

template <class T>
TyreState<T> CalcTyre(const F1CarParams& p, int corner, const T& u, const T& v, const T& r,
                      const T* steer, const T& x_total, const T& y_total, const T& kappa) {
  TyreState<T> t;
  t.fz = vehicle::CalcF1NormalLoads(p, u, x_total, y_total)[corner];
  const auto w = WheelVelocity(p, corner, u, v, r, steer);
  t.lambda = -w[1] / w[0];
  const vehicle::F1TyreForce<T> f = vehicle::CalcF1TyreForce(p.tyre(corner), t.fz, kappa, t.lambda);
  t.fx = f.fx;
  t.fy = f.fy;
  return t;
}

// The body-axis force and yaw moment of a tyre at (x, y) with wheel-frame forces (fx, fy) turned
// by `steer` (nullptr: not steered).
template <class T>
std::array<T, 3> BodyForce(const F1CarParams& p, int corner, const T& fx, const T& fy,
                           const T* steer) {
  using std::cos;
  using std::sin;
  T bx = fx, by = fy;
  if (steer != nullptr) {
    const T c = cos(*steer), s = sin(*steer);
    bx = c * fx - s * fy;
    by = s * fx + c * fy;
  }
  const auto [px, py] = p.CornerPosition(corner);
  return {bx, by, px * by - py * bx};
}

// A tyre: in (u, v, r, [steer,] X, Y, kappa) (steer on the front tyres only) -> its body-axis
// (Fx, Fy, Mz), which add into the totals' rows; its wheel-frame Fx, which enters its wheel's
// torque balance; and its lateral slip lambda, which is bounded.
struct TyreFn {
  const F1CarParams* p;
  int corner;
  template <class T>
  void operator()(const T* in, T* out) const {
    const bool front = corner < 2;
    const T* steer = front ? &in[3] : nullptr;
    const int o = front ? 4 : 3;  // X, Y, kappa follow
    const TyreState<T> t =
        CalcTyre(*p, corner, in[0], in[1], in[2], steer, in[o], in[o + 1], in[o + 2]);
    const std::array<T, 3> b = BodyForce(*p, corner, t.fx, t.fy, steer);
    out[0] = b[0];
    out[1] = b[1];
    out[2] = b[2];
    out[3] = t.fx;
    out[4] = t.lambda;
  }
};

// The front wheels' torque balance without spin inertia, Fx R = -T_brake beta brake(throttle):
// in (throttle) -> T_brake beta brake(throttle) / R, added to each front wheel's row (Fx + that).
struct FrontBrakeFn {
  const F1CarParams* p;
  template <class T>
  void operator()(const T* in, T* out) const {
    const auto split = vehicle::F1ThrottleSplit(*p, in[0]);
    out[0] = p->brake_torque_front_Nm * p->brake_bias_front * split[1] / p->front_tyre.radius_m;
  }
};

// The rear wheels' torques over R, subtracted in their rows (Fx - T / R): T = -T_brake (1 - beta)
// brake + P drive / (2 omega_mean) -+ k (omega_l - omega_r) (minus on the left wheel), omega =
// (1 + kappa) vx / R: in (u, r, kappa_rl, kappa_rr, throttle) -> (T_rl / R, T_rr / R).
struct RearDriveFn {
  const F1CarParams* p;
  template <class T>
  void operator()(const T* in, T* out) const {
    const double radius = p->rear_tyre.radius_m;
    const double half = 0.5 * p->track_rear_m;
    const T omega_l = (1.0 + in[2]) * (in[0] - in[1] * half) / radius;
    const T omega_r = (1.0 + in[3]) * (in[0] + in[1] * half) / radius;
    const auto split = vehicle::F1ThrottleSplit(*p, in[4]);
    const T engine = p->engine_power_W * split[0] / (0.5 * (omega_l + omega_r));
    const T diff = p->differential_stiffness_Nms * (omega_l - omega_r);
    const T common =
        -p->brake_torque_rear_Nm * (1.0 - p->brake_bias_front) * split[1] + 0.5 * engine;
    out[0] = (common - diff) / radius;
    out[1] = (common + diff) / radius;
  }
};

// du/ds: in (w, X, u, v, r) -> w ((X - D u^2) / m + v r).
struct LongitudinalFn {
  double inv_mass, drag;
  template <class T>
  void operator()(const T* in, T* out) const {
    out[0] = in[0] * ((in[1] - drag * in[2] * in[2]) * inv_mass + in[3] * in[4]);
  }
};

// dv/ds: in (w, Y, u, r) -> w (Y / m - u r).
struct LateralFn {
  double inv_mass;
  template <class T>
  void operator()(const T* in, T* out) const {
    out[0] = in[0] * (in[1] * inv_mass - in[2] * in[3]);
  }
};

// The wheels on the track (fastest-lap's "real track limits"): in (n, alpha) ->
// (n + t/2 cos alpha, n - t/2 cos alpha), the offsets of the axle ends.
struct WheelOffsetsFn {
  double half_track;
  template <class T>
  void operator()(const T* in, T* out) const {
    using std::cos;
    const T d = half_track * cos(in[1]);
    out[0] = in[0] + d;
    out[1] = in[0] - d;
  }
};

struct Node {
  int u, v, r, n, alpha, steer, throttle;
  std::array<int, 4> kappa;
  int x_total, y_total, mz_total, w;
  std::array<int, 5> States() const { return {u, v, r, n, alpha}; }
};

// Smoothed |curvature| for the speed profile: the largest of a node and its neighbours.
double LocalCurvature(const std::vector<double>& k, int i) {
  const int n = static_cast<int>(k.size());
  double m = 0.0;
  for (int d = -1; d <= 1; ++d) m = std::max(m, std::abs(k[(i + d + n) % n]));
  return m;
}

struct Builder {
  const F1CarParams& p;
  const track::Track& track;
  const F1LapOptions& options;
  ElementNlp nlp;
  std::vector<Node> nodes;
  std::vector<double> curvature;
  int count = 0;
  double ds = 0.0;
  std::vector<std::array<int, 5>> defect_rows;
  double guess_lap_time = 0.0;

  Builder(const F1CarParams& car, const track::Track& t, const F1LapOptions& o)
      : p(car), track(t), options(o) {}

  void AddNodes() {
    count = options.mesh_points;
    ds = track.length_m() / count;
    const std::vector<double> speeds = F1GuessSpeeds(p, track, count);
    for (int k = 0; k < count; ++k) curvature.push_back(track.At(k * ds).curvature_per_m);
    guess_lap_time = 0.0;
    for (double s : speeds) guess_lap_time += ds / s;
    const double m = p.mass_kg;
    const double a = p.front_axle_x_m, b = -p.rear_axle_x_m;
    for (int k = 0; k < count; ++k) {
      const track::TrackPoint tp = track.At(k * ds);
      const double speed = speeds[k];
      const double kc = curvature[k];
      Node nd;
      // States, with fastest-lap's bounds: u in [50, 380] km/h, |v| <= 50 km/h, |r| <= 10 rad/s,
      // |alpha| <= 45 deg, n within the track edges.
      nd.u = nlp.AddVariable(speed, 50.0 * kKmh, 380.0 * kKmh, 50.0);
      nd.v = nlp.AddVariable(0.0, -50.0 * kKmh, 50.0 * kKmh, 1.0);
      nd.r = nlp.AddVariable(speed * kc, -10.0, 10.0, 0.3);
      nd.n = nlp.AddVariable(0.0, -tp.width_right_m, tp.width_left_m, 5.0);
      nd.alpha = nlp.AddVariable(0.0, -DegToRad(45.0), DegToRad(45.0), 0.05);
      // Controls: steer within +-20 deg, throttle in [-1, 1].
      const double prev = speeds[(k + count - 1) % count], next = speeds[(k + 1) % count];
      const double ax = (next * next - prev * prev) / (4.0 * ds);
      const double drag = p.DragFactor() * speed * speed;
      const double x_req = m * ax + drag;
      const double y_req = m * speed * speed * kc;
      double throttle = 0.0;
      if (x_req >= 0.0) {
        throttle = std::clamp(x_req * speed / p.engine_power_W, 0.0, 1.0);
      } else {
        const double full =
            2.0 * (p.brake_torque_front_Nm * p.brake_bias_front / p.front_tyre.radius_m +
                   p.brake_torque_rear_Nm * (1.0 - p.brake_bias_front) / p.rear_tyre.radius_m);
        throttle = -std::clamp(-x_req / full, 0.0, 1.0);
      }
      const double steer = std::clamp((a + b) * kc, -0.3, 0.3);
      nd.steer = nlp.AddVariable(steer, -DegToRad(20.0), DegToRad(20.0), 0.05);
      nd.throttle = nlp.AddVariable(throttle, -1.0, 1.0, 1.0);
      // Algebraic variables from the quasi-steady guess.
      const std::array<double, 4> loads = vehicle::CalcF1NormalLoads(p, speed, x_req, y_req);
      std::array<double, 4> fx_want{};
      if (throttle >= 0.0) {
        fx_want = {0.0, 0.0, 0.5 * x_req, 0.5 * x_req};
      } else {
        const double front =
            -p.brake_torque_front_Nm * p.brake_bias_front * -throttle / p.front_tyre.radius_m;
        const double rear =
            -p.brake_torque_rear_Nm * (1.0 - p.brake_bias_front) * -throttle / p.rear_tyre.radius_m;
        fx_want = {front, front, rear, rear};
      }
      std::array<double, 4> kappas{};
      for (int c = 0; c < 4; ++c) {
        const double fz = std::max(loads[c], 0.05 * p.Weight());
        kappas[c] = std::clamp(0.5 * p.tyre(c).kappa_max_1 * fx_want[c] / (1.4 * fz), -0.1, 0.1);
        nd.kappa[c] = nlp.AddVariable(kappas[c], -0.11, 0.11, 0.05);
      }
      // Totals consistent with the guess's slips (a few fixed-point sweeps: the loads depend
      // on the totals).
      double tx = x_req, ty = y_req, tm = 0.0;
      for (int it = 0; it < 5; ++it) {
        double sx = 0.0, sy = 0.0, sm = 0.0;
        for (int c = 0; c < 4; ++c) {
          const double r = speed * kc;
          const TyreState<double> t =
              CalcTyre(p, c, speed, 0.0, r, c < 2 ? &steer : nullptr, tx, ty, kappas[c]);
          const auto bf = BodyForce(p, c, t.fx, t.fy, c < 2 ? &steer : nullptr);
          sx += bf[0];
          sy += bf[1];
          sm += bf[2];
        }
        tx = sx;
        ty = sy;
        tm = sm;
      }
      nd.x_total = nlp.AddVariable(tx, -kInf, kInf, 1e4);
      nd.y_total = nlp.AddVariable(ty, -kInf, kInf, 1e4);
      nd.mz_total = nlp.AddVariable(tm, -kInf, kInf, 1e4);
      nd.w = nlp.AddVariable(1.0 / speed, 1.0 / 150.0, 1.0 / 5.0, 0.02);
      nodes.push_back(nd);
    }
  }

  void AddNodeEquations(int k) {
    const Node& nd = nodes[k];
    // Totals: X - sum of the tyres' body-axis forces = 0, likewise Y and the yaw moment.
    const int rx = nlp.AddConstraint(0.0, 0.0, 1e4), ry = nlp.AddConstraint(0.0, 0.0, 1e4),
              rm = nlp.AddConstraint(0.0, 0.0, 1e4);
    nlp.AddLinear(rx, nd.x_total, 1.0);
    nlp.AddLinear(ry, nd.y_total, 1.0);
    nlp.AddLinear(rm, nd.mz_total, 1.0);
    std::array<int, 4> wheel_rows{};
    for (int c = 0; c < 4; ++c) {
      wheel_rows[c] = nlp.AddConstraint(0.0, 0.0, 1000.0);
      const int rl = nlp.AddConstraint(-options.max_lateral_slip, options.max_lateral_slip, 0.05);
      const std::vector<std::vector<Target>> targets = {
          {{rx, -1.0}}, {{ry, -1.0}}, {{rm, -1.0}}, {{wheel_rows[c], 1.0}}, {{rl, 1.0}}};
      if (c < 2) {
        nlp.AddElement(tyre[c], {nd.u, nd.v, nd.r, nd.steer, nd.x_total, nd.y_total, nd.kappa[c]},
                       targets);
      } else {
        nlp.AddElement(tyre[c], {nd.u, nd.v, nd.r, nd.x_total, nd.y_total, nd.kappa[c]}, targets);
      }
    }
    nlp.AddElement(front_brake, {nd.throttle}, {{{wheel_rows[0], 1.0}, {wheel_rows[1], 1.0}}});
    nlp.AddElement(rear_drive, {nd.u, nd.r, nd.kappa[2], nd.kappa[3], nd.throttle},
                   {{{wheel_rows[2], -1.0}}, {{wheel_rows[3], -1.0}}});
    // The wheels within the track edges: n + t/2 cos alpha <= w_left, n - t/2 cos alpha >=
    // -w_right.
    {
      const track::TrackPoint tp = track.At(k * ds);
      const int rl = nlp.AddConstraint(-kInf, tp.width_left_m, 1.0);
      const int rr = nlp.AddConstraint(-tp.width_right_m, kInf, 1.0);
      nlp.AddElement(wheel_offsets, {nd.n, nd.alpha}, {{{rl, 1.0}}, {{rr, 1.0}}});
    }
    // dt/ds.
    {
      const int rt = nlp.AddConstraint(0.0, 0.0, 1.0);
      // The stock car's element; this problem's heading error alpha stands for its xi.
      nlp.AddElement(MakeElement<5, 1>(internal::TimeFn{curvature[k]}),
                     {nd.w, nd.u, nd.v, nd.n, nd.alpha}, {{{rt, 1.0}}});
    }
  }

  std::vector<Target> DefectTargets(int k, int state) const {
    // Node k's derivative enters the defects of intervals k - 1 and k (periodic).
    return {{defect_rows[(k + count - 1) % count][state], -0.5 * ds},
            {defect_rows[k][state], -0.5 * ds}};
  }

  void AddDynamics() {
    defect_rows.resize(count);
    for (int k = 0; k < count; ++k) {
      const int k1 = (k + 1) % count;
      const auto a = nodes[k].States(), b = nodes[k1].States();
      for (int j = 0; j < 5; ++j) {
        // dalpha/ds = w r - kappa: the road's curvature moves to the right-hand side.
        const double rhs = j == 4 ? -0.5 * ds * (curvature[k] + curvature[k1]) : 0.0;
        const int row = nlp.AddConstraint(rhs, rhs, nlp.scale(a[j]));
        nlp.AddLinear(row, b[j], 1.0);
        nlp.AddLinear(row, a[j], -1.0);
        defect_rows[k][j] = row;
      }
    }
    const auto longitudinal = std::shared_ptr<const Element>(
        MakeElement<5, 1>(LongitudinalFn{1.0 / p.mass_kg, p.DragFactor()}));
    const auto lateral =
        std::shared_ptr<const Element>(MakeElement<4, 1>(LateralFn{1.0 / p.mass_kg}));
    const auto yaw = std::shared_ptr<const Element>(
        MakeElement<2, 1>(internal::ScaledProductFn{1.0 / p.yaw_inertia_kgm2}));
    // The stock car's dn/ds element; this problem's heading error alpha stands for its xi.
    const auto offset = std::shared_ptr<const Element>(MakeElement<4, 1>(internal::OffsetFn{}));
    const auto heading =
        std::shared_ptr<const Element>(MakeElement<2, 1>(internal::ScaledProductFn{1.0}));
    for (int k = 0; k < count; ++k) {
      const Node& nd = nodes[k];
      nlp.AddElement(longitudinal, {nd.w, nd.x_total, nd.u, nd.v, nd.r}, {DefectTargets(k, 0)});
      nlp.AddElement(lateral, {nd.w, nd.y_total, nd.u, nd.r}, {DefectTargets(k, 1)});
      nlp.AddElement(yaw, {nd.w, nd.mz_total}, {DefectTargets(k, 2)});
      nlp.AddElement(offset, {nd.w, nd.u, nd.v, nd.alpha}, {DefectTargets(k, 3)});
      nlp.AddElement(heading, {nd.w, nd.r}, {DefectTargets(k, 4)});
    }
  }

  void AddObjective() {
    // Lap time: the periodic trapezoid of dt/ds.
    for (int k = 0; k < count; ++k) nlp.AddObjectiveLinear(nodes[k].w, ds);
    // fastest-lap's control penalties: c ((u_{k+1} - u_k) / ds)^2 ds.
    const auto steer_rate = std::shared_ptr<const Element>(
        MakeElement<2, 1>(internal::RateFn{options.steer_dissipation / ds}));
    const auto throttle_rate = std::shared_ptr<const Element>(
        MakeElement<2, 1>(internal::RateFn{options.throttle_dissipation / ds}));
    for (int k = 0; k < count; ++k) {
      const int k1 = (k + 1) % count;
      if (options.steer_dissipation > 0.0) {
        nlp.AddElement(steer_rate, {nodes[k].steer, nodes[k1].steer},
                       {{{Target::kObjective, 1.0}}});
      }
      if (options.throttle_dissipation > 0.0) {
        nlp.AddElement(throttle_rate, {nodes[k].throttle, nodes[k1].throttle},
                       {{{Target::kObjective, 1.0}}});
      }
    }
    nlp.SetObjectiveScale(1.0);
  }

  void Build() {
    for (int c = 0; c < 2; ++c) tyre[c] = MakeElement<7, 5>(TyreFn{&p, c});
    for (int c = 2; c < 4; ++c) tyre[c] = MakeElement<6, 5>(TyreFn{&p, c});
    front_brake = MakeElement<1, 1>(FrontBrakeFn{&p});
    rear_drive = MakeElement<5, 2>(RearDriveFn{&p});
    wheel_offsets = MakeElement<2, 2>(WheelOffsetsFn{0.5 * p.track_front_m});
    AddNodes();
    for (int k = 0; k < count; ++k) AddNodeEquations(k);
    AddDynamics();
    AddObjective();
    nlp.Finalize();
  }

  std::array<std::shared_ptr<const Element>, 4> tyre;
  std::shared_ptr<const Element> wheel_offsets, front_brake, rear_drive;
};

}  // namespace

std::vector<double> F1GuessSpeeds(const F1CarParams& p, const track::Track& track,
                                  int mesh_points) {
  const int count = mesh_points;
  const double ds = track.length_m() / count;
  std::vector<double> k(count);
  for (int i = 0; i < count; ++i) k[i] = track.At(i * ds).curvature_per_m;
  const double m = p.mass_kg, g = vehicle::kF1Gravity;
  const double cl = p.DownforceFactor(), cd = p.DragFactor();
  // Grip levels of the quasi-steady guess, well below the tyres' peaks (about 1.5): a
  // conservative profile is easy to make feasible and leads Ipopt to the best lap found (77.999 s
  // from 1.1 / 1.0 in 47 iterations); profiles near the tyres' limits (1.7 / 1.5, 2.0 / 1.7)
  // ended in slower local optima (78.67 s, 79.67 s) after 115 and 171 iterations
  // (docs/f1-peer.md).
  const double mu_y = 1.1, mu_x = 1.0, rear_share = 0.53;
  // Top speed where the drive power meets the drag.
  const double v_top = std::min(380.0 * kKmh, std::cbrt(p.engine_power_W / cd));
  std::vector<double> limit(count);
  for (int i = 0; i < count; ++i) {
    const double kk = LocalCurvature(k, i);
    const double den = m * kk - mu_y * cl;
    limit[i] = den > 0.0 ? std::min(v_top, std::sqrt(mu_y * m * g / den)) : v_top;
    limit[i] = std::max(limit[i], 55.0 * kKmh);
  }
  std::vector<double> v = limit;
  for (int pass = 0; pass < 3; ++pass) {
    for (int j = 0; j < count; ++j) {  // forward: power and rear-axle traction
      const int i = j, i1 = (j + 1) % count;
      const double grip = mu_x * rear_share * (g + cl * v[i] * v[i] / m);
      const double acc = std::min(p.engine_power_W / (m * v[i]), grip) - cd * v[i] * v[i] / m;
      v[i1] = std::min(v[i1], std::sqrt(std::max(v[i] * v[i] + 2.0 * ds * acc, 0.0)));
    }
    for (int j = count - 1; j >= 0; --j) {  // backward: braking on four wheels
      const int i = j, i1 = (j + 1) % count;
      const double dec = mu_x * (g + cl * v[i1] * v[i1] / m) + cd * v[i1] * v[i1] / m;
      v[i] = std::min(v[i], std::sqrt(v[i1] * v[i1] + 2.0 * ds * dec));
    }
  }
  for (double& x : v) x = std::max(x, 55.0 * kKmh);
  return v;
}

IpoptOptions F1IpoptOptions() {
  IpoptOptions o;
  o.tolerance = 1e-7;
  o.constraint_tolerance = 1e-7;
  o.extra = {{"mu_strategy", "monotone"},
             {"mumps_permuting_scaling", "0"},
             {"mumps_scaling", "0"},
             {"mumps_pivot_order", "3"}};
  return o;
}

F1LapSolution SolveF1Lap(const F1CarParams& car, const track::Track& track,
                         const F1LapOptions& options, const IpoptOptions& ipopt) {
  if (options.mesh_points < 20) {
    throw InputError(
        fmt::format("F1 lap: at least 20 mesh points are needed, got {}", options.mesh_points));
  }
  Builder b(car, track, options);
  b.Build();
  F1LapSolution out;
  out.variables = b.nlp.variables();
  out.constraints = b.nlp.constraints();
  out.guess_lap_time = b.guess_lap_time;
  out.solve = SolveWithIpopt(b.nlp, ipopt);
  const std::vector<double>& x = out.solve.x;
  if (x.empty()) return out;
  const double time = AppendRoadFrameChannels(b.nodes, x, b.ds, out);
  for (int k = 0; k < b.count; ++k) {
    const Node& nd = b.nodes[k];
    out.alpha.push_back(x[nd.alpha]);
    out.steer.push_back(x[nd.steer]);
    out.throttle.push_back(x[nd.throttle]);
    for (int c = 0; c < 4; ++c) {
      const double steer = x[nd.steer];
      const TyreState<double> t =
          CalcTyre(car, c, x[nd.u], x[nd.v], x[nd.r], c < 2 ? &steer : nullptr, x[nd.x_total],
                   x[nd.y_total], x[nd.kappa[c]]);
      out.kappa[c].push_back(x[nd.kappa[c]]);
      out.lambda[c].push_back(t.lambda);
      out.fz[c].push_back(t.fz);
      out.fx[c].push_back(t.fx);
      out.fy[c].push_back(t.fy);
    }
  }
  out.lap_time = time + 0.5 * b.ds * (x[b.nodes.back().w] + x[b.nodes.front().w]);
  return out;
}

}  // namespace hotlap::ocp
