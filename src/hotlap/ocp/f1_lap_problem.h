#pragma once
/// @file
/// The minimum-lap-time problem of the 3-DOF F1 car (vehicle/f1_car.h) on a closed track, as the
/// peer program fastest-lap poses it: curvilinear road coordinates with arc length s as the
/// independent variable, trapezoidal collocation on N equal intervals of the centre line, periodic
/// (the last node joins the first), controls steer and throttle on every node with fastest-lap's
/// smoothness penalties, and fastest-lap's bounds (docs/f1-peer.md).
///
/// Transcription (ocp/element.h): every node carries the states u, v, r (yaw rate), n (lateral
/// offset, left +), alpha (heading relative to the centre line); the controls steer and throttle
/// (-1 full brake .. 1 full power); the four wheels' slip ratios; the body-axis tyre totals X, Y,
/// Mz; and w = dt/ds. Normal loads, lateral slips and tyre forces are functions of these inside
/// one element per tyre (6-7 inputs), so the KKT system stays small; every equation has exact
/// derivatives and Ipopt solves with exact Hessians.

#include <array>
#include <vector>

#include "hotlap/ocp/ipopt_solve.h"
#include "hotlap/ocp/road_frame_channels.h"
#include "hotlap/track/track.h"
#include "hotlap/vehicle/f1_car.h"

namespace hotlap::ocp {

struct F1LapOptions {
  int mesh_points = 500;  ///< nodes (= intervals: the lap is periodic)
  /// fastest-lap's control smoothness weights ("dissipation"): weight * sum over intervals of
  /// ((c_{k+1} - c_k) / ds)^2 ds, steer in rad, throttle in [-1, 1].
  double steer_dissipation = 50.0;
  double throttle_dissipation = 20.0 * 8.0e-4;
  /// fastest-lap's extra constraint |lambda| <= 0.11 on every tyre's lateral slip (its slip
  /// ratios are bounded likewise, as variables).
  double max_lateral_slip = 0.11;
};

/// The solution at the N mesh nodes (s = k L / N).
/// The road-frame channels (distance, time, u, v, r, n) come from RoadFrameChannels.
struct F1LapSolution : RoadFrameChannels {
  SolveResult solve;
  std::vector<double> alpha, steer, throttle;
  std::array<std::vector<double>, 4> kappa, lambda, fz, fx, fy;  ///< fl fr rl rr, wheel frame
  double lap_time = 0.0;                                         ///< s
  double guess_lap_time = 0.0;  ///< the starting point's (quasi-steady speed profile), s
  int variables = 0;
  int constraints = 0;
};

/// The starting point: a quasi-steady speed profile on the centre line (curvature-limited
/// speeds, then forward power-limited and backward brake-limited passes, at grip deliberately
/// below the tyres'), never below 55 km/h (inside the 50 km/h bound on u), m/s at the N nodes.
std::vector<double> F1GuessSpeeds(const vehicle::F1CarParams& car, const track::Track& track,
                                  int mesh_points);

/// The Ipopt settings the F1 lap is solved with: monotone barrier updates (one factorisation per
/// iteration and far fewer iterations here than the adaptive strategy: 47 against 84) and
/// MUMPS without its own scaling (the programme is scaled by ElementNlp; MUMPS' scaling cost
/// about a third of the linear-algebra time and changed nothing), SCOTCH ordering (MUMPS pivot
/// order 3: 10-20 % less CPU than its automatic choice here). Tolerance 1e-7 (scaled).
IpoptOptions F1IpoptOptions();

/// Builds and solves the lap; failures of the solve are reported in `solve`, never thrown.
/// InputError for fewer than 20 mesh points.
F1LapSolution SolveF1Lap(const vehicle::F1CarParams& car, const track::Track& track,
                         const F1LapOptions& options, const IpoptOptions& ipopt);

}  // namespace hotlap::ocp
