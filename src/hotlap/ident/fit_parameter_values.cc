#include "hotlap/ident/fit_parameter_values.h"

#include <array>

#include "hotlap/brake/brake_thermal_fields.h"
#include "hotlap/ident/brake_thermal_fit.h"
#include "hotlap/tyre/tyre_thermal_fields.h"

namespace hotlap::ident {

std::map<std::string, double> FitParameterValues(const vehicle::Car& car, Corner corner) {
  const tyre::TyreThermalParams<double>& t = car.tyre(corner).params;
  const brake::BrakeThermalParams<double>& b = car.brake(corner).params;
  std::map<std::string, double> out;
  for (const tyre::TyreThermalField* f : tyre::FittedTyreThermalFields()) {
    out[std::string(f->key)] = f->Of(t);
  }
  // The brake's top-level fitted parameters by their keys; its convection in P = L L' (the fit
  // reports those entries, not L's).
  for (const brake::BrakeThermalField* f : brake::FittedBrakeThermalFields()) {
    if (f->member) out[f->Path()] = f->Of(b);
  }
  const std::array<double, 6> disc = ConvectionMatrixEntries(b.disc_convection);
  const std::array<double, 6> calliper = ConvectionMatrixEntries(b.calliper_convection);
  const std::vector<std::string>& keys = ConvectionMatrixKeys();
  for (size_t e = 0; e < disc.size(); ++e) {
    out[keys[e]] = disc[e];
    out[keys[disc.size() + e]] = calliper[e];
  }
  return out;
}

}  // namespace hotlap::ident
