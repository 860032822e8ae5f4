#include "hotlap/fe/step_output.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "hotlap/common/atomic_file.h"
#include "hotlap/common/csv.h"

namespace hotlap::fe {

namespace fs = std::filesystem;

void WriteFeHistoryCsv(const fs::path& path, const std::string& step, const FeConfig& config,
                       const std::vector<HistoryRow>& history, double loaded_radius) {
  const std::vector<std::string> columns = {
      "time_s",      "rim_x_m",         "rim_z_m",         "rim_vx_mps",     "spin_rad_per_s",
      "omega_R_mps", "brake_torque_Nm", "road_fx_N",       "road_fz_N",      "slip",
      "kinetic_J",   "internal_J",      "hourglass_J",     "bulk_viscous_J", "damping_J",
      "friction_J",  "contact_J",       "external_work_J", "balance_error_J"};
  std::vector<std::vector<double>> v(columns.size());
  for (const HistoryRow& r : history) {
    const Energies& e = r.energies;
    const double row[] = {r.time_s,          r.rim_x_m,
                          r.rim_z_m,         r.rim_vx_mps,
                          r.spin_rad_per_s,  r.spin_rad_per_s * loaded_radius,
                          r.brake_torque_Nm, r.road_fx_N,
                          r.road_fz_N,       r.slip,
                          e.kinetic,         e.internal,
                          e.Hourglass(),     e.bulk_viscous,
                          e.damping,         e.friction,
                          e.contact_stored,  e.external_work,
                          e.BalanceError()};
    for (size_t k = 0; k < columns.size(); ++k) v[k].push_back(row[k]);
  }
  WriteCsv(path, {{"config", config.file.string()}, {"step", step}}, columns, v);
}

void WriteFootprintPressure(const fs::path& out, const FeConfig& config,
                            const FootprintResult& fp) {
  std::vector<std::vector<double>> map(4);
  for (const ContactPoint& p : fp.contact) {
    map[0].push_back(p.x_m);
    map[1].push_back(p.y_m);
    map[2].push_back(p.force_N);
    map[3].push_back(p.pressure_Pa);
  }
  WriteCsv(out / "footprint_pressure.csv", {{"config", config.file.string()}},
           {"x_m", "y_m", "force_N", "pressure_Pa"}, map);
  WriteFileAtomically(out / "footprint_pressure.svg", [&](std::ostream& svg) {
    const double scale = 2000.0;  // px per metre
    const double w = 0.35 * scale, h = 0.35 * scale;
    fmt::print(svg,
               "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0:.0f}\" height=\"{1:.0f}\">\n"
               "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
               "<text x=\"10\" y=\"20\" font-family=\"sans-serif\" font-size=\"14\">"
               "contact pressure, peak {2:.0f} kPa (x forward to the right, y up)</text>\n",
               w, h, 1e-3 * fp.peak_pressure_Pa);
    for (const ContactPoint& p : fp.contact) {
      const double s = fp.peak_pressure_Pa > 0 ? p.pressure_Pa / fp.peak_pressure_Pa : 0.0;
      const int red = static_cast<int>(255 * s), blue = static_cast<int>(255 * (1 - s));
      fmt::print(svg, "<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"6\" fill=\"rgb({},0,{})\"/>\n",
                 0.5 * w + scale * p.x_m, 0.5 * h - scale * p.y_m, red, blue);
    }
    svg << "</svg>\n";
  });
}

}  // namespace hotlap::fe
