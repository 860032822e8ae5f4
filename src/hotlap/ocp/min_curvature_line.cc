#include "hotlap/ocp/min_curvature_line.h"

#include <array>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/ocp/ipopt_solve.h"
#include "hotlap/track/track_point.h"

namespace hotlap::ocp {

namespace {

// The line's squared curvature times its length at point k: with P_j = C_j + n_j a_j,
// P' = (P_{k+1} - P_{k-1}) / 2 and P'' = P_{k+1} - 2 P_k + P_{k-1} per point, the curvature is
// (x' y'' - y' x'') / |P'|^3 and the point stands for |P'| of path: in (n_prev, n, n_next).
struct CurvatureFn {
  std::array<double, 2> c_prev, c_here, c_next;  // centre-line points
  std::array<double, 2> a_prev, a_here, a_next;  // lateral units
  template <class T>
  void operator()(const T* in, T* out) const {
    using std::sqrt;
    T p[3][2];
    for (int d = 0; d < 2; ++d) {
      p[0][d] = c_prev[d] + in[0] * a_prev[d];
      p[1][d] = c_here[d] + in[1] * a_here[d];
      p[2][d] = c_next[d] + in[2] * a_next[d];
    }
    const T dx = 0.5 * (p[2][0] - p[0][0]), dy = 0.5 * (p[2][1] - p[0][1]);
    const T ddx = p[2][0] - 2.0 * p[1][0] + p[0][0], ddy = p[2][1] - 2.0 * p[1][1] + p[0][1];
    const T speed2 = dx * dx + dy * dy;
    const T speed = sqrt(speed2);
    const T cross = dx * ddy - dy * ddx;
    // (kappa R0)^2 |P'| with R0 = 100 m: R0^2 cross^2 / |P'|^5.
    const T kappa = cross / (speed2 * speed) * 100.0;
    out[0] = kappa * kappa * speed;
  }
};

}  // namespace

track::RacingLine MinimumCurvatureLine(const track::Track& track,
                                       const MinimumCurvatureOptions& options) {
  // A negative margin would take the line off the road (the QSS then lapped faster on it).
  if (!(options.margin_m > 0.0)) {
    throw InputError(fmt::format("racing line: the margin from the edges, {:g} m, must be > 0",
                                 options.margin_m));
  }
  track::RacingLine line = track::CentreLine(track, options.step_m);
  const size_t n = line.s_m.size();
  std::vector<std::array<double, 2>> centre(n), lateral(n);
  ElementNlp nlp;
  std::vector<int> var(n);
  for (size_t k = 0; k < n; ++k) {
    const track::TrackPoint p = track.At(line.s_m[k]);
    const Eigen::Vector3d a = track::LateralUnit(p);
    centre[k] = {p.x_m, p.y_m};
    lateral[k] = {a[0], a[1]};
    const double lo = -(p.width_right_m - options.margin_m);
    const double hi = p.width_left_m - options.margin_m;
    if (!(hi > lo)) {
      throw InputError(fmt::format(
          "racing line: the track at {:.0f} m is {:.2f} m wide, narrower than twice the {:.2f} m "
          "margin",
          line.s_m[k], p.width_left_m + p.width_right_m, options.margin_m));
    }
    var[k] = nlp.AddVariable(0.0, lo, hi, 1.0);
  }
  // The integral of kappa^2 over the path, in units of (1 / 100 m)^2 m, of order one per point.
  for (size_t k = 0; k < n; ++k) {
    const size_t prev = (k + n - 1) % n, next = (k + 1) % n;
    const CurvatureFn f{centre[prev],  centre[k],  centre[next],
                        lateral[prev], lateral[k], lateral[next]};
    nlp.AddElement(MakeElement<3, 1>(f), {var[prev], var[k], var[next]},
                   {{{Target::kObjective, 1.0}}});
  }
  nlp.Finalize();
  IpoptOptions ipopt;
  ipopt.tolerance = 1e-9;
  const SolveResult r = SolveWithIpopt(nlp, ipopt);
  if (!r.ok())
    throw NumericalError("racing line: the minimum-curvature solve failed: " + r.message);
  for (size_t k = 0; k < n; ++k) line.offset_m[k] = r.x[var[k]];
  return line;
}

}  // namespace hotlap::ocp
