#include "hotlap/ocp/lap_problem.h"
#include "hotlap/common/special_values.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <tuple>

#include <fmt/format.h>
#include <Eigen/Dense>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/ocp/element_nlp.h"
#include "hotlap/ocp/lap_elements.h"
#include "hotlap/ocp/tyre_force_element.h"

namespace hotlap::ocp {

namespace {

using internal::NodeRoad;
using vehicle::VehicleParams;

// Variable indices of one node.
struct NodeVars {
  int u, v, r, n, xi;
  std::array<int, 4> tread, carcass, wear, disc, calliper;
  int steer, pedal, power, brake;
  std::array<int, 4> kappa, alpha, vx, fz, fx, fy;
  int kappa_axle;
  int sum_fx, sum_fy, yaw_moment, w;
  // With a gas-and-rim tyre or a surface-and-bulk disc on the car (wheel_states): each wheel's rim
  // and disc bulk temperatures (states; fixed where the corner's model has none) and its tyre's
  // rolling-resistance force (an algebraic variable). -1 otherwise.
  bool wheel_states = false;
  std::array<int, 4> rim{-1, -1, -1, -1}, bulk{-1, -1, -1, -1}, roll{-1, -1, -1, -1};

  // The states, in defect order: the chassis's, five a corner (the paper's), then the wheel
  // states, two a corner (kWheelStatesBegin).
  std::vector<int> States() const {
    std::vector<int> s = {u, v, r, n, xi};
    for (int c = 0; c < 4; ++c) {
      s.insert(s.end(), {tread[c], carcass[c], wear[c], disc[c], calliper[c]});
    }
    if (wheel_states) {
      for (int c = 0; c < 4; ++c) s.insert(s.end(), {rim[c], bulk[c]});
    }
    return s;
  }
};

// Where the wheel states begin in NodeVars::States(): corner c's rim at kWheelStatesBegin + 2 c,
// its disc bulk one after.
constexpr int kWheelStatesBegin = 25;

// A node's value of a channel sampled on the QSS lap, by linear interpolation in distance.
double Sample(const std::vector<double>& distance, const std::vector<double>& values, double s) {
  const auto it = std::upper_bound(distance.begin(), distance.end(), s);
  if (it == distance.begin()) return values.front();
  if (it == distance.end()) return values.back();
  const size_t j = static_cast<size_t>(it - distance.begin());
  const double w = (s - distance[j - 1]) / (distance[j] - distance[j - 1]);
  return values[j - 1] + w * (values[j] - values[j - 1]);
}

// Node k's quadrature weight on a mesh of `intervals` steps, in units of the node spacing: the
// trapezoid's (1/2 at the ends, 1 elsewhere) or Simpson's (1/3 at the ends, 4/3 at an interval's
// midpoint, 2/3 where two intervals meet).
double NodeWeight(int k, int intervals, bool hermite_simpson) {
  const bool end = k == 0 || k == intervals;
  if (!hermite_simpson) return end ? 0.5 : 1.0;
  if (end) return 1.0 / 3.0;
  return k % 2 == 1 ? 4.0 / 3.0 : 2.0 / 3.0;
}

// LapProblemOptions::mesh_m checked: from 0 to the track's length (its last value set to it
// exactly), increasing, at least 17 nodes, the trapezoid only.
std::vector<double> CheckedMesh(const std::vector<double>& mesh_m, const track::Track& track,
                                Collocation collocation) {
  if (collocation != Collocation::kTrapezoid) {
    throw InputError("optimal lap: a non-uniform mesh needs the trapezoid collocation");
  }
  const double length = track.length_m();
  if (mesh_m.size() < 17 || mesh_m.front() != 0.0 || std::abs(mesh_m.back() - length) > 1e-6) {
    throw InputError(fmt::format(
        "optimal lap: a mesh of {} nodes from {:g} to {:g} m; expected at least 17 from 0 to the "
        "track's {:g} m",
        mesh_m.size(), mesh_m.empty() ? 0.0 : mesh_m.front(), mesh_m.empty() ? 0.0 : mesh_m.back(),
        length));
  }
  std::vector<double> out = mesh_m;
  out.back() = length;
  for (size_t k = 1; k < out.size(); ++k) {
    if (!(out[k] > out[k - 1])) {
      throw InputError(fmt::format("optimal lap: mesh node {} at {:g} m is not beyond {:g} m", k,
                                   out[k], out[k - 1]));
    }
  }
  return out;
}

struct Builder {
  const vehicle::Car& car;
  const VehicleParams& p;
  const track::Track& track;
  const LapProblemOptions& options;
  const sim::QssLap& guess;
  ElementNlp nlp;
  std::vector<NodeVars> nodes;
  std::vector<NodeRoad> roads;
  int intervals = 0;             // node to node (twice the Hermite-Simpson intervals)
  double ds = 0.0;               // node to node on a uniform mesh (the mean on another)
  std::vector<double> node_m;    // each node's distance along the centre line
  std::vector<double> h;         // each interval's length (trapezoid; all ds on a uniform mesh)
  bool uniform = true;           // no LapProblemOptions::mesh_m
  bool hs = false;               // Hermite-Simpson (else trapezoid)
  double max_brake_force = 0.0;  // N at pedal -1
  // Parameters (with the smooth |x| of tyre::TyreThermalSmoothing) cast once for the thermal
  // elements' scalars.
  std::array<tyre::TyreThermalParams<double>, 4> tyre_d;
  std::array<tyre::TyreThermalParams<SecondOrder<10>>, 4> tyre_so;
  std::array<tyre::TyreThermalParams<Jet10>, 4> tyre_jet;
  std::array<brake::BrakeThermalParams<double>, 4> brake_d;
  std::array<brake::BrakeThermalParams<SecondOrder<5>>, 4> brake_so;
  std::array<brake::BrakeThermalParams<Jet5>, 4> brake_jet;
  std::array<double, 4> rolling{};
  // The wheel elements' parameters (wheel_states only).
  bool wheel_states = false;
  std::array<internal::ParamsOn<tyre::TyreThermalParams, 15>, 4> wheel_tyre;
  std::array<internal::ParamsOn<brake::BrakeThermalParams, 15>, 4> wheel_brake;
  std::array<internal::ParamsOn<tyre::TyreThermalParams, 5>, 4> rolling_tyre;
  // Each lap's vehicle (a stint's: its chassis mass falls with the fuel burnt); one for a lap.
  std::deque<VehicleParams> lap_params;

  // The vehicle of node k (the elements keep its address: lap_params never moves).
  const VehicleParams& P(int k) const {
    if (lap_params.size() == 1) return lap_params.front();
    const double s = node_m[k] / track.length_m() * track.laps();
    const int lap = std::clamp(static_cast<int>(s), 0, static_cast<int>(lap_params.size()) - 1);
    return lap_params[lap];
  }

  Builder(const vehicle::Car& c, const VehicleParams& vp, const track::Track& t,
          const LapProblemOptions& o, const sim::QssLap& g)
      : car(c), p(vp), track(t), options(o), guess(g) {
    if (options.lap_mass_kg.empty()) {
      lap_params.push_back(p);
    } else {
      if (static_cast<int>(options.lap_mass_kg.size()) != track.laps()) {
        throw InputError(fmt::format("optimal lap: {} lap masses for a track of {} laps",
                                     options.lap_mass_kg.size(), track.laps()));
      }
      for (double m : options.lap_mass_kg) {
        if (!(m > 0.0)) throw InputError(fmt::format("optimal lap: a lap's mass is {} kg", m));
        lap_params.push_back(p);
        lap_params.back().chassis.mass = m;
      }
    }
    for (int k = 0; k < 4; ++k) {
      wheel_states =
          wheel_states || car.tyres[k].params.HasGasAndRim() || car.brakes[k].params.HasBulk();
    }
    for (int k = 0; k < 4; ++k) {
      tyre_d[k] = car.tyres[k].params;
      tyre_d[k].smoothing = options.thermal_smoothing;
      tyre_so[k] = tyre_d[k].Cast<SecondOrder<10>>();
      tyre_jet[k] = tyre_d[k].Cast<Jet10>();
      brake_d[k] = car.brakes[k].params;
      brake_so[k] = brake_d[k].Cast<SecondOrder<5>>();
      brake_jet[k] = brake_d[k].Cast<Jet5>();
      if (wheel_states) {
        wheel_tyre[k] = internal::ParamsOn<tyre::TyreThermalParams, 15>(tyre_d[k]);
        wheel_brake[k] = internal::ParamsOn<brake::BrakeThermalParams, 15>(brake_d[k]);
        rolling_tyre[k] = internal::ParamsOn<tyre::TyreThermalParams, 5>(tyre_d[k]);
      }
      // Rolling resistance as the QSS takes it: -My / (R Fz) at a quarter of the weight (a
      // gas-and-rim tyre's own, RollingForceFn, replaces it).
      rolling[k] = vehicle::CalcFreeRollingCoefficient(p.corners[k], 0.25 * p.Weight());
    }
  }

