#include "hotlap/track/segment_loop.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>
#include <Eigen/Dense>

#include "hotlap/common/enum_names.h"
#include "hotlap/common/error.h"
#include "hotlap/common/units.h"

namespace hotlap::track {

namespace {

// A loop given without unknowns must close this well (docs/tracks.md).
constexpr double kClosePosition = 0.01;  // m
constexpr double kCloseHeading = 1e-6;   // rad
constexpr double kCloseLength = 0.01;    // m
// Newton stops here: the integration itself is good to about 1e-12.
constexpr double kSolvedMetres = 1e-9;
constexpr double kSolvedHeading = 1e-12;
constexpr int kMaxIterations = 50;

// Where each channel starts and ends on one segment.
struct SegmentGeometry {
  double length = 0.0;
  double kappa0 = 0.0, kappa1 = 0.0;
  double bank0 = 0.0, bank1 = 0.0;
  double wl0 = 0.0, wl1 = 0.0;
  double wr0 = 0.0, wr1 = 0.0;
};

double ValueOf(const LoopValue& v, const std::vector<double>& unknowns) {
  return v.unknown >= 0 ? unknowns[v.unknown] : v.value;
}

std::vector<SegmentGeometry> Geometry(const SegmentLoop& loop, const std::vector<double>& u) {
  const size_t n = loop.segments.size();
  std::vector<SegmentGeometry> g(n);
  for (size_t i = 0; i < n; ++i) {  // straights and arcs first: clothoids take their ends from them
    const Segment& s = loop.segments[i];
    if (s.type == SegmentType::kClothoid) continue;
    double kappa = 0.0;
    double length = 0.0;
    if (s.type == SegmentType::kStraight) {
      length = ValueOf(s.length, u);
    } else {
      const double radius = ValueOf(s.radius, u);
      kappa = s.turn_sign / radius;
      length = s.arc_by_angle ? radius * ValueOf(s.angle, u) : ValueOf(s.length, u);
    }
    g[i] = {length,         kappa,          kappa,           s.bank_rad,     s.bank_rad,
            s.width_left_m, s.width_left_m, s.width_right_m, s.width_right_m};
  }
  for (size_t i = 0; i < n; ++i) {
    if (loop.segments[i].type != SegmentType::kClothoid) continue;
    const SegmentGeometry& prev = g[(i + n - 1) % n];
    const SegmentGeometry& next = g[(i + 1) % n];
    g[i] = {ValueOf(loop.segments[i].length, u),
            prev.kappa1,
            next.kappa0,
            prev.bank1,
            next.bank0,
            prev.wl1,
            next.wl0,
            prev.wr1,
            next.wr0};
  }
  return g;
}

// Linear curvature; bank and widths along the smoothstep (a cubic with zero end slopes).
RibbonPiece PieceOf(const SegmentGeometry& g) {
  RibbonPiece p;
  p.length_m = g.length;
  const double kappa_slope = (g.kappa1 - g.kappa0) / g.length;
  p.curvature = {g.kappa0, kappa_slope, g.kappa1, kappa_slope};
  p.bank = {g.bank0, 0.0, g.bank1, 0.0};
  p.grade = CubicHermite::Constant(0.0);
  p.width_left = {g.wl0, 0.0, g.wl1, 0.0};
  p.width_right = {g.wr0, 0.0, g.wr1, 0.0};
  return p;
}

// Value and slope at t of the cubic with Hermite data c over [0, h].
std::pair<double, double> EvalHermite(const CubicHermite& c, double h, double t) {
  const double u = t / h;
  const double h00 = 2 * u * u * u - 3 * u * u + 1, h10 = u * u * u - 2 * u * u + u;
  const double h01 = -2 * u * u * u + 3 * u * u, h11 = u * u * u - u * u;
  const double value =
      h00 * c.value_start + h10 * h * c.slope_start + h01 * c.value_end + h11 * h * c.slope_end;
  const double d00 = (6 * u * u - 6 * u) / h, d10 = 3 * u * u - 4 * u + 1;
  const double d01 = (-6 * u * u + 6 * u) / h, d11 = 3 * u * u - 2 * u;
  const double slope =
      d00 * c.value_start + d10 * c.slope_start + d01 * c.value_end + d11 * c.slope_end;
  return {value, slope};
}

// The piece split at distance t from its start, as two pieces with the same cubics.
std::pair<RibbonPiece, RibbonPiece> SplitPiece(const RibbonPiece& p, double t) {
  RibbonPiece a = p, b = p;
  a.length_m = t;
  b.length_m = p.length_m - t;
  const auto split = [&](CubicHermite RibbonPiece::*channel) {
    const auto [value, slope] = EvalHermite(p.*channel, p.length_m, t);
    (a.*channel).value_end = value;
    (a.*channel).slope_end = slope;
    (b.*channel).value_start = value;
    (b.*channel).slope_start = slope;
  };
  split(&RibbonPiece::curvature);
  split(&RibbonPiece::bank);
  split(&RibbonPiece::grade);
  split(&RibbonPiece::width_left);
  split(&RibbonPiece::width_right);
  return {a, b};
}

std::vector<RibbonPiece> Pieces(const std::vector<SegmentGeometry>& g) {
  std::vector<RibbonPiece> pieces;
  pieces.reserve(g.size());
  for (const SegmentGeometry& s : g) pieces.push_back(PieceOf(s));
  return pieces;
}

// The closure equations for unknown values u: x, y and heading gaps and the length error, all
// in metres (heading scaled by `heading_scale_m`).
struct Residual {
  internal::CentreLineEnd end;
  Eigen::VectorXd r;
};

std::string Where(const SegmentLoop& loop, const std::string& field) {
  return fmt::format("{}: field '{}'", loop.path.string(), field);
}

std::string UnknownList(const SegmentLoop& loop, const std::vector<double>& u) {
  std::string out;
  for (size_t k = 0; k < loop.unknowns.size(); ++k) {
    const LoopUnknown& x = loop.unknowns[k];
    const double shown = x.kind == UnknownKind::kAngle ? RadToDeg(u[k]) : u[k];
    out += fmt::format("{}{} = {:.6g}", k == 0 ? "" : ", ", x.name, shown);
  }
  return out;
}

// The closure equations of a loop (x, y, heading and, with a target length, length) and the
// loop's centre line for unknown values x.
class Closure {
 public:
  // Integrates the loop once at `guess` for the turns it winds and the heading's scale.
  Closure(const SegmentLoop& loop, const std::vector<double>& guess)
      : loop_(loop), equations_(loop.target_length_m ? 4 : 3) {
    const internal::CentreLineEnd guess_end = Integrate(guess);
    winding_ = static_cast<int>(std::lround(guess_end.heading_rad / (2.0 * kPi)));
    heading_scale_m_ = guess_end.length_m / (2.0 * kPi);
  }

