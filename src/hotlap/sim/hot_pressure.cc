#include "hotlap/sim/hot_pressure.h"

#include <variant>

#include "hotlap/tyre/rolling_radius.h"
#include "hotlap/tyre/tyre_thermal.h"

namespace hotlap::sim {

vehicle::Car WithHotPressures(const vehicle::Car& car, const std::array<double, 4>& pressure) {
  vehicle::Car out = car;
  if (!out.vehicle) return out;
  for (int c = 0; c < 4; ++c) {
    if (!car.tyres[c].params.HasGasAndRim() || pressure[c] <= 0.0) continue;
    vehicle::CornerSetup& setup = out.vehicle->corners[c];
    const double cold = setup.pressure;
    setup.pressure = pressure[c];
    // The rollout as set (measured, or the .tir's free radius) grows with the air
    // (tyre/rolling_radius.h).
    if (const auto* mf = std::get_if<tyre::MagicFormulaModel<double>>(&setup.forces.params)) {
      const tyre::MagicFormulaParams<double>& p = mf->params;
      setup.rolling_radius += tyre::CalcRollingRadiusChange(p, p.FNOMIN, cold, pressure[c]);
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