  // The pedal's split into drive power and brake force.
  internal::PedalSplitFn Split() const {
    return {p.powertrain.WheelPower(), max_brake_force, options.pedal_smoothing};
  }

  void AddNodes() {
    for (int c = 0; c < 4; ++c) {
      // A wheel's brake heats its rim (and a bulk disc has a state of its own): with wheel states
      // every brake is in the programme.
      brake_in_programme[c] = options.all_brake_states || options.periodic_thermal ||
                              (options.front_disc_limit && IsFront(kAllCorners[c])) || wheel_states;
    }
    hs = options.collocation == Collocation::kHermiteSimpson;
    uniform = options.mesh_m.empty();
    if (uniform) {
      intervals = LapNodeCount(track, options.step_m, options.collocation) - 1;
      ds = track.length_m() / intervals;
      for (int k = 0; k <= intervals; ++k) node_m.push_back(std::min(k * ds, track.length_m()));
      h.assign(intervals, ds);
    } else {
      node_m = CheckedMesh(options.mesh_m, track, options.collocation);
      intervals = static_cast<int>(node_m.size()) - 1;
      ds = track.length_m() / intervals;
      for (int k = 0; k < intervals; ++k) h.push_back(node_m[k + 1] - node_m[k]);
    }
    max_brake_force = options.max_brake_force > 0.0 ? options.max_brake_force : 2.0 * p.Weight();
    for (int k = 0; k <= intervals; ++k) {
      const double s = node_m[k];
      const track::TrackPoint tp = track.At(k == intervals ? 0.0 : s);
      roads.push_back({tp.curvature_per_m, tp.bank_rad, tp.grade_rad});
      // The guess is indexed by centre-line distance (its path may be a racing line).
      const double g_s = std::min(s, guess.centre_distance.back());
      const auto at = [&](const std::vector<double>& v) {
        return Sample(guess.centre_distance, v, g_s);
      };
      const double speed = std::max(at(guess.speed), 10.0);
      NodeVars nv;
      AddMechanicalStates(s, tp, g_s, speed, at, nv);
      AddThermalStates(k, g_s, nv);
      // Controls from the QSS lap's forces.
      double total_fx = 0.0;
      for (int c = 0; c < 4; ++c) total_fx += at(guess.corners[c].fx);
      AddControls(speed, total_fx, at, nv);
      AddAlgebraicVariables(speed, total_fx, at, nv);
      if (wheel_states) AddWheelVariables(k, nv, at);
      nodes.push_back(nv);
    }
  }

  // A node's mechanical states at distance s (track point tp, the guess's g_s), from the guess.
  template <class At>
  void AddMechanicalStates(double s, const track::TrackPoint& tp, double g_s, double speed,
                           const At& at, NodeVars& nv) {
    nv.u = nlp.AddVariable(speed, 5.0, 150.0, 50.0);
    nv.v = nlp.AddVariable(0.0, -20.0, 20.0, 1.0);
    nv.r = nlp.AddVariable(speed * roads.back().kappa_g(), -3.0, 3.0, 0.3);
    const double n_max = tp.width_left_m - options.car_half_width;
    const double n_min = -(tp.width_right_m - options.car_half_width);
    if (!(n_max > n_min)) {
      throw InputError(
          fmt::format("optimal lap: the track at {:.0f} m is narrower than the car ({:.2f} m)", s,
                      2.0 * options.car_half_width));
    }
    nv.n = nlp.AddVariable(std::clamp(at(guess.offset), n_min, n_max), n_min, n_max, 5.0);
    // Heading error of the guess's line: atan(dn/ds) (the offset's slope).
    const double dn = (Sample(guess.centre_distance, guess.offset,
                              std::min(g_s + 1.0, guess.centre_distance.back())) -
                       Sample(guess.centre_distance, guess.offset, std::max(g_s - 1.0, 0.0))) /
                      2.0;
    nv.xi = nlp.AddVariable(std::atan(dn), -1.0, 1.0, 0.05);
  }

  // Node k's thermal states: the start's fixed (unless periodic), the rest from the QSS replay
  // (at the guess's distance g_s).
  void AddThermalStates(int k, double g_s, NodeVars& nv) {
    for (int c = 0; c < 4; ++c) {
      const sim::CornerHistory& h = guess.thermal.corners[c];
      const bool fix = k == 0 && !options.periodic_thermal;
      const auto state = [&](const std::vector<double>& hist, double start, double lo, double hi,
                             double scale, bool in_programme = true,
                             std::optional<bool> fixed_start = std::nullopt) {
        const double value = k == 0 ? start : Sample(guess.centre_distance, hist, g_s);
        // A state left out of the programme is a fixed variable: Ipopt leaves it out of its
        // programme, and it is integrated after the solve (IntegrateBrakesLeftOut,
        // IntegrateWearLeftOut).
        if (!in_programme) return nlp.AddVariable(value, value, value, scale);
        const bool fixed = fixed_start.value_or(fix);
        return nlp.AddVariable(value, fixed ? start : lo, fixed ? start : hi, scale);
      };
      nv.tread[c] = state(h.tread_temp, options.initial.tyres[c].tread_temp, 200.0, 800.0, 100.0);
      nv.carcass[c] =
          state(h.carcass_temp, options.initial.tyres[c].carcass_temp, 200.0, 800.0, 100.0);
      // The wear starts at `initial` even on a periodic lap: it only grows.
      nv.wear[c] = state(h.wear, options.initial.tyres[c].wear, 0.0, 50.0, 0.01,
                         options.wear_in_programme, k == 0);
      double disc_hi = 2000.0;
      if (options.front_disc_limit && IsFront(kAllCorners[c])) disc_hi = *options.front_disc_limit;
      const bool in = brake_in_programme[c];
      nv.disc[c] =
          state(h.disc_temp, options.initial.brakes[c].disc_temp, 200.0, disc_hi, 100.0, in);
      if (!fix && in) {
        nlp.set_initial(nv.disc[c], std::min(nlp.initial(nv.disc[c]), disc_hi - 1.0));
      }
      nv.calliper[c] =
          state(h.calliper_temp, options.initial.brakes[c].calliper_temp, 200.0, 2000.0, 100.0, in);
    }
  }

  // A node's controls from the QSS lap's forces (total_fx their sum).
  template <class At>
  void AddControls(double speed, double total_fx, const At& at, NodeVars& nv) {
    const double wheel_power = p.powertrain.WheelPower();
    nv.steer = nlp.AddVariable(at(guess.steer), -0.5, 0.5, 0.05);
    // The pedal: the QSS lap's drive power or braking force as a fraction of its range.
    const double power0 = std::clamp(total_fx * speed, 0.0, wheel_power);
    const double brake0 = std::clamp(-total_fx, 0.0, max_brake_force);
    const double pedal0 = power0 > 0.0 ? power0 / wheel_power : -brake0 / max_brake_force;
    const bool pedal = !options.independent_drive_and_brake;
    nv.pedal = nlp.AddVariable(pedal ? pedal0 : 0.0, pedal ? -1.0 : 0.0, pedal ? 1.0 : 0.0, 0.5);
    const internal::PedalSplitFn split = Split();
    // Their range is the pedal's, bounds of their own none: pos() > 0 keeps them positive, and
    // a bound would nearly coincide with the pedal's (the upper) or with the defining equation
    // (the lower: off the pedal, P = P_max eps^2 / (4 |p|) is a few watts above 0). Nearly
    // parallel active constraints drive Ipopt's multipliers to 1e15 and stall the solve.
    const double lo = pedal ? -kInf : 0.0;
    nv.power = nlp.AddVariable(wheel_power * split.Pos(pedal0, split.eps), lo,
                               pedal ? kInf : wheel_power, 2e5);
    nv.brake = nlp.AddVariable(max_brake_force * split.Pos(-pedal0, split.eps), lo,
                               pedal ? kInf : max_brake_force, 1e4);
  }

