// make_example_log: writes the built-in example log data/telemetry/darlington_example.csv.
//
// A plausible, not a measured, lap of a Darlington-like egg-shaped oval, used by the README's
// main job until the lap simulator replaces it. How it is made (every number assumed unless
// said):
//  1. Track by distance: 2198 m (public length), start/finish mid front straight; straights of
//     375 m (public, medium confidence) banked 3 deg (front) and 2 deg (back); turns 1-2 of 760 m
//     banked 25 deg and turns 3-4 of 688 m banked 23 deg (public bankings), each a 150 m clothoid,
//     an arc and a 150 m clothoid turning through 180 deg, so turns 3-4 are the tighter end.
//  2. Speed: the cornering limit of a 1542 kg car with friction 0.95 and downforce on the banked
//     surface, then a forward pass limited by 400 kW at the wheels (670 hp less driveline losses)
//     less drag and a backward pass limited to 2.5 m/s^2 of braking less drag (oval braking is
//     light). Two braking zones follow: into turn 1 and into turn 3.
//  3. Forces per corner: static loads (52 % front, 53 % left), aero load split 45/55, lateral and
//     longitudinal load transfer (CoG 0.43 m, track 1.65 m, wheelbase 2.794 m), lateral force
//     shared in proportion to load so the right-side tyres carry more, drive on the rear axle,
//     brakes 58/42 front/rear; slip angles and slip ratios from a softened linear tyre.
//  4. Resampled at 50 Hz in time; air 25 degC and track 40 degC as columns.
//
// Usage: make_example_log OUT.csv

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "hotlap/common/corner.h"
#include "hotlap/common/csv.h"
#include "hotlap/common/error.h"
#include "hotlap/common/units.h"

namespace {

using hotlap::kGravity;
using hotlap::kPi;

constexpr double kLength = 2198.0;
constexpr double kMass = 1542.0;
constexpr double kMu = 0.95;
constexpr double kAirDensity = 1.2;
constexpr double kDragArea = 1.05;    // Cd A, m^2
constexpr double kLiftArea = 1.6;     // Cl A, m^2
constexpr double kPower = 400e3;      // W at the wheels
constexpr double kBrakeDecel = 2.5;   // m/s^2 from the brakes
constexpr double kCogHeight = 0.43;   // m
constexpr double kTrack = 1.65;       // m
constexpr double kWheelbase = 2.794;  // m

struct TrackPoint {
  double curvature;  // 1/m, positive turning left
  double bank;       // rad
};

// A 180-deg end: clothoid in, arc, clothoid out.
double EndCurvature(double s, double length, double clothoid) {
  const double peak = kPi / (length - clothoid);
  if (s < clothoid) return peak * s / clothoid;
  if (s > length - clothoid) return peak * (length - s) / clothoid;
  return peak;
}

TrackPoint TrackAt(double s) {
  // Layout from the start/finish line: half the front straight, turns 1-2, back straight,
  // turns 3-4, the other half of the front straight.
  const double half_front = 187.5, turn12 = 760.0, back = 375.0, turn34 = 688.0;
  const double deg = kPi / 180.0;
  if (s < half_front) return {0.0, 3 * deg};
  s -= half_front;
  if (s < turn12) {
    const double k = EndCurvature(s, turn12, 150.0);
    return {k, (3 + 22 * k / (kPi / (turn12 - 150.0))) * deg};
  }
  s -= turn12;
  if (s < back) return {0.0, 2 * deg};
  s -= back;
  if (s < turn34) {
    const double k = EndCurvature(s, turn34, 150.0);
    return {k, (2 + 21 * k / (kPi / (turn34 - 150.0))) * deg};
  }
  return {0.0, 3 * deg};
}

// Highest steady speed on the banked surface with friction kMu and downforce.
double CorneringSpeed(const TrackPoint& p) {
  if (p.curvature < 1e-9) return 1e9;
  const double lift = 0.5 * kAirDensity * kLiftArea / kMass;
  const double c = std::cos(p.bank), s = std::sin(p.bank);
  const double denominator = p.curvature * (c - kMu * s) - kMu * lift;
  if (denominator <= 0.0) return 1e9;
  return std::sqrt(kGravity * (s + kMu * c) / denominator);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: make_example_log OUT.csv\n");
    return 2;
  }
  // 1-2. Speed by distance: cornering limit, forward (power) and backward (brakes) passes.
  const double ds = 0.5;
  const int n = static_cast<int>(kLength / ds);
  std::vector<double> v(n);
  for (int i = 0; i < n; ++i) v[i] = CorneringSpeed(TrackAt(i * ds));
  const auto drag = [](double u) { return 0.5 * kAirDensity * kDragArea * u * u / kMass; };
  for (int pass = 0; pass < 2; ++pass) {  // twice, so the lap is periodic
    for (int k = 1; k <= n; ++k) {
      const int i = k % n, j = k - 1;
      const double a = kPower / (kMass * std::max(v[j], 10.0)) - drag(v[j]);
      v[i] = std::min(v[i], std::sqrt(std::max(v[j] * v[j] + 2.0 * a * ds, 1.0)));
    }
    for (int k = n - 1; k >= 0; --k) {
      const int i = k, j = (k + 1) % n;
      const double a = kBrakeDecel + drag(v[j]);
      v[i] = std::min(v[i], std::sqrt(v[j] * v[j] + 2.0 * a * ds));
    }
  }
  // Time along the lap.
  std::vector<double> t(n + 1, 0.0);
  for (int i = 0; i < n; ++i) t[i + 1] = t[i] + 2.0 * ds / (v[i] + v[(i + 1) % n]);
  const double lap_time = t[n];

