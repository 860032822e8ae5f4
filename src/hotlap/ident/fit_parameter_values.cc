#include "hotlap/ident/fit_parameter_values.h"

#include <array>

#include <fmt/format.h>

#include "hotlap/ident/brake_thermal_fit.h"

namespace hotlap::ident {

std::map<std::string, double> FitParameterValues(const vehicle::Car& car, Corner corner) {
  const tyre::TyreThermalParams<double>& t = car.tyre(corner).params;
  const brake::BrakeThermalParams<double>& b = car.brake(corner).params;
  std::map<std::string, double> out = {{"p1", t.p1},
                                       {"p2_J_per_kgN", t.p2},
                                       {"p3_J_per_kgN", t.p3},
                                       {"p4_J_per_kgN", t.p4},
                                       {"p5_W_per_m2K", t.p5},
                                       {"wp1_mm_per_s", t.wear_coeff},
                                       {"wp2", t.wear_exponent},
                                       {"p_cp1", t.contact_length_coeff},
                                       {"p_cp2", t.contact_length_exponent},
                                       {"heat_partition", b.heat_partition},
                                       {"mass_participation", b.mass_participation}};
  constexpr std::array<const char*, 6> kNames = {"P11", "P21", "P22", "P31", "P32", "P33"};
  const std::array<double, 6> disc = ConvectionMatrixEntries(b.disc_convection);
  const std::array<double, 6> calliper = ConvectionMatrixEntries(b.calliper_convection);
  for (size_t e = 0; e < kNames.size(); ++e) {
    out[fmt::format("disc_convection_{}_W_per_K", kNames[e])] = disc[e];
    out[fmt::format("calliper_convection_{}_W_per_K", kNames[e])] = calliper[e];
  }
  return out;
}

}  // namespace hotlap::ident
