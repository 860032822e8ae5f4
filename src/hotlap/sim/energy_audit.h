#pragma once
/// @file
/// The energy audit of one corner over a stretch of a run (a lap, a log): what the car spent on
/// the tyre, the heat the tyre made of it, where the heat went, what the tyre, the rim and the
/// brake stored; each balance and its closure (docs/models.md, "Energy audit").
///
/// The energies are integrated with the temperatures (the same Runge-Kutta stages, sim/replay.cc),
/// so a balance that does not close within round-off means a flow enters one node's equation and
/// not another's, or with a wrong sign or heat capacity: a bug, not an integration error.

#include <array>

#include <nlohmann/json.hpp>

namespace hotlap::sim {

/// The energies of one corner, J, accumulated along a run; index with TyreEnergy / BrakeEnergy.
enum TyreEnergy {
  kSlidingWork,         ///< u (|Fx kappa| + |Fy tan(alpha)|): the car's work in the sliding
  kRollingWork,         ///< u c_rr |Fz|: the car's work against rolling resistance
  kTreadHeat,           ///< Q1 (000:9)
  kCarcassHeat,         ///< Q2 (000:10, or the gas-and-rim model's)
  kTreadConvection,     ///< Q3
  kTrackConduction,     ///< Q4
  kTreadRadiation,      ///< Q6
  kSidewallRadiation,   ///< Q7
  kSidewallConvection,  ///< gas-and-rim model
  kCarcassToGas,        ///< gas-and-rim model: = the gases' heat into the rim
  kRimToAir,            ///< gas-and-rim model
  kBrakeToRim,          ///< gas-and-rim model: the brake's heat into the rim
  kTyreEnergyCount
};
enum BrakeEnergy {
  kBrakeWork,           ///< u max(-Fx, 0) (000:26)
  kDiscRadiation,       ///< to the air (000:28)
  kDiscConvection,      ///< surface (000:30)
  kCalliperRadiation,   ///< (000:29)
  kCalliperConvection,  ///< (000:31)
  kVaneConvection,      ///< bulk disc
  kHubToRim,            ///< bulk disc
  kRadiationToRim,      ///< bulk disc
  kBrakeEnergyCount
};
using TyreEnergies = std::array<double, kTyreEnergyCount>;
using BrakeEnergies = std::array<double, kBrakeEnergyCount>;

/// One corner's audit over a stretch, J (the `stored` terms are the change of the nodes' heat,
/// m c dT, from the stretch's start to its end).
struct CornerEnergyAudit {
  double duration_s = 0.0;
  TyreEnergies tyre{};        ///< integrals over the stretch
  BrakeEnergies brake{};      ///< integrals over the stretch
  double tyre_stored = 0.0;   ///< tread and carcass
  double rim_stored = 0.0;    ///< gas-and-rim model
  double brake_stored = 0.0;  ///< disc (surface and bulk) and calliper
  bool has_rim = false;

  double MechanicalWork() const { return tyre[kSlidingWork] + tyre[kRollingWork]; }
  double GeneratedHeat() const { return tyre[kTreadHeat] + tyre[kCarcassHeat]; }
  /// Heat leaving the tread and carcass, J.
  double TyreHeatOut() const {
    return tyre[kTreadConvection] + tyre[kTrackConduction] + tyre[kTreadRadiation] +
           tyre[kSidewallRadiation] + tyre[kSidewallConvection] + tyre[kCarcassToGas];
  }
  double BrakeHeatOut() const {
    return brake[kDiscRadiation] + brake[kDiscConvection] + brake[kCalliperRadiation] +
           brake[kCalliperConvection] + brake[kVaneConvection] + brake[kHubToRim] +
           brake[kRadiationToRim];
  }
  /// (in - out - stored) / in of each balance; 0 where nothing came in.
  double TyreClosure() const;
  double RimClosure() const;
  double BrakeClosure() const;
  /// Generated heat over the mechanical work (at most 1 for an honest tyre); 0 without work.
  double HeatOverWork() const;
};

/// The audit between two points of a run: the accumulated energies and the stored heat at each.
CornerEnergyAudit AuditBetween(const TyreEnergies& tyre_from, const TyreEnergies& tyre_to,
                               const BrakeEnergies& brake_from, const BrakeEnergies& brake_to,
                               double tyre_stored_change, double rim_stored_change,
                               double brake_stored_change, double duration_s, bool has_rim);

/// The audit as JSON (docs/json-output.md, "Energy audit"): energies in J, the closures and the
/// heat over the work as fractions.
nlohmann::json AuditJson(const CornerEnergyAudit& audit);

}  // namespace hotlap::sim