  int equations() const { return equations_; }
  double heading_scale_m() const { return heading_scale_m_; }

  // A geometry the unknowns make impossible (a track beyond the longest the builder takes, a
  // piece of no length): an InputError naming the file's unknowns, not a NumericalError out of
  // the loader (found by fuzzing, 2026-11-27: a Newton step through such a geometry).
  internal::CentreLineEnd Integrate(const std::vector<double>& x) const {
    try {
      return internal::IntegrateCentreLine(Pieces(Geometry(loop_, x)), origin_);
    } catch (const NumericalError& e) {
      throw InputError(fmt::format("{}: the loop cannot be built with these numbers ({}): {}",
                                   Where(loop_, "solve"), UnknownList(loop_, x), e.what()));
    }
  }

  Residual At(const std::vector<double>& x) const {
    Residual out;
    out.end = Integrate(x);
    out.r.resize(equations_);
    out.r[0] = out.end.x_m;
    out.r[1] = out.end.y_m;
    out.r[2] = (out.end.heading_rad - 2.0 * kPi * winding_) * heading_scale_m_;
    if (loop_.target_length_m) out.r[3] = out.end.length_m - *loop_.target_length_m;
    return out;
  }

  bool Solved(const Residual& res) const {
    const double heading = res.r[2] / heading_scale_m_;
    return std::abs(res.r[0]) < kSolvedMetres && std::abs(res.r[1]) < kSolvedMetres &&
           std::abs(heading) < kSolvedHeading &&
           (equations_ == 3 || std::abs(res.r[3]) < kSolvedMetres);
  }

