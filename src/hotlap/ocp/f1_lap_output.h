#pragma once
/// @file
/// What `hotlap optimise` reports of the limebeer-2014-f1 car's lap (docs/f1-peer.md): its
/// channels as CSV, its summary lines and its JSON summary, with the peer's lap time on the
/// peer benchmark's track.

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "hotlap/ocp/f1_lap_problem.h"
#include "hotlap/track/track.h"
#include "hotlap/vehicle/f1_car.h"

namespace hotlap::ocp {

/// fastest-lap's lap time for this car on its 500-point Catalunya (shared/data/peer README), s.
inline constexpr double kF1PeerLapTime = 77.791;

/// The channels (distance, time, speeds, yaw rate, offset, heading error, steer, throttle, then
/// per corner slip ratio, lateral slip and the wheel forces) as CSV, written atomically.
void WriteF1LapCsv(const std::filesystem::path& path, const F1LapSolution& lap,
                   const track::Track& track, const vehicle::F1CarParams& car);

/// The solve's outcome, lap and guess times, speeds and the problem's size: two lines, each
/// ending in a newline.
std::string F1LapText(const F1LapSolution& lap);

/// The JSON summary (docs/json-output.md); on catalunya-fl also the peer's lap time and the
/// difference from it in percent.
nlohmann::json F1LapJson(const F1LapSolution& lap, const std::string& track_name,
                         const std::string& car_name, int mesh_points);

}  // namespace hotlap::ocp