  // A node's algebraic variables: the tyres' slips, speeds and forces, the spool's slip and the
  // force and moment sums, from the QSS lap (total_fx its longitudinal force).
  template <class At>
  void AddAlgebraicVariables(double speed, double total_fx, const At& at, NodeVars& nv) {
    const double r_mean = 0.5 * (p.corner(Corner::kRearLeft).rolling_radius +
                                 p.corner(Corner::kRearRight).rolling_radius);
    for (int c = 0; c < 4; ++c) {
      const sim::CornerChannels& ch = guess.corners[c];
      nv.kappa[c] = nlp.AddVariable(at(ch.slip_ratio), -0.6, 0.6, 0.05);
      nv.alpha[c] = nlp.AddVariable(
          std::clamp(at(ch.slip_angle), -options.max_slip_angle, options.max_slip_angle),
          -options.max_slip_angle, options.max_slip_angle, 0.05);
      nv.vx[c] = nlp.AddVariable(at(ch.speed), 1.0, 160.0, 50.0);
      nv.fz[c] = nlp.AddVariable(at(ch.fz), 0.0, 40000.0, 5000.0);
      nv.fx[c] = nlp.AddVariable(at(ch.fx), -40000.0, 40000.0, 5000.0);
      nv.fy[c] = nlp.AddVariable(at(ch.fy), -40000.0, 40000.0, 5000.0);
    }
    {
      const sim::CornerChannels& rl = guess.corners[CornerIndex(Corner::kRearLeft)];
      const double axle = (1.0 + at(rl.slip_ratio)) * at(rl.speed) /
                              p.corner(Corner::kRearLeft).rolling_radius * r_mean / speed -
                          1.0;
      nv.kappa_axle = nlp.AddVariable(axle, -0.6, 0.6, 0.05);
    }
    double fy_total = 0.0;
    for (int c = 0; c < 4; ++c) fy_total += at(guess.corners[c].fy);
    nv.sum_fx = nlp.AddVariable(total_fx, -kInf, kInf, 1e4);
    nv.sum_fy = nlp.AddVariable(fy_total, -kInf, kInf, 1e4);
    nv.yaw_moment = nlp.AddVariable(0.0, -kInf, kInf, 1e4);
    nv.w = nlp.AddVariable(1.0 / speed, 1.0 / 150.0, 1.0 / 3.0, 0.015);
  }

  // Node k's wheel states (rim, disc bulk: fixed at the start's value where the corner's model
  // has none) and rolling-resistance forces; `at` samples a guess channel at the node.
  template <class At>
  void AddWheelVariables(int k, NodeVars& nv, const At& at) {
    nv.wheel_states = true;
    const bool fix = k == 0 && !options.periodic_thermal;
    for (int c = 0; c < 4; ++c) {
      const sim::CornerHistory& h = guess.thermal.corners[c];
      const auto state = [&](const std::vector<double>& hist, double start, bool has) {
        const double value = k == 0 || hist.empty() || !has ? start : at(hist);
        if (!has || fix) return nlp.AddVariable(value, value, value, 100.0);
        return nlp.AddVariable(value, 200.0, 2000.0, 100.0);
      };
      nv.rim[c] =
          state(h.rim_temp, options.initial.tyres[c].rim_temp, car.tyres[c].params.HasGasAndRim());
      nv.bulk[c] = state(h.disc_bulk_temp, options.initial.brakes[c].bulk_temp,
                         car.brakes[c].params.HasBulk());
      const double roll0 = (h.rolling_resistance.empty() ? rolling[c] : at(h.rolling_resistance)) *
                           at(guess.corners[c].fz);
      nv.roll[c] = nlp.AddVariable(roll0, -kInf, kInf, 100.0);
    }
  }

  // Node k's rolling-resistance forces: a gas-and-rim tyre's from its carcass and rim
  // (RollingForceFn), a paper tyre's the vehicle model's coefficient times its load.
  void AddRollingEquations(int k) {
    const NodeVars& nv = nodes[k];
    for (int c = 0; c < 4; ++c) {
      const int row = nlp.AddConstraint(0, 0, 100.0);
      if (car.tyres[c].params.HasGasAndRim()) {
        nlp.AddElement(MakeElement<5, 1>(internal::RollingForceFn{&rolling_tyre[c]}),
                       {nv.carcass[c], nv.rim[c], nv.vx[c], nv.fz[c], nv.roll[c]}, {{{row, 1.0}}});
      } else {
        nlp.AddLinear(row, nv.roll[c], 1.0);
        nlp.AddLinear(row, nv.fz[c], -rolling[c]);
      }
    }
  }

  // The algebraic equations of node k.
  void AddNodeEquations(int k) {
    const NodeVars& nv = nodes[k];
    const NodeRoad& road = roads[k];
    const double beta = p.brakes.front_share;
    const double r_mean = 0.5 * (p.corner(Corner::kRearLeft).rolling_radius +
                                 p.corner(Corner::kRearRight).rolling_radius);
    for (Corner c : kAllCorners) {
      const int i = CornerIndex(c);
      // Slip angle and wheel speed.
      const int ra = nlp.AddConstraint(0, 0, 0.05), rv = nlp.AddConstraint(0, 0, 10.0);
      nlp.AddElement(MakeElement<6, 2>(internal::KinematicsFn{&P(k), c}),
                     {nv.u, nv.v, nv.r, nv.steer, nv.alpha[i], nv.vx[i]},
                     {{{ra, 1.0}}, {{rv, 1.0}}});
      // Tyre forces.
      const int rfx = nlp.AddConstraint(0, 0, 5000.0), rfy = nlp.AddConstraint(0, 0, 5000.0);
      nlp.AddElement(
          tyre_elements[i],
          {nv.fz[i], nv.kappa[i], nv.alpha[i], nv.tread[i], nv.wear[i], nv.fx[i], nv.fy[i]},
          {{{rfx, 1.0}}, {{rfy, 1.0}}});
      if (IsFront(c)) {
        // Each front wheel brakes with beta B / 2 and is not driven.
        const int rb = nlp.AddConstraint(0, 0, 5000.0);
        nlp.AddLinear(rb, nv.fx[i], 1.0);
        nlp.AddLinear(rb, nv.brake, 0.5 * beta);
      } else {
        // Rear wheels on the spool.
        const int rs = nlp.AddConstraint(0, 0, 1.0);
        nlp.AddElement(MakeElement<4, 1>(internal::SpoolFn{p.corners[i].rolling_radius / r_mean}),
                       {nv.kappa[i], nv.vx[i], nv.kappa_axle, nv.u}, {{{rs, 1.0}}});
      }
    }
    if (!options.independent_drive_and_brake) {
      // Drive power and brake force from the one pedal.
      const int rp = nlp.AddConstraint(0, 0, 2e5), rb = nlp.AddConstraint(0, 0, 1e4);
      nlp.AddElement(MakeElement<3, 2>(Split()), {nv.pedal, nv.power, nv.brake},
                     {{{rp, 1.0}}, {{rb, 1.0}}});
    }
    {
      const int rd = nlp.AddConstraint(0, 0, 1e5);
      const int l = CornerIndex(Corner::kRearLeft), r = CornerIndex(Corner::kRearRight);
      nlp.AddElement(MakeElement<6, 1>(internal::RearDriveFn{1.0 - beta}),
                     {nv.fx[l], nv.fx[r], nv.brake, nv.u, nv.kappa_axle, nv.power}, {{{rd, 1.0}}});
    }
    // Totals.
    {
      const int rx = nlp.AddConstraint(0, 0, 1e4), ry = nlp.AddConstraint(0, 0, 1e4),
                rm = nlp.AddConstraint(0, 0, 1e4);
      nlp.AddLinear(rx, nv.sum_fx, 1.0);
      nlp.AddLinear(ry, nv.sum_fy, 1.0);
      nlp.AddLinear(rm, nv.yaw_moment, 1.0);
      std::vector<int> in = {nv.steer};
      for (int i = 0; i < 4; ++i) in.push_back(nv.fx[i]);
      for (int i = 0; i < 4; ++i) in.push_back(nv.fy[i]);
      nlp.AddElement(MakeElement<9, 3>(internal::TotalsFn{&P(k)}), in,
                     {{{rx, -1.0}}, {{ry, -1.0}}, {{rm, -1.0}}});
    }
    // Normal loads.
    {
      std::vector<std::vector<Target>> targets;
      for (int i = 0; i < 4; ++i) {
        const int rz = nlp.AddConstraint(0, 0, 5000.0);
        nlp.AddLinear(rz, nv.fz[i], 1.0);
        targets.push_back({{rz, -1.0}});
      }
      nlp.AddElement(MakeElement<5, 4>(internal::LoadsFn{&P(k), road}),
                     {nv.u, nv.v, nv.n, nv.sum_fx, nv.sum_fy}, targets);
    }
    // dt/ds.
    {
      const int rt = nlp.AddConstraint(0, 0, 1.0);
      nlp.AddElement(MakeElement<5, 1>(internal::TimeFn{road.kappa_g()}),
                     {nv.w, nv.u, nv.v, nv.n, nv.xi}, {{{rt, 1.0}}});
    }
    if (wheel_states) AddRollingEquations(k);
  }

