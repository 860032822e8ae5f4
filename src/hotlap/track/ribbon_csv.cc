#include "hotlap/track/ribbon_csv.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "hotlap/common/csv.h"
#include "hotlap/common/units.h"

namespace hotlap::track {

void WriteRibbonCsv(const std::filesystem::path& path, const TrackFile& file, double step_m) {
  const Track& t = file.track;
  // Steps of at most step_m (a length that is a whole number of steps gives exactly those).
  const int intervals = std::max(1, static_cast<int>(std::ceil(t.length_m() / step_m - 1e-9)));
  const std::vector<TrackPoint> points = t.Sample(intervals);
  const std::vector<std::string> columns = {"distance_m",
                                            "x_m",
                                            "y_m",
                                            "z_m",
                                            "heading_rad",
                                            "curvature_per_m",
                                            "curvature_rate_per_m2",
                                            "geodesic_curvature_per_m",
                                            "normal_curvature_per_m",
                                            "bank_deg",
                                            "grade_deg",
                                            "width_left_m",
                                            "width_right_m"};
  std::vector<std::vector<double>> values(columns.size());
  for (const TrackPoint& p : points) {
    const double row[] = {p.s_m,
                          p.x_m,
                          p.y_m,
                          p.z_m,
                          p.heading_rad,
                          p.curvature_per_m,
                          p.curvature_rate_per_m2,
                          GeodesicCurvature(p),
                          NormalCurvature(p),
                          RadToDeg(p.bank_rad),
                          RadToDeg(p.grade_rad),
                          p.width_left_m,
                          p.width_right_m};
    for (size_t c = 0; c < columns.size(); ++c) values[c].push_back(row[c]);
  }
  const std::vector<std::pair<std::string, std::string>> metadata = {
      {"track", t.name()},
      {"source", fmt::format("hotlap {} track info", HOTLAP_VERSION)},
      {"track_file", file.path.string()},
      {"format", TrackFormatName(file.format)},
      {"length_m", fmt::format("{:.9g}", t.length_m())},
  };
  WriteCsv(path, metadata, columns, values);
}

}  // namespace hotlap::track
