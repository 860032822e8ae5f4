#pragma once
/// @file
/// A car's values of the parameters the log fits report, by the keys the fits give them
/// (FitParameter::key): to compare fitted values with the truth of a synthesized log.

#include <map>
#include <string>

#include "hotlap/common/corner.h"
#include "hotlap/vehicle/car.h"

namespace hotlap::ident {

/// The values of one corner's parameters in the fits' keys and units: the tyre's p1..p5, wp1,
/// wp2 (TyreParameterKeys), p_cp1, p_cp2; the brake's heat_partition, mass_participation and the
/// entries of P = L L' ("disc_convection_P11_W_per_K" .. "calliper_convection_P33_W_per_K").
std::map<std::string, double> FitParameterValues(const vehicle::Car& car, Corner corner);

}  // namespace hotlap::ident
