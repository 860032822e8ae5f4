#pragma once
/// @file
/// The abs step's part of the `hotlap fe abs --json` summary (docs/fe-tyre.md): the FE tyre's
/// braking event under the ABS controller (fe_abs_stop.h).

#include <nlohmann/json.hpp>

#include "hotlap/abs/abs_metrics.h"
#include "hotlap/abs/fe_abs_ensemble.h"
#include "hotlap/abs/fe_abs_stop.h"

namespace hotlap::sim {

/// The stop's speeds, distance, slip, brake torque, control cycles, cord strain
/// (fe::CordStrainJson; fe::CordStrainWarning says when it is too high) and the energies at its
/// end.
nlohmann::json FeAbsStopJson(const FeAbsStopResult& r, double duration_s,
                             const fe::Energies& energies);

/// The lumped `hotlap abs` run of the same event beside it ("lumped"): its cycles, the slip
/// after the first, its final speed and distance.
nlohmann::json LumpedAbsJson(const AbsMetrics& m);

/// An ensemble of stops ("abs_ensemble"): its size and perturbation, each figure's statistic
/// over the members (n, mean, standard_error, sd, min, max, unit) and each member's figures.
nlohmann::json FeAbsEnsembleJson(const FeAbsEnsembleResult& e, double duration_s);

}  // namespace hotlap::sim