 private:
  const SegmentLoop& loop_;
  const int equations_;
  const TrackStart origin_;
  int winding_ = 0;
  double heading_scale_m_ = 0.0;
};

// Central-difference Jacobian of the closure at u, steps relative to each unknown.
Eigen::MatrixXd Jacobian(const Closure& closure, const std::vector<double>& u) {
  const int equations = closure.equations();
  Eigen::MatrixXd jacobian(equations, equations);
  for (int k = 0; k < equations; ++k) {
    const double h = 1e-6 * std::max(1.0, std::abs(u[k]));
    std::vector<double> up = u, down = u;
    up[k] += h;
    down[k] -= h;
    jacobian.col(k) = (closure.At(up).r - closure.At(down).r) / (2.0 * h);
  }
  return jacobian;
}

// Damped step: keep every unknown positive and the residual decreasing. Moves u and res and
// returns true, or returns false if no fraction of the step does.
bool TakeDampedStep(const Closure& closure, const Eigen::VectorXd& step, std::vector<double>& u,
                    Residual& res) {
  for (double alpha = 1.0; alpha > 1e-6; alpha /= 2.0) {
    std::vector<double> trial = u;
    bool positive = true;
    for (int k = 0; k < closure.equations(); ++k) {
      trial[k] += alpha * step[k];
      positive = positive && trial[k] > 0.0;
    }
    if (!positive) continue;
    Residual next;
    try {
      next = closure.At(trial);
    } catch (const InputError&) {
      continue;  // a step too far: a shorter one may build
    }
    if (next.r.norm() < res.r.norm()) {
      u = trial;
      res = std::move(next);
      return true;
    }
  }
  return false;
}

// Newton's method on the closure from u (as many unknowns as equations); returns the
// iterations taken. Whether it closed is judged by the caller.
int SolveUnknowns(const SegmentLoop& loop, const Closure& closure, std::vector<double>& u) {
  const int equations = closure.equations();
  if (static_cast<int>(loop.unknowns.size()) != equations) {
    throw InputError(fmt::format(
        "{}: {} unknown(s) for {} closure equations (x, y, heading{}): declare exactly {} "
        "unknowns, or none and numbers that close the loop",
        Where(loop, "solve"), loop.unknowns.size(), equations,
        loop.target_length_m ? ", length_m" : "", equations));
  }
  int iterations = 0;
  Residual res = closure.At(u);
  for (;; ++iterations) {
    if (closure.Solved(res)) break;
    if (iterations == kMaxIterations) break;  // judged by the closure check
    Eigen::FullPivLU<Eigen::MatrixXd> lu(Jacobian(closure, u));
    lu.setThreshold(1e-8);
    if (lu.rank() < equations) {
      throw InputError(fmt::format(
          "{}: the unknowns cannot close the loop: changing them does not move the end "
          "independently in x, y, heading{} (e.g. two parallel straights both unknown); choose "
          "other unknowns ({})",
          Where(loop, "solve"), loop.target_length_m ? " and length" : "", UnknownList(loop, u)));
    }
    const Eigen::VectorXd step = lu.solve(-res.r);
    if (!TakeDampedStep(closure, step, u, res)) break;  // no further progress; judged later
  }
  return iterations;
}

// Solved values must lie in the ranges a file could give them.
void CheckSolvedRanges(const SegmentLoop& loop, const std::vector<double>& u) {
  for (size_t k = 0; k < loop.unknowns.size(); ++k) {
    const LoopUnknown& x = loop.unknowns[k];
    if (x.kind == UnknownKind::kAngle && u[k] > 2.0 * kPi) {
      throw InputError(fmt::format(
          "{}: solved value {:.6g} deg is out of range: must be in (0, 360] deg; the loop "
          "cannot close with these numbers ({})",
          Where(loop, "solve." + x.name), RadToDeg(u[k]), UnknownList(loop, u)));
    }
  }
}

// Whether solved or given, the loop must close.
void CheckClosed(const SegmentLoop& loop, const Closure& closure, const std::vector<double>& u,
                 int iterations) {
  const int equations = closure.equations();
  const Residual final_res = closure.At(u);
  const double heading_gap = final_res.r[2] / closure.heading_scale_m();
  const double position_gap = std::hypot(final_res.r[0], final_res.r[1]);
  const double length_gap = equations == 4 ? final_res.r[3] : 0.0;
  if (position_gap > kClosePosition || std::abs(heading_gap) > kCloseHeading ||
      std::abs(length_gap) > kCloseLength) {
    const std::string gaps = fmt::format(
        "the end is {:.6g} m from the start (dx {:.6g} m, dy {:.6g} m), the heading is off by "
        "{:.6g} rad{}; allowed: {} m, {} rad{}",
        position_gap, final_res.r[0], final_res.r[1], heading_gap,
        equations == 4 ? fmt::format(" and the length by {:.6g} m", length_gap) : "",
        kClosePosition, kCloseHeading, equations == 4 ? fmt::format(", {} m", kCloseLength) : "");
    if (loop.unknowns.empty()) {
      throw InputError(fmt::format(
          "{}: the loop does not close: {}. Declare unknowns under 'solve:' so that the loader "
          "closes it (docs/tracks.md)",
          Where(loop, "segments"), gaps));
    }
    throw InputError(
        fmt::format("{}: the loop cannot close with these unknowns: after {} Newton "
                    "iterations {} ({}); change the guesses or the fixed numbers",
                    Where(loop, "solve"), iterations, gaps, UnknownList(loop, u)));
  }
}

// The track of the closed loop, built from the start/finish point (the first segment split
// there), with its segments' spans.
SegmentTrack BuildLoopTrack(const SegmentLoop& loop, const std::vector<double>& u, int iterations) {
  const std::vector<SegmentGeometry> geometry = Geometry(loop, u);
  std::vector<RibbonPiece> pieces = Pieces(geometry);
  const double lead = loop.start_finish_fraction * geometry[0].length;
  if (lead > 0.0) {
    auto [before, after] = SplitPiece(pieces[0], lead);
    pieces[0] = after;
    pieces.push_back(before);
  }
  std::vector<LoopUnknown> unknowns = loop.unknowns;
  for (size_t k = 0; k < loop.unknowns.size(); ++k) unknowns[k].value = u[k];
  const TrackStart origin;
  SegmentTrack out{Track::FromPieces(loop.name, pieces, origin), {}, unknowns, iterations};
  double s = 0.0;
  for (size_t i = 0; i < geometry.size(); ++i) {
    const SegmentGeometry& g = geometry[i];
    SegmentSpan span;
    span.index = static_cast<int>(i);
    span.type = loop.segments[i].type;
    span.start_m = out.track.Wrap(s - lead);
    span.length_m = g.length;
    span.curvature_start_per_m = g.kappa0;
    span.curvature_end_per_m = g.kappa1;
    span.bank_start_rad = g.bank0;
    span.bank_end_rad = g.bank1;
    out.spans.push_back(span);
    s += g.length;
  }
  return out;
}

}  // namespace

constexpr EnumNames<SegmentType, 3> kSegmentTypes{{{{SegmentType::kStraight, "straight"},
                                                    {SegmentType::kArc, "arc"},
                                                    {SegmentType::kClothoid, "clothoid"}}}};

const char* SegmentTypeName(SegmentType type) { return kSegmentTypes.Name(type); }

SegmentTrack SolveSegmentLoop(const SegmentLoop& loop) {
  std::vector<double> u(loop.unknowns.size());
  for (size_t k = 0; k < u.size(); ++k) u[k] = loop.unknowns[k].guess;
  const Closure closure(loop, u);
  int iterations = 0;
  if (!loop.unknowns.empty()) {
    iterations = SolveUnknowns(loop, closure, u);
    CheckSolvedRanges(loop, u);
  }
  CheckClosed(loop, closure, u, iterations);
  return BuildLoopTrack(loop, u, iterations);
}

}  // namespace hotlap::track
