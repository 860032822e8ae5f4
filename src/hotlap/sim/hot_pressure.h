#pragma once
/// @file
/// The pressure that acts: a gas-and-rim tyre's force model and rolling radius at its hot
/// pressure instead of the cold set. The Magic Formula takes the inflation pressure (its PPX*, PPY* terms about the
/// file's NOMPRES); the set-up's `pressure` is the cold set, and over a run the gas heats it by
/// 5-18 psi (docs/models.md). The QSS lap runs each lap at the hot pressures the last lap had (the
/// first at its start's), the optimal lap at its guess lap's: a lap's pressure moves by about 1%
/// (docs/validation/optimal-lap.md), so a constant a lap is the gas's own time scale.

#include <array>

#include "hotlap/sim/replay.h"
#include "hotlap/vehicle/car.h"

namespace hotlap::sim {

/// The car with corner c's force model at `pressure[c]` (Pa, gauge) where its tyre runs the
/// gas-and-rim model (the set-up's cold pressure elsewhere, and for a car without vehicle
/// sections, the car as it is), and a Magic Formula corner's rolling radius moved by what the
/// pressure changes in the file's effective rolling radius at its nominal load
/// (tyre/rolling_radius.h): the stagger follows the air.
vehicle::Car WithHotPressures(const vehicle::Car& car, const std::array<double, 4>& pressure);

/// Each gas-and-rim tyre's time-mean hot pressure over a replay, Pa; 0 for a tyre without gas.
std::array<double, 4> MeanHotPressures(const vehicle::Car& car, const ReplayResult& replay);

/// Each gas-and-rim tyre's hot pressure at a thermal state with the car at `speed` (m/s; the gas
/// is quasi-static), Pa; 0 for a tyre without gas.
std::array<double, 4> HotPressuresAt(const vehicle::Car& car, const ReplayInitialState& state,
                                     double speed);

}  // namespace hotlap::sim