  // Rows of the state derivatives f_j(node k) feed. Trapezoid: the defects of intervals k-1 and
  // k with coefficient -ds/2. Hermite-Simpson (h = 2 ds, the defect rows of node step 2i its
  // interval's Hermite rows, of step 2i + 1 its Simpson rows): an interval's ends feed its
  // Simpson rows with -h/6 and its Hermite rows with -h/8 (first node) and +h/8 (last node), its
  // midpoint its Simpson rows with -4h/6.
  std::vector<Target> DefectTargets(int k, int state) const {
    std::vector<Target> t;
    if (!state_in_programme[state]) return t;  // a state left out: its rate feeds nothing
    if (!hs) {
      if (k > 0) t.push_back({defect_rows[k - 1][state], -0.5 * h[k - 1]});
      if (k < intervals) t.push_back({defect_rows[k][state], -0.5 * h[k]});
      return t;
    }
    const double hh = 2.0 * ds;
    if (k % 2 == 1) {
      t.push_back({defect_rows[k][state], -4.0 * hh / 6.0});
      return t;
    }
    if (k > 0) {  // the last node of the interval before
      t.push_back({defect_rows[k - 2][state], hh / 8.0});
      t.push_back({defect_rows[k - 1][state], -hh / 6.0});
    }
    if (k < intervals) {  // the first node of the interval after
      t.push_back({defect_rows[k][state], -hh / 8.0});
      t.push_back({defect_rows[k + 1][state], -hh / 6.0});
    }
    return t;
  }

  void AddDynamics() {
    const int n_states = static_cast<int>(nodes[0].States().size());
    // Defect rows x_{k+1} - x_k - ds/2 (f_k + f_{k+1}) = c, c from the road's -kappa_g terms; none
    // for the brakes left out of the programme (-1).
    state_in_programme.assign(n_states, true);
    for (int c = 0; c < 4; ++c) {
      state_in_programme[5 + 5 * c + 3] = state_in_programme[5 + 5 * c + 4] = brake_in_programme[c];
      state_in_programme[5 + 5 * c + 2] = options.wear_in_programme;
      if (wheel_states) {
        state_in_programme[kWheelStatesBegin + 2 * c] = car.tyres[c].params.HasGasAndRim();
        state_in_programme[kWheelStatesBegin + 2 * c + 1] = car.brakes[c].params.HasBulk();
      }
    }
    defect_rows.assign(intervals, std::vector<int>(n_states, -1));
    for (int k = 0; k < intervals; ++k) {
      // Trapezoid: x_{k+1} - x_k. Hermite-Simpson: step k = 2i holds the Hermite rows
      // x_m - (x_a + x_b) / 2, step 2i + 1 the Simpson rows x_b - x_a (a, m, b: the interval's
      // first node, midpoint and last node).
      const bool hermite = hs && k % 2 == 0;
      const int first = hs ? k - k % 2 : k;
      const std::vector<int> a = nodes[first].States(), m = nodes[first + 1].States(),
                             b = nodes[hs ? first + 2 : k + 1].States();
      for (int j = 0; j < n_states; ++j) {
        if (!state_in_programme[j]) continue;
        // dxi/ds = w r - kappa_g: the constant moves to the right-hand side.
        double rhs = 0.0;
        if (j == 4) {
          const double ka = roads[first].kappa_g(), kb = roads[hs ? first + 2 : k + 1].kappa_g();
          const double hh = 2.0 * ds;
          if (!hs)
            rhs = -0.5 * h[k] * (ka + kb);
          else if (hermite)
            rhs = -hh / 8.0 * (ka - kb);
          else
            rhs = -hh / 6.0 * (ka + 4.0 * roads[first + 1].kappa_g() + kb);
        }
        const double scale = nlp.scale(a[j]);
        const int row = nlp.AddConstraint(rhs, rhs, scale);
        if (hermite) {
          nlp.AddLinear(row, m[j], 1.0);
          nlp.AddLinear(row, a[j], -0.5);
          nlp.AddLinear(row, b[j], -0.5);
        } else {
          nlp.AddLinear(row, b[j], 1.0);
          nlp.AddLinear(row, a[j], -1.0);
        }
        defect_rows[k][j] = row;
      }
    }
    const double inv_iz = 1.0 / p.chassis.yaw_inertia;
    rate_terms.assign(intervals + 1, {});
    for (int k = 0; k <= intervals; ++k) {
      const NodeVars& nv = nodes[k];
      const NodeRoad& road = roads[k];
      if (wheel_states) {
        // The rolling-resistance forces themselves (coefficient 1).
        AddRates(k, MakeElement<10, 1>(internal::LongitudinalFn{&P(k), road, {1, 1, 1, 1}}),
                 {nv.w, nv.sum_fx, nv.u, nv.v, nv.r, nv.xi, nv.roll[0], nv.roll[1], nv.roll[2],
                  nv.roll[3]},
                 {0});
      } else {
        AddRates(k, MakeElement<10, 1>(internal::LongitudinalFn{&P(k), road, rolling}),
                 {nv.w, nv.sum_fx, nv.u, nv.v, nv.r, nv.xi, nv.fz[0], nv.fz[1], nv.fz[2], nv.fz[3]},
                 {0});
      }
      AddRates(k, MakeElement<5, 1>(internal::LateralFn{&P(k), road}),
               {nv.w, nv.sum_fy, nv.u, nv.r, nv.xi}, {1});
      AddRates(k, MakeElement<2, 1>(internal::ScaledProductFn{inv_iz}), {nv.w, nv.yaw_moment}, {2});
      AddRates(k, MakeElement<4, 1>(internal::OffsetFn{}), {nv.w, nv.u, nv.v, nv.xi}, {3});
      AddRates(k, MakeElement<2, 1>(internal::ScaledProductFn{1.0}), {nv.w, nv.r}, {4});
      for (int c = 0; c < 4; ++c) {
        const int base = 5 + 5 * c;
        if (wheel_states) {
          const int wheel = kWheelStatesBegin + 2 * c;
          AddRates(k, wheel_elements[c], WheelInputs(nv, c),
                   {base, base + 1, base + 2, wheel, base + 3, base + 4, wheel + 1});
          continue;
        }
        AddRates(k, thermal_elements[c],
                 {nv.w, nv.tread[c], nv.carcass[c], nv.wear[c], nv.vx[c], nv.fx[c], nv.fy[c],
                  nv.fz[c], nv.alpha[c], nv.kappa[c]},
                 {base, base + 1, base + 2});
        if (!brake_in_programme[c]) continue;
        AddRates(k, brake_elements[c], {nv.w, nv.disc[c], nv.calliper[c], nv.vx[c], nv.brake},
                 {base + 3, base + 4});
      }
    }
  }

  // An element whose outputs are the rates d/ds of the states `states` (positions in
  // NodeVars::States()) at node k: added to the defects and kept for NodeRates.
  void AddRates(int k, std::shared_ptr<const Element> element, std::vector<int> inputs,
                const std::vector<int>& states) {
    std::vector<std::vector<Target>> targets;
    for (int j : states) targets.push_back(DefectTargets(k, j));
    rate_terms[k].push_back({element, inputs, states});
    nlp.AddElement(std::move(element), std::move(inputs), std::move(targets));
  }

  // The rates d/ds of every state at node k of the point x, in NodeVars::States() order (the
  // heading error's with its road term -kappa_g, which the defects carry on their right-hand
  // side).
  std::vector<double> NodeRates(int k, const std::vector<double>& x) const {
    std::vector<double> f(state_in_programme.size(), 0.0), in, out;
    for (const RateTerm& t : rate_terms[k]) {
      in.clear();
      for (int i : t.inputs) in.push_back(x[i]);
      out.assign(t.states.size(), 0.0);
      t.element->Values(in.data(), out.data());
      for (size_t o = 0; o < t.states.size(); ++o) f[t.states[o]] += out[o];
    }
    f[4] -= roads[k].kappa_g();
    return f;
  }

  // The trapezoid's rates and costates at the solution (x, lambda in the layout's rows) for the
  // mesh error estimate (ocp/mesh_error.h).
  CollocationRates Rates(const std::vector<double>& x, const std::vector<double>& lambda) const {
    CollocationRates r;
    if (hs) return r;
    r.node_m = node_m;
    r.states = static_cast<int>(state_in_programme.size());
    const std::vector<int> first = nodes[0].States();
    for (int k = 0; k <= intervals; ++k) {
      const std::vector<double> f = NodeRates(k, x);
      r.rates.insert(r.rates.end(), f.begin(), f.end());
      r.dt_ds.push_back(x[nodes[k].w]);
    }
    const int defects_begin = layout.nodes * layout.rows_per_node;
    const bool have_lambda = lambda.size() == static_cast<size_t>(layout.rows());
    for (int k = 0; k < intervals; ++k) {
      for (int j = 0; j < r.states; ++j) {
        // The physical multiplier: the scaled row's over its scale (the state's).
        const double l =
            have_lambda ? lambda[defects_begin + k * layout.defects_per_interval + j] : 0.0;
        r.costates.push_back(state_in_programme[j] ? l / nlp.scale(first[j]) : 0.0);
      }
    }
    return r;
  }

