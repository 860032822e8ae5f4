#include "hotlap/sim/hot_pressure.h"

#include "hotlap/tyre/tyre_thermal.h"

namespace hotlap::sim {

vehicle::Car WithHotPressures(const vehicle::Car& car, const std::array<double, 4>& pressure) {
  vehicle::Car out = car;
  if (!out.vehicle) return out;
  for (int c = 0; c < 4; ++c) {
    if (car.tyres[c].params.HasGasAndRim() && pressure[c] > 0.0) {
      out.vehicle->corners[c].pressure = pressure[c];
    }
  }
  return out;
}

std::array<double, 4> MeanHotPressures(const vehicle::Car& car, const ReplayResult& replay) {
  std::array<double, 4> out{};
  const std::vector<double>& t = replay.time;
  for (int c = 0; c < 4; ++c) {
    const std::vector<double>& p = replay.corners[c].pressure;
    if (!car.tyres[c].params.HasGasAndRim() || p.size() != t.size() || t.size() < 2) continue;
    out[c] = CalcHistoryStats(t, p).mean;
  }
  return out;
}

std::array<double, 4> HotPressuresAt(const vehicle::Car& car, const ReplayInitialState& state,
                                     double speed) {
  std::array<double, 4> out{};
  for (int c = 0; c < 4; ++c) {
    const tyre::TyreThermalParams<double>& p = car.tyres[c].params;
    if (!p.HasGasAndRim()) continue;
    out[c] =
        tyre::CalcTyreGas(p, state.tyres[c].carcass_temp, state.tyres[c].rim_temp, speed).pressure;
  }
  return out;
}

}  // namespace hotlap::sim
