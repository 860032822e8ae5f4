#include "hotlap/ident/car_log_fit.h"

#include <algorithm>
#include <utility>

#include <fmt/format.h>

#include "hotlap/brake/brake_thermal_fields.h"
#include "hotlap/common/error.h"
#include "hotlap/common/parallel_for.h"
#include "hotlap/common/units.h"
#include "hotlap/ident/brake_thermal_fit.h"
#include "hotlap/ident/contact_length_fit.h"
#include "hotlap/ident/fit_log.h"
#include "hotlap/ident/fit_parameter_values.h"
#include "hotlap/ident/tyre_thermal_fit.h"
#include "hotlap/tyre/tyre_thermal_fields.h"

namespace hotlap::ident {

namespace {

// What every corner's fit reads: the car, the log and what was made of it once for all corners.
struct CarFitInputs {
  const vehicle::Car& car;
  const Telemetry& log;
  const CarFitOptions& options;
  LogFitOptions fit;                        // with the joint family of all corners
  std::optional<sim::ReplayInputs> replay;  // tyre and brake
  std::vector<double> weights;              // TrapezoidWeights of the replay's time
  int laps = 1;                             // for wear_per_lap_mm
  std::string date, log_name;               // of the source comments
};

// The pair in display units: value * scale + offset.
ChannelPair Pair(std::string quantity, std::string title, std::string unit, std::string column_unit,
                 const std::vector<double>& measured, const std::vector<double>& model,
                 double scale, double offset) {
  ChannelPair p{std::move(quantity),    std::move(title), std::move(unit),
                std::move(column_unit), measured,         model};
  for (double& v : p.measured) v = v * scale + offset;
  for (double& v : p.model) v = v * scale + offset;
  return p;
}

// What the tyre fit's gas stage reads: the TPMS channels, the brake whose heat the rim takes, and
// the states that start the brake and the rim (the log's first disc and calliper samples, else
// the car's starting values).
void ReadGasStageData(const CarFitInputs& in, Corner c, TyreCornerData& d) {
  // Gauge pressure from a vacuum to 2000 kPa, as telemetry reads it; a TPMS reads 0.1 kPa.
  d.pressure = ReadLoggedChannel(in.log, "pressure", c, -tyre::kAtmosphericPressure, 2e6, 10.0);
  d.gas_temp = ReadLoggedChannel(in.log, "gas_temp", c, 223.15, 573.15, 0.01);
  if (d.pressure.column.empty() && d.gas_temp.column.empty()) return;
  d.brake = &in.car.brake(c).params;
  d.brake_samples = BrakeSamplesOf(*in.replay, c);
  const sim::ReplayInitialState start =
      sim::InitialStateFor(in.log, in.car, in.options.temperatures);
  d.brake_start = start.brakes[CornerIndex(c)];
  d.fallback_rim_temp = start.tyres[CornerIndex(c)].rim_temp;
}

// The gas stage's fit as reported: its edits name each conductance's own section (gas or rim).
void ReportGasFit(const CarFitInputs& in, const FitResult& gas, const tyre::TyreFile& tyre,
                  CornerFitOutcome& out, std::vector<FileEdit>& edits) {
  ReportedFit reported{"gas", gas, {}};
  for (const FileEdit& e : FileEditsOf(gas, "", in.date, in.log_name)) {
    for (const tyre::TyreThermalField* f : GasFitFields()) {
      if (e.key == f->key) edits.push_back({f->Path(), e.value, e.comment});
    }
  }
  // The gas path's parameters it holds at the file's values (docs/fitting.md).
  for (const char* path :
       {"gas.gas_liner_W_per_K", "gas.liner_rim_W_per_K", "rim.sidewall_air_W_per_K",
        "rim.rim_mass_kg", "rim.rim_heat_capacity_J_per_kgK", "rim.still_air_fraction"}) {
    if (const tyre::TyreThermalField* f = tyre::FindTyreThermalField(path)) {
      reported.held[std::string(f->key)] = f->Of(tyre.params);
    }
  }
  out.fits.push_back(std::move(reported));
  for (const ChannelStats& ch : gas.channels) {
    if (ch.name == "pressure") out.rms.emplace_back("rms_pressure_kPa", 1e-3 * ch.rms);
    if (ch.name == "gas_temp") out.rms.emplace_back("rms_gas_temp_C", ch.rms);
  }
}

// p1..p5 to the tread and carcass temperatures, then wp1, wp2 to the wear; with TPMS channels,
// the gas path's conductances to them.
void FitTyre(const CarFitInputs& in, Corner c, CornerFitOutcome& out,
             std::vector<FileEdit>& edits) {
  const int i = CornerIndex(c);
  TyreCornerData d;
  d.samples = CornerSamplesOf(*in.replay, c);
  d.tread = ReadLoggedChannel(in.log, "tread_temp", c, 223.15, 573.15, 0.01);
  d.carcass = ReadLoggedChannel(in.log, "carcass_temp", c, 223.15, 573.15, 0.01);
  d.wear = ReadLoggedChannel(in.log, "wear", c, -1.0, 50.0, 1e-9);
  d.weights = in.weights;
  d.fallback_tread_temp = in.car.initial.tread_temp;
  d.fallback_carcass_temp = in.car.initial.carcass_temp;
  ReadGasStageData(in, c, d);
  if (auto it = in.options.wear_per_lap_mm.find(c); it != in.options.wear_per_lap_mm.end()) {
    d.wear_total_mm = it->second * in.laps;
    d.wear_total_sd_mm = in.options.wear_sd_mm * in.laps;
  }
  const TyreFitResult r = FitTyreCorner(in.car.tyres[i], d, in.fit);
  out.warnings = r.warnings;
  if (r.thermal) {
    out.fits.push_back({"thermal", *r.thermal, {}});
    out.rms = {{"rms_tread_C", r.thermal->channels[0].rms},
               {"rms_carcass_C", r.thermal->channels[1].rms}};
    const auto e = FileEditsOf(*r.thermal, "heat_generation.", in.date, in.log_name);
    edits.insert(edits.end(), e.begin(), e.end());
  }
  if (r.wear) {
    out.fits.push_back({"wear", *r.wear, {}});
    out.rms.emplace_back("rms_wear_mm", r.wear->channels[0].rms);
    const auto e = FileEditsOf(*r.wear, "wear.", in.date, in.log_name);
    edits.insert(edits.end(), e.begin(), e.end());
  }
  // The tyre parameters no fit freed are reported as held, with the last fit.
  std::vector<std::string> fitted_keys;
  for (const ReportedFit& f : out.fits) {
    for (const FitParameter& p : f.fit.parameters) fitted_keys.push_back(p.key);
  }
  const tyre::TyreThermalParams<double>& p = in.car.tyres[i].params;
  for (const tyre::TyreThermalField* f : TyreFitFields()) {
    if (out.fits.empty()) break;
    const std::string key(f->key);
    if (std::find(fitted_keys.begin(), fitted_keys.end(), key) != fitted_keys.end()) continue;
    out.fits.back().held[key] = f->Of(p);
  }
  if (r.gas) ReportGasFit(in, *r.gas, in.car.tyres[i], out, edits);
  out.fitted = !out.fits.empty();
  out.channels = {Pair("tread_temp", "tread temperature", "\u00b0C", "C", d.tread.values,
                       r.tread_model, 1.0, -kZeroCelsius),
                  Pair("carcass_temp", "carcass temperature", "\u00b0C", "C", d.carcass.values,
                       r.carcass_model, 1.0, -kZeroCelsius),
                  Pair("wear", "wear", "mm", "mm", d.wear.values, r.wear_model, 1.0, 0.0)};
  if (r.gas) {
    out.channels.push_back(Pair("pressure", "inflation pressure", "kPa", "kPa", d.pressure.values,
                                r.pressure_model, 1e-3, 0.0));
    out.channels.push_back(Pair("gas_temp", "gas temperature", "\u00b0C", "C", d.gas_temp.values,
                                r.gas_temp_model, 1.0, -kZeroCelsius));
  }
}

// gamma, xi and the convection entries to the disc and calliper temperatures.
void FitBrake(const CarFitInputs& in, Corner c, CornerFitOutcome& out,
              std::vector<FileEdit>& edits) {
  BrakeCornerData d;
  d.samples = BrakeSamplesOf(*in.replay, c);
  d.disc = ReadLoggedChannel(in.log, "disc_temp", c, 223.15, 1773.15, 0.01);
  d.calliper = ReadLoggedChannel(in.log, "calliper_temp", c, 223.15, 1773.15, 0.01);
  d.weights = in.weights;
  d.fallback_disc_temp = in.car.initial.disc_temp;
  d.fallback_calliper_temp = in.car.initial.calliper_temp;
  const BrakeFitResult r = FitBrakeCorner(in.car.brake(c), d, in.fit);
  out.warnings = r.warnings;
  if (r.fit) {
    out.fits.push_back({"brake", *r.fit, {}});
    out.rms = {{"rms_disc_C", r.fit->channels[0].rms}, {"rms_calliper_C", r.fit->channels[1].rms}};
    // gamma and xi as reported; L as solved (its uncertainty is reported for P = L L').
    for (const FileEdit& e : FileEditsOf(*r.fit, "", in.date, in.log_name)) {
      const brake::BrakeThermalField* f = brake::FindBrakeThermalField(e.key);
      if (f && f->member) edits.push_back(e);  // a top-level key of the brake file
    }
    for (const FileEdit& e : FileEditsOf(*r.cholesky_fit, "", in.date, in.log_name)) {
      const brake::BrakeThermalField* f = brake::FindBrakeThermalField(e.key);
      if (!f || !f->polynomial) continue;  // a convection polynomial's entry
      edits.push_back({e.key, e.value,
                       fmt::format("fitted {} to {}; its uncertainty is reported for P = L L' "
                                   "(fit report)",
                                   in.date, in.log_name)});
    }
    out.fitted = true;
  }
  out.channels = {Pair("disc_temp", "disc temperature", "\u00b0C", "C", d.disc.values, r.disc_model,
                       1.0, -kZeroCelsius),
                  Pair("calliper_temp", "calliper temperature", "\u00b0C", "C", d.calliper.values,
                       r.calliper_model, 1.0, -kZeroCelsius)};
}

// p_cp1, p_cp2 to the rolling radii.
void FitContact(const CarFitInputs& in, Corner c, CornerFitOutcome& out,
                std::vector<FileEdit>& edits) {
  const std::vector<double> fz = in.log.FilledChannel("fz", c);
  const LoggedChannel radius = ReadLoggedChannel(in.log, "rolling_radius", c, 0.05, 2.0, 1e-7);
  const ContactLengthFitResult r = FitContactLength(in.car.tyre(c), fz, radius, in.fit.solver);
  out.warnings = r.warnings;
  if (r.fit) {
    out.fits.push_back({"contact length", *r.fit, {}});
    out.rms = {{"rms_rolling_radius_mm", 1e3 * r.fit->channels[0].rms}};
    edits = FileEditsOf(*r.fit, "contact_length.", in.date, in.log_name);
    out.fitted = true;
  }
  out.channels = {Pair("rolling_radius", "rolling radius", "mm", "mm", radius.values,
                       r.radius_model, 1e3, 0.0)};
}

void CheckOptions(const CarFitOptions& o) {
  if (o.corners.empty()) throw InputError("fit: no corner to fit");
  for (Corner c : o.corners) {
    if (std::find(kAllCorners.begin(), kAllCorners.end(), c) == kAllCorners.end()) {
      throw InputError(fmt::format("fit: unknown corner ({})", static_cast<int>(c)));
    }
  }
  for (size_t n = 0; n < o.corners.size(); ++n) {
    if (std::count(o.corners.begin(), o.corners.end(), o.corners[n]) > 1) {
      throw InputError(
          fmt::format("fit: corner '{}' is asked for more than once", CornerName(o.corners[n])));
    }
  }
  if (o.threads < 1) {
    throw InputError(fmt::format("fit: threads must be at least 1 (got {})", o.threads));
  }
  if (o.laps && *o.laps < 1) {
    throw InputError(fmt::format("fit: laps must be at least 1 (got {})", *o.laps));
  }
  if (!(o.wear_sd_mm > 0.0)) {
    throw InputError(
        fmt::format("fit: the wear standard deviation must be positive (got {} mm)", o.wear_sd_mm));
  }
}

// The gas stage's model parameters over the corners it may fit (a gas-and-rim tyre and a TPMS
// column): they join the report's joint family.
int GasParametersFitted(const vehicle::Car& car, const Telemetry& log,
                        const std::vector<Corner>& corners) {
  int n = 0;
  for (Corner c : corners) {
    if (car.tyre(c).params.HasGasAndRim() && (log.Has("pressure", c) || log.Has("gas_temp", c))) {
      n += static_cast<int>(GasFitFields().size());
    }
  }
  return n;
}

}  // namespace

int ModelParametersPerCorner(CarFitKind kind) {
  switch (kind) {
    case CarFitKind::kTyre:
      return static_cast<int>(TyreParameterKeys().size());
    case CarFitKind::kBrake:
      return static_cast<int>(BrakeParameterKeys().size());
    case CarFitKind::kContactLength:
      break;
  }
  return 2;
}

CarFitResult FitCarToLog(const vehicle::Car& car, const Telemetry& log,
                         const CarFitOptions& options) {
  CheckOptions(options);
  CarFitResult result;
  // The joint intervals hold every model parameter fitted, over all corners.
  result.joint_family_size =
      static_cast<int>(options.corners.size()) * ModelParametersPerCorner(options.kind);
  if (options.kind == CarFitKind::kTyre) {
    result.joint_family_size += GasParametersFitted(car, log, options.corners);
  }
  LogFitOptions fit = options.fit;
  fit.solver.joint_family_size = result.joint_family_size;
  std::optional<sim::ReplayInputs> replay;
  std::vector<double> weights;
  if (options.kind != CarFitKind::kContactLength) {
    replay = sim::ReplayInputsFromTelemetry(log, options.temperatures);
    weights = TrapezoidWeights(replay->time);
  }
  const CarFitInputs in{
      car,
      log,
      options,
      fit,
      std::move(replay),
      std::move(weights),
      options.laps.value_or(MetadataInt(log, "laps").value_or(1)),
      options.source_date.empty() ? TodayIsoDate() : options.source_date,
      options.source_log.empty() ? log.path().filename().string() : options.source_log};

  result.corners.resize(options.corners.size());
  ParallelFor(options.corners.size(), options.threads, [&](size_t n) {
    const Corner c = options.corners[n];
    CornerFitOutcome& out = result.corners[n];
    out.corner = c;
    if (options.truth) out.truth = FitParameterValues(*options.truth, c);
    switch (options.kind) {
      case CarFitKind::kTyre:
        FitTyre(in, c, out, result.edits.tyres[CornerIndex(c)]);
        break;
      case CarFitKind::kBrake:
        FitBrake(in, c, out, result.edits.brakes[CornerIndex(c)]);
        break;
      case CarFitKind::kContactLength:
        FitContact(in, c, out, result.edits.tyres[CornerIndex(c)]);
        break;
    }
  });
  return result;
}

std::vector<std::string> CornerWarnings(const CornerFitOutcome& corner) {
  std::vector<std::string> all = corner.warnings;
  for (const ReportedFit& r : corner.fits) {
    for (const std::string& w : r.fit.AllWarnings()) all.push_back(r.title + ": " + w);
  }
  return all;
}

std::vector<std::pair<const FitParameter*, const ParameterEstimate*>> ModelParameters(
    const CornerFitOutcome& corner) {
  std::vector<std::pair<const FitParameter*, const ParameterEstimate*>> out;
  for (const ReportedFit& r : corner.fits) {
    for (size_t i = 0; i < r.fit.parameters.size(); ++i) {
      if (r.fit.parameters[i].role == ParameterRole::kModel) {
        out.emplace_back(&r.fit.parameters[i], &r.fit.estimates[i]);
      }
    }
  }
  return out;
}

}  // namespace hotlap::ident
