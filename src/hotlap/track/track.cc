#include "hotlap/track/track.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>
#include <Eigen/Core>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"

namespace hotlap::track {

namespace {

// Longest polynomial piece. The quintic Hermite centre line between knots then departs from the
// integrated one by at most (h/2)^6 |x^(6)| / 720: below 1e-7 m for a 10 m radius, 1e-12 m on an
// oval's 160 m.
constexpr double kMaxPieceLength = 2.5;

// Longest track: 100 km, four times the Nuerburgring's combined loop. A longer one (a point of a
// file a million metres out) would be subdivided into more pieces than memory holds.
constexpr double kMaxTrackLength = 1e5;

// 8-point Gauss-Legendre on [-1, 1]: exact for polynomials of degree 15.
constexpr std::array<double, 4> kGaussX = {0.1834346424956498, 0.5255324099163290,
                                           0.7966664774136267, 0.9602898564975363};
constexpr std::array<double, 4> kGaussW = {0.3626837833783620, 0.3137066458778873,
                                           0.2223810344533745, 0.1012285362903763};

// Coefficients of the cubic a0 + a1 t + a2 t^2 + a3 t^3 on [0, h] with the given Hermite data.
std::array<double, 4> CubicFromHermite(const CubicHermite& c, double h) {
  const double secant = (c.value_end - c.value_start) / h;
  return {c.value_start, c.slope_start, (3.0 * secant - 2.0 * c.slope_start - c.slope_end) / h,
          (c.slope_start + c.slope_end - 2.0 * secant) / (h * h)};
}

// The same cubic re-expanded about t = a (a Taylor shift).
std::array<double, 4> ShiftCubic(const std::array<double, 4>& c, double a) {
  return {c[0] + a * (c[1] + a * (c[2] + a * c[3])), c[1] + a * (2.0 * c[2] + 3.0 * a * c[3]),
          c[2] + 3.0 * a * c[3], c[3]};
}

double Cubic(const double* c, double t) { return c[0] + t * (c[1] + t * (c[2] + t * c[3])); }
double CubicSlope(const double* c, double t) { return c[1] + t * (2.0 * c[2] + 3.0 * t * c[3]); }
// Integral of the cubic from 0 to t.
double CubicIntegral(const double* c, double t) {
  return t * (c[0] + t * (c[1] / 2.0 + t * (c[2] / 3.0 + t * c[3] / 4.0)));
}

// Quintic on [0, h] with value p, slope v and second derivative a given at both ends.
std::array<double, 6> QuinticFromHermite(double p0, double v0, double a0, double p1, double v1,
                                         double a1, double h) {
  const double d = p1 - (p0 + h * (v0 + h * a0 / 2.0));
  const double dv = v1 - (v0 + a0 * h);
  const double da = a1 - a0;
  const double h2 = h * h, h3 = h2 * h;
  return {p0,
          v0,
          a0 / 2.0,
          (10.0 * d - 4.0 * dv * h + da * h2 / 2.0) / h3,
          (-15.0 * d + 7.0 * dv * h - da * h2) / (h3 * h),
          (6.0 * d - 3.0 * dv * h + da * h2 / 2.0) / (h3 * h2)};
}

double Quintic(const double* c, double t) {
  return c[0] + t * (c[1] + t * (c[2] + t * (c[3] + t * (c[4] + t * c[5]))));
}

bool AllFinite(const CubicHermite& c) {
  return std::isfinite(c.value_start) && std::isfinite(c.slope_start) &&
         std::isfinite(c.value_end) && std::isfinite(c.slope_end);
}

// One piece after subdivision: every channel as cubic coefficients in the local t.
struct Sub {
  double h;
  std::array<double, 4> kappa, bank, grade, wl, wr;
};

// Splits the pieces into pieces of at most kMaxPieceLength; every channel stays the same cubic.
std::vector<Sub> Subdivide(const std::string& name, const std::vector<RibbonPiece>& pieces) {
  std::vector<Sub> subs;
  double length = 0.0;
  for (size_t i = 0; i < pieces.size(); ++i) {
    const RibbonPiece& p = pieces[i];
    if (!(p.length_m > 0.0) || !std::isfinite(p.length_m) || !AllFinite(p.curvature) ||
        !AllFinite(p.bank) || !AllFinite(p.grade) || !AllFinite(p.width_left) ||
        !AllFinite(p.width_right)) {
      throw NumericalError(fmt::format(
          "track '{}': piece {} has a non-positive length or a non-finite value", name, i));
    }
    length += p.length_m;
    if (!(length <= kMaxTrackLength)) {
      throw NumericalError(fmt::format("track '{}': longer than {:g} km (pieces 0 to {})", name,
                                       kMaxTrackLength / 1e3, i));
    }
    const auto kappa = CubicFromHermite(p.curvature, p.length_m);
    const auto bank = CubicFromHermite(p.bank, p.length_m);
    const auto grade = CubicFromHermite(p.grade, p.length_m);
    const auto wl = CubicFromHermite(p.width_left, p.length_m);
    const auto wr = CubicFromHermite(p.width_right, p.length_m);
    const int n = std::max(1, static_cast<int>(std::ceil(p.length_m / kMaxPieceLength - 1e-9)));
    const double h = p.length_m / n;
    for (int k = 0; k < n; ++k) {
      const double a = k * h;
      subs.push_back({h, ShiftCubic(kappa, a), ShiftCubic(bank, a), ShiftCubic(grade, a),
                      ShiftCubic(wl, a), ShiftCubic(wr, a)});
    }
  }
  return subs;
}

// Displacement of the centre line over one piece starting at `heading0` (Gauss-Legendre).
Eigen::Vector3d IntegrateSub(const Sub& sub, double heading0) {
  Eigen::Vector3d d = Eigen::Vector3d::Zero();
  for (size_t g = 0; g < 2 * kGaussX.size(); ++g) {
    const double xi = g < kGaussX.size() ? -kGaussX[g] : kGaussX[g - kGaussX.size()];
    const double w = kGaussW[g % kGaussX.size()] * sub.h / 2.0;
    const double t = (xi + 1.0) * sub.h / 2.0;
    const double heading = heading0 + CubicIntegral(sub.kappa.data(), t);
    const double grade = Cubic(sub.grade.data(), t);
    d += w * Eigen::Vector3d(std::cos(grade) * std::cos(heading),
                             std::cos(grade) * std::sin(heading), std::sin(grade));
  }
  return d;
}

// Position and derivatives of the centre line at one knot, before the closure spread.
struct KnotState {
  double s, x, y, z, heading;
};

}  // namespace

namespace internal {

CentreLineEnd IntegrateCentreLine(const std::vector<RibbonPiece>& pieces, const TrackStart& start) {
  CentreLineEnd end{start.x_m, start.y_m, start.z_m, start.heading_rad, 0.0};
  for (const Sub& sub : Subdivide("", pieces)) {
    const Eigen::Vector3d d = IntegrateSub(sub, end.heading_rad);
    end.x_m += d.x();
    end.y_m += d.y();
    end.z_m += d.z();
    end.heading_rad += CubicIntegral(sub.kappa.data(), sub.h);
    end.length_m += sub.h;
  }
  return end;
}

}  // namespace internal

double ClosureError::position_m() const {
  return std::sqrt(dx_m * dx_m + dy_m * dy_m + dz_m * dz_m);
}

Track Track::FromPieces(std::string name, const std::vector<RibbonPiece>& pieces,
                        const TrackStart& start,
                        const std::optional<ClosureError>& closure_before_correction) {
  if (pieces.empty()) throw NumericalError("track '" + name + "': no pieces");
  Track track;
  track.name_ = std::move(name);

  for (size_t i = 0; i < pieces.size(); ++i) {
    const RibbonPiece& p = pieces[i];
    if (!(p.width_left.value_start > 0.0 && p.width_left.value_end > 0.0 &&
          p.width_right.value_start > 0.0 && p.width_right.value_end > 0.0)) {
      throw NumericalError(
          fmt::format("track '{}': piece {} has a non-positive width", track.name_, i));
    }
  }
  const std::vector<Sub> subs = Subdivide(track.name_, pieces);

  // Integrate heading exactly and the centre line with Gauss-Legendre, piece by piece.
  std::vector<KnotState> knots;
  knots.reserve(subs.size() + 1);
  knots.push_back({0.0, start.x_m, start.y_m, start.z_m, start.heading_rad});
  for (const Sub& sub : subs) {
    const KnotState& k0 = knots.back();
    const Eigen::Vector3d d = IntegrateSub(sub, k0.heading);
    knots.push_back({k0.s + sub.h, k0.x + d.x(), k0.y + d.y(), k0.z + d.z(),
                     k0.heading + CubicIntegral(sub.kappa.data(), sub.h)});
  }
  const KnotState& end = knots.back();
  track.length_ = end.s;
  const double turns = (end.heading - start.heading_rad) / (2.0 * kPi);
  track.winding_ = static_cast<int>(std::lround(turns));
  track.spread_ = {end.x - start.x_m, end.y - start.y_m, end.z - start.z_m,
                   end.heading - start.heading_rad - 2.0 * kPi * track.winding_};
  if (std::abs(track.spread_.heading_rad) > 0.1) {
    throw NumericalError(
        fmt::format("track '{}': the pieces turn through {:.4f} turns, not a "
                    "whole number",
                    track.name_, turns));
  }
  track.closure_before_ = closure_before_correction.value_or(track.spread_);

  // Spread the remaining gap linearly over the lap and build the per-piece polynomials.
  const double L = track.length_;
  const ClosureError& e = track.spread_;
  const double heading_fix = -e.heading_rad / L;
  track.knots_.resize(knots.size());
  track.pieces_.resize(subs.size());
  struct Corrected {
    double p[3], v[3], a[3];
  };
  const auto corrected = [&](size_t k, const Sub& sub, double t) {
    const KnotState& ks = knots[k];
    const double f = ks.s / L;
    const double heading = ks.heading + heading_fix * ks.s;
    const double heading_slope = Cubic(sub.kappa.data(), t) + heading_fix;
    const double grade = Cubic(sub.grade.data(), t);
    const double grade_slope = CubicSlope(sub.grade.data(), t);
    const double ch = std::cos(heading), sh = std::sin(heading);
    const double cg = std::cos(grade), sg = std::sin(grade);
    Corrected c;
    c.p[0] = ks.x - f * e.dx_m;
    c.p[1] = ks.y - f * e.dy_m;
    c.p[2] = ks.z - f * e.dz_m;
    c.v[0] = cg * ch - e.dx_m / L;
    c.v[1] = cg * sh - e.dy_m / L;
    c.v[2] = sg - e.dz_m / L;
    c.a[0] = -sg * grade_slope * ch - cg * sh * heading_slope;
    c.a[1] = -sg * grade_slope * sh + cg * ch * heading_slope;
    c.a[2] = cg * grade_slope;
    return c;
  };
  for (size_t i = 0; i < subs.size(); ++i) {
    const Sub& sub = subs[i];
    Piece& piece = track.pieces_[i];
    track.knots_[i] = knots[i].s;
    std::copy(sub.kappa.begin(), sub.kappa.end(), piece.kappa);
    std::copy(sub.bank.begin(), sub.bank.end(), piece.bank);
    std::copy(sub.grade.begin(), sub.grade.end(), piece.grade);
    std::copy(sub.wl.begin(), sub.wl.end(), piece.width_left);
    std::copy(sub.wr.begin(), sub.wr.end(), piece.width_right);
    piece.heading0 = knots[i].heading + heading_fix * knots[i].s;
    piece.heading_correction_per_m = heading_fix;
    const Corrected c0 = corrected(i, sub, 0.0);
    const Corrected c1 = corrected(i + 1, sub, sub.h);
    double* out[3] = {piece.x, piece.y, piece.z};
    for (int d = 0; d < 3; ++d) {
      const auto q =
          QuinticFromHermite(c0.p[d], c0.v[d], c0.a[d], c1.p[d], c1.v[d], c1.a[d], sub.h);
      std::copy(q.begin(), q.end(), out[d]);
    }
  }
  track.knots_.back() = L;
  return track;
}

Track Track::Repeated(int laps) const {
  if (laps < 1) throw InputError(fmt::format("a track repeats 1 or more laps, not {}", laps));
  Track t = *this;
  t.length_ = length_ * laps;
  t.winding_ = winding_ * laps;
  t.laps_ = laps_ * laps;
  const size_t n = pieces_.size();
  t.pieces_.clear();
  t.knots_.clear();
  t.pieces_.reserve(n * laps);
  t.knots_.reserve(n * laps + 1);
  for (int lap = 0; lap < laps; ++lap) {
    for (size_t i = 0; i < n; ++i) {
      Piece piece = pieces_[i];
      piece.heading0 += 2.0 * kPi * winding_ * lap;
      t.pieces_.push_back(piece);
      t.knots_.push_back(knots_[i] + length_ * lap);
    }
  }
  t.knots_.push_back(t.length_);
  return t;
}

double Track::Wrap(double s_m) const {
  double s = std::fmod(s_m, length_);
  if (s < 0.0) s += length_;
  if (s >= length_) s = 0.0;  // fmod rounding at exactly -length
  return s;
}

TrackPoint Track::EvalPiece(size_t i, double t) const {
  const Piece& p = pieces_[i];
  TrackPoint out;
  out.s_m = knots_[i] + t;
  out.x_m = Quintic(p.x, t);
  out.y_m = Quintic(p.y, t);
  out.z_m = Quintic(p.z, t);
  out.heading_rad = p.heading0 + CubicIntegral(p.kappa, t) + p.heading_correction_per_m * t;
  out.curvature_per_m = Cubic(p.kappa, t);
  out.curvature_rate_per_m2 = CubicSlope(p.kappa, t);
  out.bank_rad = Cubic(p.bank, t);
  out.bank_rate_per_m = CubicSlope(p.bank, t);
  out.grade_rad = Cubic(p.grade, t);
  out.width_left_m = Cubic(p.width_left, t);
  out.width_right_m = Cubic(p.width_right, t);
  return out;
}

TrackPoint Track::At(double s_m) const {
  const double s = Wrap(s_m);
  // The piece [knots_[i], knots_[i + 1]) that holds s.
  const size_t i =
      std::clamp<size_t>(std::upper_bound(knots_.begin(), knots_.end(), s) - knots_.begin(), 1,
                         pieces_.size()) -
      1;
  TrackPoint p = EvalPiece(i, s - knots_[i]);
  p.s_m = s;
  return p;
}

std::vector<TrackPoint> Track::Sample(int intervals) const {
  const int n = std::max(1, intervals);
  std::vector<TrackPoint> out;
  out.reserve(n + 1);
  for (int i = 0; i < n; ++i) out.push_back(At(length_ * i / n));
  TrackPoint last = out.front();
  last.s_m = length_;
  last.heading_rad += 2.0 * kPi * winding_;
  out.push_back(last);
  return out;
}

}  // namespace hotlap::track