  // The variables of corner c's wheel element (internal::WheelThermalFn) at node nv.
  static std::vector<int> WheelInputs(const NodeVars& nv, int c) {
    return {nv.w,        nv.tread[c], nv.carcass[c],  nv.wear[c], nv.rim[c],
            nv.vx[c],    nv.fx[c],    nv.fy[c],       nv.fz[c],   nv.alpha[c],
            nv.kappa[c], nv.disc[c],  nv.calliper[c], nv.bulk[c], nv.brake};
  }

  // |c_{k+1} - c_k| <= rate ds (w_k + w_{k+1}) / 2 for the control `c` (no limit if rate <= 0).
  void AddRateLimit(int NodeVars::*control, double rate, double row_scale) {
    if (!(rate > 0.0)) return;
    for (int k = 0; k < intervals; ++k) {
      const double c = 0.5 * h[k] * rate;
      const int up = nlp.AddConstraint(-kInf, 0.0, row_scale),
                down = nlp.AddConstraint(0.0, kInf, row_scale);
      for (const int row : {up, down}) {
        const double sign = row == up ? -1.0 : 1.0;
        nlp.AddLinear(row, nodes[k + 1].*control, 1.0);
        nlp.AddLinear(row, nodes[k].*control, -1.0);
        nlp.AddLinear(row, nodes[k].w, sign * c);
        nlp.AddLinear(row, nodes[k + 1].w, sign * c);
      }
    }
  }

  void AddPeriodicityAndObjective() {
    // The lap closes: mechanical states (and the temperatures on request, not the wear, which
    // only grows) end where they start.
    std::vector<int> periodic = {0, 1, 2, 3, 4};
    if (options.periodic_thermal) {
      for (int j = 5; j < static_cast<int>(nodes[0].States().size()); ++j) {
        const bool wear = j < kWheelStatesBegin && (j - 5) % 5 == 2;
        if (!wear && state_in_programme[j]) periodic.push_back(j);
      }
    }
    const std::vector<int> a = nodes.front().States(), b = nodes.back().States();
    for (int j : periodic) {
      const int row = nlp.AddConstraint(0, 0, nlp.scale(a[j]));
      nlp.AddLinear(row, b[j], 1.0);
      nlp.AddLinear(row, a[j], -1.0);
    }
    layout.closure_rows = static_cast<int>(periodic.size());
    // The driver's hands and feet: |c_{k+1} - c_k| <= rate * dt, dt = ds (w_k + w_k+1) / 2.
    AddRateLimit(&NodeVars::steer, options.max_steer_rate, 0.01);
    if (!options.independent_drive_and_brake) {
      AddRateLimit(&NodeVars::pedal, options.max_pedal_rate, 0.1);
    }
    // Lap time: the trapezoid of dt/ds, or Simpson's rule.
    for (int k = 0; k <= intervals; ++k) nlp.AddObjectiveLinear(nodes[k].w, Weight(k));
    // Smooth controls: weight * sum ((c_{k+1} - c_k) / scale)^2 per control.
    const double spacing = hs ? 0.5 * options.step_m : options.step_m;
    const double pedal_weight = options.pedal_smoothing_weight >= 0.0
                                    ? options.pedal_smoothing_weight
                                    : options.smoothing * std::pow(spacing / 3.0, 2);
    const double steer_weight =
        options.steer_smoothing_weight >= 0.0 ? options.steer_smoothing_weight : options.smoothing;
    for (int k = 0; k < intervals; ++k) {
      // On a non-uniform mesh the pedal's weight follows each interval's own length, and the
      // steer's is the 3 m mesh's times 3 m / h: the penalty is then the same integral of the
      // squared steer rate on every mesh (a uniform mesh's, with a weight that does not change
      // with the spacing, falls with it, and moves the lap at first order in the spacing).
      const double pedal_k = uniform || options.pedal_smoothing_weight >= 0.0
                                 ? pedal_weight
                                 : options.smoothing * std::pow(h[k] / 3.0, 2);
      const double steer_k = uniform ? steer_weight : steer_weight * 3.0 / h[k];
      for (const auto& [a_var, b_var, weight] :
           {std::tuple{nodes[k].steer, nodes[k + 1].steer, steer_k},
            std::tuple{nodes[k].pedal, nodes[k + 1].pedal, pedal_k},
            std::tuple{nodes[k].power, nodes[k + 1].power,
                       options.independent_drive_and_brake ? options.smoothing : 0.0},
            std::tuple{nodes[k].brake, nodes[k + 1].brake,
                       options.independent_drive_and_brake ? options.smoothing : 0.0}}) {
        if (!(weight > 0.0)) continue;
        const double s = nlp.scale(a_var);
        nlp.AddElement(MakeElement<2, 1>(internal::RateFn{weight / (s * s)}), {a_var, b_var},
                       {{{Target::kObjective, 1.0}}});
      }
    }
    nlp.SetObjectiveScale(1.0);
    nlp.SetConvexElementHessians(options.convex_element_hessians);
    nlp.SetThreads(options.derivative_threads);
  }

  // Node k's quadrature weight, m (the trapezoid's or Simpson's).
  double Weight(int k) const {
    if (hs) return NodeWeight(k, intervals, hs) * ds;
    return (k > 0 ? 0.5 * h[k - 1] : 0.0) + (k < intervals ? 0.5 * h[k] : 0.0);
  }

  void Build() {
    AddNodes();
    for (int c = 0; c < 4; ++c) {
      const Corner corner = kAllCorners[c];
      const vehicle::CornerSetup& setup = p.corner(corner);
      tyre_elements[c] =
          std::make_shared<TyreForceElement>(setup, *car.tyre(corner).compound, 50.0);
      thermal_elements[c] = MakeElement<10, 3>(internal::TyreThermalFn{
          &tyre_d[c], &tyre_so[c], &tyre_jet[c], car.tyres[c].compound.get(), options.ambient_temp,
          options.track_temp});
      const double share =
          IsFront(corner) ? 0.5 * p.brakes.front_share : 0.5 * (1.0 - p.brakes.front_share);
      brake_fns[c] = std::make_shared<internal::BrakeFn>(
          internal::BrakeFn{&brake_d[c], &brake_so[c], &brake_jet[c], share, options.ambient_temp});
      brake_elements[c] = MakeElement<5, 2>(*brake_fns[c]);
      if (wheel_states) {
        wheel_elements[c] = MakeElement<15, 7>(
            internal::WheelThermalFn{&wheel_tyre[c], &wheel_brake[c], car.tyres[c].compound.get(),
                                     share, options.ambient_temp, options.track_temp});
      }
    }
    layout.nodes = intervals + 1;
    layout.collocation = options.collocation;
    if (!uniform) layout.mesh_m = node_m;
    layout.vars_per_node = nlp.variables() / layout.nodes;
    for (int k = 0; k <= intervals; ++k) AddNodeEquations(k);
    layout.rows_per_node = nlp.constraints() / layout.nodes;
    AddDynamics();
    layout.defects_per_interval = static_cast<int>(nodes[0].States().size());
    defects_left_out =
        static_cast<int>(std::count(state_in_programme.begin(), state_in_programme.end(), false));
    const int before_closure = nlp.constraints();
    AddPeriodicityAndObjective();
    // The closure's rows come first, then the rate limits' pairs per interval.
    layout.rate_blocks =
        (nlp.constraints() - before_closure - layout.closure_rows) / (2 * intervals);
    if (layout.rows() - intervals * defects_left_out != nlp.constraints() ||
        layout.variables() != nlp.variables()) {
      throw std::logic_error("lap problem: rows or variables out of their layout");
    }
    nlp.Finalize();
  }

  std::array<std::shared_ptr<const Element>, 4> tyre_elements, thermal_elements, brake_elements,
      wheel_elements;
  std::array<std::shared_ptr<const internal::BrakeFn>, 4> brake_fns;
  std::vector<std::vector<int>> defect_rows;
  // The elements of each node's state rates (AddRates).
  struct RateTerm {
    std::shared_ptr<const Element> element;
    std::vector<int> inputs, states;
  };
  std::vector<std::vector<RateTerm>> rate_terms;
  std::array<bool, 4> brake_in_programme{};
  std::vector<bool> state_in_programme;  // by position in NodeVars::States()
  int defects_left_out = 0;              // per interval
  LapLayout layout;

