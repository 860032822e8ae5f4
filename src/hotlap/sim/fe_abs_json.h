#pragma once
/// @file
/// The abs step's part of the `hotlap fe abs --json` summary (docs/fe-tyre.md): the FE tyre's
/// braking event under the ABS controller (fe_abs_stop.h).

#include <nlohmann/json.hpp>

#include "hotlap/sim/fe_abs_stop.h"

namespace hotlap::sim {

/// The stop's speeds, distance, slip, brake torque, control cycles, cord strain
/// (fe::CordStrainJson; fe::CordStrainWarning says when it is too high) and the energies at its
/// end.
nlohmann::json FeAbsStopJson(const FeAbsStopResult& r, double duration_s,
                             const fe::Energies& energies);

}  // namespace hotlap::sim
