#include "hotlap/sim/energy_audit.h"

#include "hotlap/common/json_output.h"

namespace hotlap::sim {

namespace {

double Closure(double in, double out, double stored) {
  return in > 0.0 ? (in - out - stored) / in : 0.0;
}

}  // namespace

double CornerEnergyAudit::TyreClosure() const {
  return Closure(GeneratedHeat(), TyreHeatOut(), tyre_stored);
}

double CornerEnergyAudit::RimClosure() const {
  return Closure(tyre[kCarcassToGas] + tyre[kBrakeToRim], tyre[kRimToAir], rim_stored);
}

double CornerEnergyAudit::BrakeClosure() const {
  return Closure(brake[kBrakeWork], BrakeHeatOut(), brake_stored);
}

double CornerEnergyAudit::HeatOverWork() const {
  const double work = MechanicalWork();
  return work > 0.0 ? GeneratedHeat() / work : 0.0;
}

CornerEnergyAudit AuditBetween(const TyreEnergies& tyre_from, const TyreEnergies& tyre_to,
                               const BrakeEnergies& brake_from, const BrakeEnergies& brake_to,
                               double tyre_stored_change, double rim_stored_change,
                               double brake_stored_change, double duration_s, bool has_rim) {
  CornerEnergyAudit a;
  a.duration_s = duration_s;
  for (int i = 0; i < kTyreEnergyCount; ++i) a.tyre[i] = tyre_to[i] - tyre_from[i];
  for (int i = 0; i < kBrakeEnergyCount; ++i) a.brake[i] = brake_to[i] - brake_from[i];
  a.tyre_stored = tyre_stored_change;
  a.rim_stored = rim_stored_change;
  a.brake_stored = brake_stored_change;
  a.has_rim = has_rim;
  return a;
}

nlohmann::json AuditJson(const CornerEnergyAudit& a) {
  const auto r = [](double x) { return RoundSignificant(x); };
  const TyreEnergies& t = a.tyre;
  const BrakeEnergies& b = a.brake;
  nlohmann::json j = {{"duration_s", r(a.duration_s)},
                      {"mechanical_work_J",
                       {{"sliding", r(t[kSlidingWork])},
                        {"rolling", r(t[kRollingWork])},
                        {"total", r(a.MechanicalWork())}}},
                      {"heat_generated_J",
                       {{"tread", r(t[kTreadHeat])},
                        {"carcass", r(t[kCarcassHeat])},
                        {"total", r(a.GeneratedHeat())}}},
                      {"heat_over_work", r(a.HeatOverWork())},
                      {"tyre_heat_out_J",
                       {{"tread_convection", r(t[kTreadConvection])},
                        {"track_conduction", r(t[kTrackConduction])},
                        {"tread_radiation", r(t[kTreadRadiation])},
                        {"sidewall_radiation", r(t[kSidewallRadiation])},
                        {"sidewall_convection", r(t[kSidewallConvection])},
                        {"carcass_to_gas", r(t[kCarcassToGas])}}},
                      {"tyre_stored_J", r(a.tyre_stored)},
                      {"tyre_closure", r(a.TyreClosure())},
                      {"brake_J",
                       {{"work", r(b[kBrakeWork])},
                        {"disc_radiation", r(b[kDiscRadiation])},
                        {"disc_convection", r(b[kDiscConvection])},
                        {"calliper_radiation", r(b[kCalliperRadiation])},
                        {"calliper_convection", r(b[kCalliperConvection])},
                        {"vane_convection", r(b[kVaneConvection])},
                        {"hub_to_rim", r(b[kHubToRim])},
                        {"radiation_to_rim", r(b[kRadiationToRim])},
                        {"stored", r(a.brake_stored)}}},
                      {"brake_closure", r(a.BrakeClosure())}};
  if (a.has_rim) {
    j["rim_J"] = {{"from_gas", r(t[kCarcassToGas])},
                  {"from_brake", r(t[kBrakeToRim])},
                  {"to_air", r(t[kRimToAir])},
                  {"stored", r(a.rim_stored)}};
    j["rim_closure"] = r(a.RimClosure());
  }
  return j;
}

}  // namespace hotlap::sim