  // The programme's rows and the layout's (which has every state's defects) from one another.
  // Node rows come first in both, and the rows after the defects keep their order.
  int LayoutRowOf(int row) const {
    const int defects_begin = layout.nodes * layout.rows_per_node;
    const int programme_defects = intervals * (layout.defects_per_interval - defects_left_out);
    if (row < defects_begin) return row;
    if (row >= defects_begin + programme_defects) return row + intervals * defects_left_out;
    const int present = layout.defects_per_interval - defects_left_out;
    const int k = (row - defects_begin) / present, i = (row - defects_begin) % present;
    int j = -1;
    for (int seen = -1; seen < i;) seen += state_in_programme[++j] ? 1 : 0;
    return defects_begin + k * layout.defects_per_interval + j;
  }
  std::vector<double> ToLayoutRows(const std::vector<double>& programme) const {
    std::vector<double> out(layout.rows(), 0.0);
    for (size_t r = 0; r < programme.size(); ++r)
      out[LayoutRowOf(static_cast<int>(r))] = programme[r];
    return out;
  }
  std::vector<double> ToProgrammeRows(const std::vector<double>& full) const {
    std::vector<double> out(nlp.constraints());
    for (size_t r = 0; r < out.size(); ++r) out[r] = full[LayoutRowOf(static_cast<int>(r))];
    return out;
  }

  // The tyres' wear left out of the programme, integrated over the solution `x` by the
  // collocation its defects would have imposed, from the start's wear. Its rate does not depend
  // on the wear (000:23), so each step is explicit.
  void IntegrateWearLeftOut(std::vector<double>& x) const {
    if (options.wear_in_programme) return;
    std::vector<double> rate(intervals + 1);
    for (int c = 0; c < 4; ++c) {
      for (int k = 0; k <= intervals; ++k) {
        const NodeVars& nv = nodes[k];
        if (wheel_states) {
          std::vector<double> in;
          for (int i : WheelInputs(nv, c)) in.push_back(x[i]);
          double out[7];
          wheel_elements[c]->Values(in.data(), out);
          rate[k] = out[2];  // d wear / ds
          continue;
        }
        const double in[10] = {x[nv.w],        x[nv.tread[c]], x[nv.carcass[c]], x[nv.wear[c]],
                               x[nv.vx[c]],    x[nv.fx[c]],    x[nv.fy[c]],      x[nv.fz[c]],
                               x[nv.alpha[c]], x[nv.kappa[c]]};
        double out[3];
        thermal_elements[c]->Values(in, out);
        rate[k] = out[2];  // d wear / ds
      }
      const auto wear = [&](int k) -> double& { return x[nodes[k].wear[c]]; };
      wear(0) = options.initial.tyres[c].wear;
      if (hs) {
        const double hh = 2.0 * ds;
        for (int a = 0; a + 2 <= intervals; a += 2) {
          wear(a + 2) =
              wear(a) + hh / 6.0 * (rate[a] + 4.0 * rate[a + 1] + rate[a + 2]);  // Simpson
          wear(a + 1) =
              0.5 * (wear(a) + wear(a + 2)) + hh / 8.0 * (rate[a] - rate[a + 2]);  // Hermite
        }
        continue;
      }
      for (int k = 0; k < intervals; ++k)
        wear(k + 1) = wear(k) + 0.5 * h[k] * (rate[k] + rate[k + 1]);
    }
  }

  // Brake c's dT/ds (disc, calliper) at node k of the point x with temperatures y, and its
  // Jacobian in y if `jac`.
  Eigen::Vector2d BrakeRate(int c, const std::vector<double>& x, int k, const Eigen::Vector2d& y,
                            Eigen::Matrix2d* jac) const {
    const NodeVars& nv = nodes[k];
    Jet5 in[5] = {Jet5(x[nv.w]), Jet5(y[0], 0), Jet5(y[1], 1), Jet5(x[nv.vx[c]]),
                  Jet5(x[nv.brake])};
    Jet5 out[2];
    (*brake_fns[c])(in, out);
    if (jac) *jac << out[0].v[0], out[0].v[1], out[1].v[0], out[1].v[1];
    return {out[0].a, out[1].a};
  }
  void SetBrake(int c, int k, const Eigen::Vector2d& y, std::vector<double>& x) const {
    x[nodes[k].disc[c]] = y[0];
    x[nodes[k].calliper[c]] = y[1];
  }

  // The brakes left out of the programme, integrated node by node over the solution `x` by the
  // collocation the defects would have imposed (so x is the point the full programme would have
  // had), from the start's temperatures.
  void IntegrateBrakesLeftOut(std::vector<double>& x) const {
    for (int c = 0; c < 4; ++c) {
      if (brake_in_programme[c]) continue;
      Eigen::Vector2d y(options.initial.brakes[c].disc_temp,
                        options.initial.brakes[c].calliper_temp);
      SetBrake(c, 0, y, x);
      if (hs) {
        for (int a = 0; a + 2 <= intervals; a += 2) {
          y = HermiteSimpsonBrakeStep(c, x, a, y);
        }
        continue;
      }
      for (int k = 0; k < intervals; ++k) {
        const Eigen::Vector2d f0 = BrakeRate(c, x, k, y, nullptr);
        Eigen::Vector2d next = y;
        for (int it = 0; it < 30; ++it) {  // Newton on next - y - ds/2 (f0 + f(next)) = 0
          Eigen::Matrix2d j;
          const Eigen::Vector2d f1 = BrakeRate(c, x, k + 1, next, &j);
          const double hk = h[k];
          const double r0 = next[0] - y[0] - 0.5 * hk * (f0[0] + f1[0]);
          const double r1 = next[1] - y[1] - 0.5 * hk * (f0[1] + f1[1]);
          const double a = 1.0 - 0.5 * hk * j(0, 0), b = -0.5 * hk * j(0, 1);
          const double cc = -0.5 * hk * j(1, 0), d = 1.0 - 0.5 * hk * j(1, 1);
          const double det = a * d - b * cc;
          const double step0 = (d * r0 - b * r1) / det, step1 = (a * r1 - cc * r0) / det;
          next[0] -= step0;
          next[1] -= step1;
          if (std::abs(step0) + std::abs(step1) < 1e-10) break;
        }
        y = next;
        SetBrake(c, k + 1, y, x);
      }
    }
  }