  // 3-4. Resample at 50 Hz and make the per-corner channels.
  const double rate = 50.0;
  const int samples = static_cast<int>(std::floor(lap_time * rate)) + 1;
  std::vector<std::string> names = {"time_s", "distance_m", "speed_mps", "ambient_temp_C",
                                    "track_temp_C"};
  for (hotlap::Corner c : hotlap::kAllCorners) {
    const std::string cn(hotlap::CornerName(c));
    for (const char* q : {"fx_", "fy_", "fz_"}) names.push_back(q + cn + "_N");
    names.push_back("slip_angle_" + cn + "_deg");
    names.push_back("slip_ratio_" + cn);
  }
  std::vector<std::vector<double>> cols(names.size(), std::vector<double>(samples));
  int seg = 0;
  for (int k = 0; k < samples; ++k) {
    const double time = k / rate;
    while (seg < n - 1 && t[seg + 1] < time) ++seg;
    const double f = std::clamp((time - t[seg]) / (t[seg + 1] - t[seg]), 0.0, 1.0);
    const double s = (seg + f) * ds;
    const double u = v[seg] + f * (v[(seg + 1) % n] - v[seg]);
    // Longitudinal acceleration from the speed profile.
    const double dvds = (v[(seg + 1) % n] - v[seg]) / ds;
    const double ax = u * dvds;
    const TrackPoint p = TrackAt(s);
    const double cb = std::cos(p.bank), sb = std::sin(p.bank);
    const double ay = u * u * p.curvature * cb - kGravity * sb;      // in the banked plane
    const double normal = kGravity * cb + u * u * p.curvature * sb;  // per unit mass
    const double downforce = 0.5 * kAirDensity * kLiftArea * u * u;
    const double total_fz = kMass * normal + downforce;
    // Loads: static share scaled by the normal acceleration, aero split, load transfer.
    const double front = 0.52, left = 0.53;
    double fz[4];
    fz[0] = kMass * normal * front * left + 0.45 * downforce / 2;
    fz[1] = kMass * normal * front * (1 - left) + 0.45 * downforce / 2;
    fz[2] = kMass * normal * (1 - front) * left + 0.55 * downforce / 2;
    fz[3] = kMass * normal * (1 - front) * (1 - left) + 0.55 * downforce / 2;
    const double lateral_transfer = kMass * ay * kCogHeight / kTrack / 2;   // per axle
    const double long_transfer = kMass * ax * kCogHeight / kWheelbase / 2;  // per side
    fz[0] += -lateral_transfer - long_transfer;
    fz[1] += +lateral_transfer - long_transfer;
    fz[2] += -lateral_transfer + long_transfer;
    fz[3] += +lateral_transfer + long_transfer;
    // Longitudinal force needed: mass * ax + drag; drive on the rear, brakes 58/42.
    const double fx_total = kMass * ax + kMass * drag(u);
    double fx[4];
    if (fx_total >= 0) {
      fx[0] = fx[1] = 0.0;
      fx[2] = fx[3] = fx_total / 2;
    } else {
      fx[0] = fx[1] = 0.58 * fx_total / 2;
      fx[2] = fx[3] = 0.42 * fx_total / 2;
    }
    double* row[] = {&cols[0][k], &cols[1][k], &cols[2][k], &cols[3][k], &cols[4][k]};
    *row[0] = time;
    *row[1] = s;
    *row[2] = u;
    *row[3] = 25.0;
    *row[4] = 40.0;
    for (int c = 0; c < 4; ++c) {
      const double fy = kMass * ay * fz[c] / total_fz;
      // Softened linear tyre: cornering stiffness 18 Fz per rad, slip stiffness 25 Fz.
      const double uy = fy / (kMu * fz[c]), ux = fx[c] / (kMu * fz[c]);
      const double alpha = -(fy / fz[c]) / 18.0 * (1.0 + 0.5 * uy * uy);
      const double kappa = (fx[c] / fz[c]) / 25.0 * (1.0 + 0.5 * ux * ux);
      const int base = 5 + 5 * c;
      cols[base + 0][k] = fx[c];
      cols[base + 1][k] = fy;
      cols[base + 2][k] = fz[c];
      cols[base + 3][k] = hotlap::RadToDeg(alpha);
      cols[base + 4][k] = kappa;
    }
  }
  try {
    hotlap::WriteCsv(argv[1],
                     {{"track", "darlington-like (tools/make_example_log.cc)"},
                      {"car", "gen7"},
                      {"source", "hotlap make_example_log: plausible, not measured"},
                      {"lap_time_s", std::to_string(lap_time)}},
                     names, cols);
  } catch (const hotlap::InputError& e) {
    std::fprintf(stderr, "make_example_log: %s\n", e.what());
    return 2;
  }
  std::printf("wrote %s: %d samples, lap %.2f s, speeds %.1f..%.1f m/s\n", argv[1], samples,
              lap_time, *std::min_element(v.begin(), v.end()),
              *std::max_element(v.begin(), v.end()));
  return 0;
}
