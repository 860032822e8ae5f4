#include "hotlap/track/racing_line.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "hotlap/common/csv.h"
#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/track/periodic_spline.h"
#include "hotlap/track/track_point.h"

namespace hotlap::track {

namespace {

Eigen::Vector3d PositionAt(const Track& track, double s, double n) {
  return PointAtOffset(track.At(s), n);
}

}  // namespace

double RacingLine::OffsetAt(double s, double length_m) const {
  const size_t n = s_m.size();
  const double step = length_m / static_cast<double>(n);
  double x = std::fmod(s, length_m);
  if (x < 0.0) x += length_m;
  const double f = x / step;
  const size_t i = std::min(static_cast<size_t>(f), n - 1);
  const double w = f - static_cast<double>(i);
  return offset_m[i] + w * (offset_m[(i + 1) % n] - offset_m[i]);
}

RacingLine CentreLine(const Track& track, double step_m) {
  const int n = std::max(16, static_cast<int>(std::round(track.length_m() / step_m)));
  RacingLine line;
  for (int k = 0; k < n; ++k) {
    line.s_m.push_back(track.length_m() * k / n);
    line.offset_m.push_back(0.0);
  }
  return line;
}

RacingLine ResampleLine(std::span<const double> s, std::span<const double> n, const Track& track,
                        double step_m) {
  const double length = track.length_m();
  // Knots from the first row; a closing row one lap after the first is the first again.
  std::vector<double> knots, values;
  for (size_t i = 0; i < s.size(); ++i) {
    if (i > 0 && s[i] - s[0] >= length - 1e-3) break;  // within a millimetre
    knots.push_back(s[i] - s[0]);
    values.push_back(n[i]);
  }
  if (knots.size() < 3) {
    throw InputError(
        fmt::format("a racing line needs 3 distinct points or more, got {}", knots.size()));
  }
  // The periodic cubic spline through the rows (C2): a line's curvature is its offset's second
  // derivative, which linear interpolation would pile onto the rows as spikes.
  const std::vector<double> slopes = internal::PeriodicSplineSlopes(knots, values, length);
  const auto offset_at = [&](double x) {
    return internal::PeriodicHermiteValue(knots, values, slopes, length, x - s[0]);
  };
  RacingLine line = CentreLine(track, step_m);
  for (size_t k = 0; k < line.s_m.size(); ++k) line.offset_m[k] = offset_at(line.s_m[k]);
  return line;
}

RacingLine ReadRacingLine(const std::filesystem::path& path, const Track& track, double step_m) {
  const CsvTable table = ReadCsv(path);
  const std::vector<double>& s = table.Column("distance_m");
  const std::vector<double>& n = table.Column("offset_m");
  const double length = track.length_m();
  const size_t rows = s.size();
  const auto fail = [&](size_t row, const std::string& what) {
    return InputError(fmt::format("{}:{}: {}", path.string(), table.line_numbers[row], what));
  };
  for (size_t r = 0; r < rows; ++r) {
    if (std::isnan(s[r]) || std::isnan(n[r])) throw fail(r, "empty distance_m or offset_m");
    if (s[r] < 0.0 || s[r] > length + 1e-6) {
      throw fail(r, fmt::format("distance_m {} is outside the lap [0, {:.3f}] m", s[r], length));
    }
    if (r > 0 && !(s[r] > s[r - 1])) {
      throw fail(r, fmt::format("distance_m {} does not increase", s[r]));
    }
    const TrackPoint p = track.At(std::min(s[r], length));
    if (n[r] > p.width_left_m || n[r] < -p.width_right_m) {
      throw fail(r, fmt::format("offset_m {:.3f} is off the track (allowed [{:.3f}, {:.3f}] m)",
                                n[r], -p.width_right_m, p.width_left_m));
    }
  }
  if (rows < 4)
    throw InputError(fmt::format("{}: a racing line needs 4 rows or more", path.string()));
  return ResampleLine(s, n, track, step_m);
}

std::vector<LinePoint> SampleLine(const Track& track, const RacingLine& line, double step_m) {
  const double length = track.length_m();
  // Path length between the line's own points (fine enough: 2 m points on >100 m radii).
  const size_t m = line.s_m.size();
  std::vector<double> cumulative(m + 1, 0.0);
  Eigen::Vector3d prev = PositionAt(track, line.s_m[0], line.offset_m[0]);
  for (size_t k = 1; k <= m; ++k) {
    const double s = k < m ? line.s_m[k] : length;
    const Eigen::Vector3d p = PositionAt(track, s, line.offset_m[k % m]);
    cumulative[k] = cumulative[k - 1] + (p - prev).norm();
    prev = p;
  }
  const double path_length = cumulative[m];
  const int count = std::max(16, static_cast<int>(std::round(path_length / step_m)));
  const double step = path_length / count;
  std::vector<LinePoint> out(count);
  for (int i = 0; i < count; ++i) {
    const double path = step * i;
    const auto it = std::upper_bound(cumulative.begin(), cumulative.end(), path);
    const size_t j = std::min(static_cast<size_t>(it - cumulative.begin()), m) - 1;
    const double w = (path - cumulative[j]) / (cumulative[j + 1] - cumulative[j]);
    const double s0 = line.s_m[j], s1 = j + 1 < m ? line.s_m[j + 1] : length;
    const double s = s0 + w * (s1 - s0);
    const double n = line.offset_m[j] + w * (line.offset_m[(j + 1) % m] - line.offset_m[j]);
    const TrackPoint p = track.At(s);
    const Eigen::Vector3d pos = PointAtOffset(p, n);
    out[i] = {path, p.s_m, n, pos[0], pos[1], 0.0, p.bank_rad, p.grade_rad, 0.0};
  }
  // Heading from the chord to the next point, made continuous; curvature from its change,
  // central and then averaged over three points.
  for (int i = 0; i < count; ++i) {
    const LinePoint& a = out[i];
    const LinePoint& b = out[(i + 1) % count];
    out[i].heading_rad = std::atan2(b.y_m - a.y_m, b.x_m - a.x_m);
    if (i > 0) {
      double d = out[i].heading_rad - out[i - 1].heading_rad;
      d -= 2.0 * kPi * std::round(d / (2.0 * kPi));
      out[i].heading_rad = out[i - 1].heading_rad + d;
    }
  }
  const double turns = 2.0 * kPi * track.winding();
  std::vector<double> raw(count);
  for (int i = 0; i < count; ++i) {
    // Chord headings belong to the mid-points; their difference to the point between them.
    const double h_next = out[i].heading_rad;
    const double h_prev = i > 0 ? out[i - 1].heading_rad : out[count - 1].heading_rad - turns;
    raw[i] = (h_next - h_prev) / step;
  }
  for (int i = 0; i < count; ++i) {
    out[i].curvature_per_m =
        (raw[(i + count - 1) % count] + 2.0 * raw[i] + raw[(i + 1) % count]) / 4.0;
  }
  return out;
}

}  // namespace hotlap::track