  // One Hermite-Simpson interval of brake c from node a (temperatures ya): Newton on its four
  // equations in the midpoint's and the last node's temperatures, which it stores in x and
  // returns the last node's.
  Eigen::Vector2d HermiteSimpsonBrakeStep(int c, std::vector<double>& x, int a,
                                          const Eigen::Vector2d& ya) const {
    const double h = 2.0 * ds;  // (this interval's: the member h is the trapezoid's)
    const Eigen::Matrix2d I = Eigen::Matrix2d::Identity();
    const Eigen::Vector2d fa = BrakeRate(c, x, a, ya, nullptr);
    Eigen::Vector2d ym = ya, yb = ya;
    for (int it = 0; it < 30; ++it) {
      Eigen::Matrix2d jm, jb;
      const Eigen::Vector2d fm = BrakeRate(c, x, a + 1, ym, &jm);
      const Eigen::Vector2d fb = BrakeRate(c, x, a + 2, yb, &jb);
      Eigen::Vector4d r;
      r << ym - 0.5 * (ya + yb) - h / 8.0 * (fa - fb),  // Hermite
          yb - ya - h / 6.0 * (fa + 4.0 * fm + fb);     // Simpson
      Eigen::Matrix4d j;
      j << I, -0.5 * I + h / 8.0 * jb, -4.0 * h / 6.0 * jm, I - h / 6.0 * jb;
      const Eigen::Vector4d step = j.partialPivLu().solve(r);
      ym -= step.head<2>();
      yb -= step.tail<2>();
      if (step.cwiseAbs().sum() < 1e-10) break;
    }
    SetBrake(c, a + 1, ym, x);
    SetBrake(c, a + 2, yb, x);
    return yb;
  }
};

}  // namespace

void RequireFrontDiscsWithinLimit(const sim::ReplayInitialState& start, double front_disc_limit) {
  for (const Corner corner : {Corner::kFrontLeft, Corner::kFrontRight}) {
    const double t = start.brakes[CornerIndex(corner)].disc_temp;
    if (t > front_disc_limit) {
      throw InputError(
          fmt::format("optimal lap: the {} disc starts at {:.0f} degC, above the {:.0f} degC limit",
                      CornerName(corner), KelvinToCelsius(t), KelvinToCelsius(front_disc_limit)));
    }
  }
}

int LapNodeCount(const track::Track& track, double step_m, Collocation collocation) {
  if (collocation == Collocation::kHermiteSimpson) {
    return 2 * std::max(8, static_cast<int>(std::round(track.length_m() / step_m))) + 1;
  }
  return std::max(16, static_cast<int>(std::round(track.length_m() / step_m))) + 1;
}

Collocation ParseCollocation(const std::string& name) {
  if (name == "trapezoid") return Collocation::kTrapezoid;
  if (name == "hermite-simpson") return Collocation::kHermiteSimpson;
  throw InputError(fmt::format("collocation '{}': expected trapezoid or hermite-simpson", name));
}

std::vector<double> ResampleLapPoint(const std::vector<double>& x, int from_nodes, int to_nodes) {
  if (from_nodes < 2 || to_nodes < 2 || x.empty() || x.size() % from_nodes != 0) {
    throw InputError(
        fmt::format("optimal lap: {} values are not {} nodes of a lap", x.size(), from_nodes));
  }
  const size_t per_node = x.size() / static_cast<size_t>(from_nodes);
  std::vector<double> out(per_node * static_cast<size_t>(to_nodes));
  for (int k = 0; k < to_nodes; ++k) {
    // The fine node's place on the coarse mesh, in coarse intervals.
    const double at = static_cast<double>(k) * (from_nodes - 1) / (to_nodes - 1);
    const int j = std::min(static_cast<int>(at), from_nodes - 2);
    const double w = at - j;
    for (size_t i = 0; i < per_node; ++i) {
      out[k * per_node + i] = (1.0 - w) * x[j * per_node + i] + w * x[(j + 1) * per_node + i];
    }
  }
  return out;
}

void StartFromSolution(const SolveResult& solve, const LapLayout& from, int to_nodes,
                       Collocation to_collocation, bool with_multipliers,
                       std::vector<double>& start_point, IpoptOptions& ipopt) {
  start_point = ResampleLapPoint(solve.x, from.nodes, to_nodes);
  if (!with_multipliers) return;
  LapLayout to = from.WithNodes(to_nodes);
  to.collocation = to_collocation;
  const LapMultipliers m = ResampleLapMultipliers(solve, from, to);
  ipopt.warm_z_lower = m.z_lower;
  ipopt.warm_z_upper = m.z_upper;
  ipopt.warm_lambda = m.lambda;
}

namespace {

// Linear interpolation of a function sampled at `from` points onto `to` points, both uniform on
// [0, 1] with `first` the first sample's place in units of the spacing (0 for nodes, 0.5 for
// interval midpoints). Values beyond the ends are held.
double Interpolate(const std::function<double(int)>& value, int from_count, double from_first,
                   double place) {
  if (from_count < 2) return value(0);
  const double at = std::clamp(place - from_first, 0.0, static_cast<double>(from_count - 1));
  const int j = std::min(static_cast<int>(at), from_count - 2);
  const double w = at - j;
  return (1.0 - w) * value(j) + w * value(j + 1);
}

}  // namespace

LapMultipliers ResampleLapMultipliers(const SolveResult& solve, const LapLayout& from,
                                      const LapLayout& to) {
  if (from.nodes < 2 || to.nodes < 2 ||
      solve.z_lower.size() != static_cast<size_t>(from.variables()) ||
      solve.z_upper.size() != solve.z_lower.size() ||
      solve.lambda.size() != static_cast<size_t>(from.rows()) ||
      (from.collocation == Collocation::kHermiteSimpson && from.nodes % 2 == 0) ||
      (to.collocation == Collocation::kHermiteSimpson && to.nodes % 2 == 0)) {
    throw InputError(fmt::format(
        "optimal lap: multipliers of {} variables and {} rows are not the {}-node problem's",
        solve.z_lower.size(), solve.lambda.size(), from.nodes));
  }
  const int nf = from.intervals(), nt = to.intervals();
  const bool hs_from = from.collocation == Collocation::kHermiteSimpson;
  const bool hs_to = to.collocation == Collocation::kHermiteSimpson;
  const double ratio = static_cast<double>(nf) / nt;  // ds_to / ds_from
  // A place on `to`'s mesh (in its node spacings) on `from`'s.
  const auto on_from = [&](double place_to) { return place_to * nf / nt; };
  // Node quantities: densities per unit of `from`'s spacing (over its quadrature weights),
  // interpolated, times the new weight.
  const auto nodes = [&](const std::vector<double>& src, int src_begin, int per_node,
                         std::vector<double>& dst, int dst_begin) {
    for (int k = 0; k < to.nodes; ++k) {
      for (int i = 0; i < per_node; ++i) {
        const double density = Interpolate(
            [&](int j) { return src[src_begin + j * per_node + i] / NodeWeight(j, nf, hs_from); },
            from.nodes, 0.0, on_from(k));
        dst[dst_begin + k * per_node + i] = density * NodeWeight(k, nt, hs_to) * ratio;
      }
    }
  };
  // Interval quantities (the rate limits' rows, from node to node): interpolated at the
  // midpoints, unscaled.
  const auto intervals = [&](const std::vector<double>& src, int src_begin, int per_interval,
                             std::vector<double>& dst, int dst_begin) {
    for (int k = 0; k < nt; ++k) {
      for (int i = 0; i < per_interval; ++i) {
        dst[dst_begin + k * per_interval + i] =
            Interpolate([&](int j) { return src[src_begin + j * per_interval + i]; }, nf, 0.5,
                        on_from(k + 0.5));
      }
    }
  };
  LapMultipliers out;
  out.z_lower.assign(to.variables(), 0.0);
  out.z_upper.assign(to.variables(), 0.0);
  out.lambda.assign(to.rows(), 0.0);
  nodes(solve.z_lower, 0, from.vars_per_node, out.z_lower, 0);
  nodes(solve.z_upper, 0, from.vars_per_node, out.z_upper, 0);
  nodes(solve.lambda, 0, from.rows_per_node, out.lambda, 0);
  int src = from.nodes * from.rows_per_node, dst = to.nodes * to.rows_per_node;
  // The defects. A trapezoid's or Simpson's row's multiplier is its state's costate, the same on
  // any mesh: interpolated where the row's interval has its middle. A Hermite row's (the midpoint
  // state's own equation) carries the midpoint's weight like a node's: interpolated as a density
  // between the midpoints; from a trapezoid, which has none, 0.
  const int per = from.defects_per_interval;
  const auto costate = [&](int i, double place_from) {
    if (!hs_from) {
      return Interpolate([&](int j) { return solve.lambda[src + j * per + i]; }, nf, 0.5,
                         place_from);
    }
    return Interpolate([&](int j) { return solve.lambda[src + (2 * j + 1) * per + i]; }, nf / 2,
                       0.5, 0.5 * place_from);
  };
  const auto hermite_density = [&](int i, double place_from) {
    return Interpolate(
        [&](int j) { return solve.lambda[src + 2 * j * per + i] / NodeWeight(1, nf, true); },
        nf / 2, 0.5, 0.5 * place_from);
  };
  for (int k = 0; k < nt; ++k) {
    for (int i = 0; i < to.defects_per_interval; ++i) {
      double value = 0.0;
      if (!hs_to) {
        value = costate(i, on_from(k + 0.5));
      } else if (k % 2 == 1) {  // Simpson's row of the interval with its midpoint at node k
        value = costate(i, on_from(k));
      } else if (hs_from) {  // Hermite's row of the interval with its midpoint at node k + 1
        value = hermite_density(i, on_from(k + 1)) * NodeWeight(1, nt, true) * ratio;
      }
      out.lambda[dst + k * to.defects_per_interval + i] = value;
    }
  }
  src += nf * from.defects_per_interval;
  dst += nt * to.defects_per_interval;
  std::copy_n(solve.lambda.begin() + src, from.closure_rows, out.lambda.begin() + dst);
  src += from.closure_rows;
  dst += to.closure_rows;
  for (int b = 0; b < from.rate_blocks; ++b) {
    intervals(solve.lambda, src, 2, out.lambda, dst);
    src += 2 * nf;
    dst += 2 * nt;
  }
  return out;
}

namespace {

// A solve from a given point (options.start_point, as many values as variables): every variable
// starts there, within its bounds.
void ApplyStartPoint(const LapProblemOptions& options, Builder& b) {
  if (static_cast<int>(options.start_point.size()) != b.nlp.variables()) {
    throw InputError(fmt::format("optimal lap: a start point of {} values for {} variables",
                                 options.start_point.size(), b.nlp.variables()));
  }
  for (int i = 0; i < b.nlp.variables(); ++i) {
    b.nlp.set_initial(i, std::clamp(options.start_point[i], b.nlp.lower(i), b.nlp.upper(i)));
  }
  if (!options.wear_in_programme) {
    // The wear left out is frozen at the start's wear gained along the lap, added to this
    // lap's own start (a saved lap may have started with other wear).
    for (int c = 0; c < 4; ++c) {
      const double shift = options.initial.tyres[c].wear - options.start_point[b.nodes[0].wear[c]];
      for (size_t k = 1; k < b.nodes.size(); ++k) {
        const int i = b.nodes[k].wear[c];
        const double v = std::max(0.0, options.start_point[i] + shift);
        b.nlp.set_bounds(i, v, v);
        b.nlp.set_initial(i, v);
      }
    }
  }
  if (!options.independent_drive_and_brake) {
    // The pedal of the start's drive power and brake force (p = P / P_max - B / B_max, exact for
    // a pedal solution, since pos(p) - pos(-p) = p; a start with both on gets the net of them).
    const internal::PedalSplitFn split = b.Split();
    for (const NodeVars& nv : b.nodes) {
      const double pedal = std::clamp(b.nlp.initial(nv.power) / split.max_power -
                                          b.nlp.initial(nv.brake) / split.max_brake_force,
                                      -1.0, 1.0);
      b.nlp.set_initial(nv.pedal, pedal);
      b.nlp.set_initial(nv.power, split.max_power * split.Pos(pedal, split.eps));
      b.nlp.set_initial(nv.brake, split.max_brake_force * split.Pos(-pedal, split.eps));
    }
  }
}

// The grip factor's largest error from the frozen wear (the fixed variables keep the frozen
// values).
double FrozenWearGripDifference(const vehicle::Car& car, const Builder& b,
                                const std::vector<double>& x) {
  double difference = 0.0;
  for (const NodeVars& nv : b.nodes) {
    for (int c = 0; c < 4; ++c) {
      const tyre::GripWearTable& h = car.tyres[c].compound->grip_vs_wear;
      difference = std::max(
          difference, std::abs(h.Evaluate(x[nv.wear[c]]) - h.Evaluate(b.nlp.lower(nv.wear[c]))));
    }
  }
  return difference;
}

// The solution's channels node by node: the heading error, the controls and each corner's
// forces, slips, temperatures, brake power and (a gas-and-rim tyre) its gas.
void AppendNodeChannels(const vehicle::Car& car, const VehicleParams& p, const Builder& b,
                        const std::vector<double>& x, LapSolution& out) {
  for (int k = 0; k <= b.intervals; ++k) {
    const NodeVars& nv = b.nodes[k];
    out.xi.push_back(x[nv.xi]);
    out.steer.push_back(x[nv.steer]);
    out.pedal.push_back(x[nv.pedal]);
    out.drive_power.push_back(x[nv.power]);
    out.brake_force.push_back(x[nv.brake]);
    for (int c = 0; c < 4; ++c) {
      CornerTrace& t = out.corners[c];
      t.fz.push_back(x[nv.fz[c]]);
      t.fx.push_back(x[nv.fx[c]]);
      t.fy.push_back(x[nv.fy[c]]);
      t.slip_angle.push_back(x[nv.alpha[c]]);
      t.slip_ratio.push_back(x[nv.kappa[c]]);
      t.speed.push_back(x[nv.vx[c]]);
      t.tread_temp.push_back(x[nv.tread[c]]);
      t.carcass_temp.push_back(x[nv.carcass[c]]);
      t.wear.push_back(x[nv.wear[c]]);
      t.disc_temp.push_back(x[nv.disc[c]]);
      t.calliper_temp.push_back(x[nv.calliper[c]]);
      const double share =
          IsFront(kAllCorners[c]) ? 0.5 * p.brakes.front_share : 0.5 * (1.0 - p.brakes.front_share);
      t.brake_power.push_back(x[nv.vx[c]] * share * x[nv.brake]);
      if (!nv.wheel_states) continue;
      t.rim_temp.push_back(x[nv.rim[c]]);
      t.disc_bulk_temp.push_back(x[nv.bulk[c]]);
      const tyre::TyreThermalParams<double>& tp = car.tyres[c].params;
      if (!tp.HasGasAndRim()) continue;
      const tyre::TyreGas<double> gas =
          tyre::CalcTyreGas(tp, x[nv.carcass[c]], x[nv.rim[c]], x[nv.vx[c]]);
      t.gas_temp.push_back(gas.gas_temp);
      t.pressure.push_back(gas.pressure);
      t.rolling_resistance.push_back(gas.rolling_resistance);
    }
  }
}

}  // namespace

LapSolution SolveMinimumTimeLap(const vehicle::Car& car, const track::Track& track,
                                const LapProblemOptions& options, const sim::QssLap& guess,
                                const IpoptOptions& ipopt, const SolveResult* solved) {
  const VehicleParams& p = vehicle::RequireVehicle(car, "the optimal lap");
  if (!(options.step_m > 0.0)) throw InputError("optimal lap: the mesh step must be > 0 m");
  if (options.front_disc_limit && !options.periodic_thermal) {
    RequireFrontDiscsWithinLimit(options.initial, *options.front_disc_limit);
  }
  Builder b(car, p, track, options, guess);
  b.Build();
  if (!options.start_point.empty()) ApplyStartPoint(options, b);
  LapSolution out;
  out.layout = b.layout;
  out.variables = b.nlp.variables();
  out.constraints = b.nlp.constraints();
  // Multipliers come and go in the layout's rows (every state's defects; zero for the brakes
  // left out, whose costates are zero: they feed nothing back).
  if (solved != nullptr) {
    // Solved elsewhere, already in the layout (x complete, multipliers in the layout's rows).
    if (!solved->x.empty() && static_cast<int>(solved->x.size()) != b.nlp.variables()) {
      throw InputError(fmt::format("optimal lap: a solution of {} values for {} variables",
                                   solved->x.size(), b.nlp.variables()));
    }
    out.solve = *solved;
    if (out.solve.x.empty()) return out;
  } else {
    IpoptOptions programme_ipopt = ipopt;
    if (programme_ipopt.warm_lambda.size() == static_cast<size_t>(b.layout.rows())) {
      programme_ipopt.warm_lambda = b.ToProgrammeRows(ipopt.warm_lambda);
    }
    out.solve = SolveWithIpopt(b.nlp, programme_ipopt);
    if (out.solve.lambda.size() == static_cast<size_t>(b.nlp.constraints())) {
      out.solve.lambda = b.ToLayoutRows(out.solve.lambda);
    }
    if (out.solve.x.empty()) return out;
    b.IntegrateBrakesLeftOut(out.solve.x);
    b.IntegrateWearLeftOut(out.solve.x);
  }
  if (!options.wear_in_programme) {
    out.frozen_wear_grip_difference = FrozenWearGripDifference(car, b, out.solve.x);
  }
  const std::vector<double>& x = out.solve.x;
  const double time = b.uniform ? AppendRoadFrameChannels(b.nodes, x, b.ds, out, b.hs)
                                : AppendRoadFrameChannelsOnMesh(b.nodes, x, b.node_m, out);
  AppendNodeChannels(car, p, b, x, out);
  out.lap_time = time;
  out.max_brake_force = b.max_brake_force;
  out.rates = b.Rates(x, out.solve.lambda);
  return out;
}

LapProgrammeValues EvaluateLapProgramme(const vehicle::Car& car, const track::Track& track,
                                        const LapProblemOptions& options, const sim::QssLap& guess,
                                        const std::vector<double>& x) {
  const VehicleParams& p = vehicle::RequireVehicle(car, "the optimal lap");
  if (!(options.step_m > 0.0)) throw InputError("optimal lap: the mesh step must be > 0 m");
  Builder b(car, p, track, options, guess);
  b.Build();
  if (!options.start_point.empty()) ApplyStartPoint(options, b);
  const ElementNlp& nlp = b.nlp;
  const int n = nlp.variables(), m = nlp.constraints();
  if (static_cast<int>(x.size()) != n) {
    throw InputError(
        fmt::format("optimal lap: a point of {} values for {} variables", x.size(), n));
  }
  LapProgrammeValues out;
  std::vector<double> at = x;
  for (int i = 0; i < n; ++i) {
    out.lower.push_back(nlp.lower(i));
    out.upper.push_back(nlp.upper(i));
    out.scale.push_back(nlp.scale(i));
    if (nlp.lower(i) == nlp.upper(i)) at[i] = nlp.lower(i);  // a fixed variable, as Ipopt had it
  }
  out.objective = nlp.Objective(at);
  out.objective_scale = nlp.objective_scale();
  std::vector<double> lo(m), hi(m), sc(m);
  for (int r = 0; r < m; ++r)
    lo[r] = nlp.row_lower(r), hi[r] = nlp.row_upper(r), sc[r] = nlp.row_scale(r);
  out.rows = b.ToLayoutRows(nlp.Constraints(at));
  out.row_lower = b.ToLayoutRows(lo);
  out.row_upper = b.ToLayoutRows(hi);
  out.row_scale = b.ToLayoutRows(sc);
  // The rows left out: scale 1.
  std::vector<double> present(m, 1.0);
  const std::vector<double> in_layout = b.ToLayoutRows(present);
  for (size_t r = 0; r < in_layout.size(); ++r) {
    if (in_layout[r] == 0.0) out.row_scale[r] = 1.0;
  }
  return out;
}

}  // namespace hotlap::ocp
