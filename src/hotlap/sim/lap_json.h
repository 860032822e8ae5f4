#pragma once
/// @file
/// The JSON summary of `hotlap lap --method qss --json` (docs/json-output.md).

#include <string>

#include <nlohmann/json.hpp>

#include "hotlap/sim/lap_summary.h"
#include "hotlap/track/track.h"
#include "hotlap/vehicle/car.h"

namespace hotlap::sim {

/// One corner of one lap: its means (degC; the gas-and-rim tyre's gas, rim and hot pressure with
/// its build over the cold set pressure; the bulk disc's bulk) and its energy audit (AuditJson).
nlohmann::json LapCornerJson(const CornerLapMeans& means, const CornerEnergyAudit& audit,
                             const tyre::TyreThermalParams<double>& tyre);

/// The stint's summary: track, car (its name and overrides), each lap's time and speeds, the last
/// lap's at the top level, the braking zones, per corner the peaks (degC) and wear, the slip points
/// not reached and the output files' paths.
nlohmann::json StintJson(const StintSummary& stint, const track::Track& track,
                         const vehicle::Car& car, const std::string& out_csv,
                         const std::string& out_report);

}  // namespace hotlap::sim
