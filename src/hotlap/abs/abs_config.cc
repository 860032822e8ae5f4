#include "hotlap/abs/abs_config.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "hotlap/brake/abs_params_io.h"
#include "hotlap/common/data_path.h"
#include "hotlap/common/error.h"
#include "hotlap/common/string_match.h"
#include "hotlap/common/units.h"
#include "hotlap/common/yaml_reader.h"

namespace hotlap::sim {

namespace fs = std::filesystem;

namespace {

constexpr double kMPa = 1e6;

double ReadCelsius(YamlReader& y, std::string_view key) {
  return CelsiusToKelvin(y.Number(key, Range::Closed(-60.0, 1200.0, "degC")));
}

AbsEvent ReadEvent(YamlReader& e) {
  AbsEvent ev;
  ev.initial_speed_mps = e.Number("initial_speed_mps", Range::OpenClosed(0.0, 150.0, "m/s"));
  ev.duration_s = e.Number("duration_s", Range::OpenClosed(0.0, 600.0, "s"));
  ev.vehicle = e.Choice("vehicle", {"free", "drum"}) == "free" ? AbsVehicleMode::kFree
                                                               : AbsVehicleMode::kDrum;
  ev.surface = e.String("surface");
  ev.stop_speed_mps = e.Number("stop_speed_mps", Range::OpenClosed(0.0, 5.0, "m/s"));
  ev.ambient_temp_K = ReadCelsius(e, "ambient_temp_C");
  ev.initial_disc_temp_K = ReadCelsius(e, "initial_disc_temp_C");
  ev.initial_calliper_temp_K = ReadCelsius(e, "initial_calliper_temp_C");
  const double steps = e.Number("integration_steps_per_period", Range::Closed(1.0, 1000.0, ""));
  if (steps != std::floor(steps)) {
    e.Fail("integration_steps_per_period", fmt::format("{:g} is not a whole number", steps));
  }
  ev.steps_per_period = static_cast<int>(steps);
  e.Finish();
  return ev;
}

AbsWheelParams<double> ReadWheel(YamlReader& w, fs::path& tyre_file) {
  AbsWheelParams<double> p;
  tyre_file = w.FilePath("tyre_file");
  p.vertical_load = w.Number("vertical_load_N", Range::Positive("N"));
  p.mass = p.vertical_load / kGravity;  // the quarter car, m = Fz / g (spec section 8)
  p.radius = w.Number("loaded_radius_m", Range::OpenClosed(0.0, 2.0, "m"));
  p.inertia = w.Number("inertia_kg_m2", Range::Positive("kg m^2"));
  p.relaxation_length = w.Number("relaxation_length_m", Range::OpenClosed(0.0, 2.0, "m"));
  p.rolling_resistance = w.Number("rolling_resistance_coefficient", Range::Closed(0.0, 0.1, ""));
  p.tread_temp = ReadCelsius(w, "tread_temp_C");
  p.reference_friction = w.Number("reference_friction", Range::OpenClosed(0.0, 3.0, ""));
  w.Finish();
  return p;
}

FrictionLaw<double> ReadLaw(YamlReader& l) {
  FrictionLaw<double> law;
  law.static_friction = l.Number("static_friction", Range::OpenClosed(0.0, 3.0, ""));
  law.kinetic_friction = l.Number("kinetic_friction", Range::OpenClosed(0.0, 3.0, ""));
  law.decay = l.Number("decay_s_per_m", Range::NonNegative("s/m"));
  return law;
}

std::vector<std::string> SurfaceNames(const std::vector<Surface>& surfaces) {
  std::vector<std::string> names;
  for (const Surface& s : surfaces) names.push_back(s.name);
  return names;
}

}  // namespace

const Surface& AbsConfig::SurfaceNamed(std::string_view name) const {
  for (const Surface& s : surfaces) {
    if (s.name == name) return s;
  }
  throw InputError(fmt::format("{}: no surface '{}'; the file has {}", path.string(), name,
                               QuotedList(SurfaceNames(surfaces))));
}

int AbsConfig::DelayTicks() const {
  return static_cast<int>(std::lround(plant.hydraulics.delay / controller.period_s));
}

std::vector<YamlOverride> ParseAbsOverrides(const std::vector<std::string>& texts) {
  std::vector<YamlOverride> out;
  for (const std::string& t : texts) {
    out.push_back(ParseYamlOverride(t, "controller.reapply_fraction=0.85"));
  }
  return out;
}

nlohmann::json AbsOverridesJson(const std::vector<YamlOverride>& overrides) {
  nlohmann::json j = nlohmann::json::object();
  for (const YamlOverride& o : overrides) j[o.field] = o.value;
  return j;
}

AbsConfig LoadAbsConfig(const fs::path& path, const std::vector<YamlOverride>& overrides) {
  YamlReader y = overrides.empty() ? YamlReader::Load(path) : YamlReader::Load(path, overrides);
  AbsConfig c;
  c.path = path;
  c.overrides = overrides;
  c.name = y.String("name");
  y.Choice("model", {"abs_quarter_car"});
  {
    YamlReader e = y.Map("event");
    c.event = ReadEvent(e);
  }
  {
    YamlReader d = y.Map("driver");
    c.driver.pressure_rate_Pa_per_s =
        kMPa * d.Number("pressure_rate_MPa_per_s", Range::Positive("MPa/s"));
    c.driver.pressure_Pa = kMPa * d.Number("pressure_MPa", Range::Positive("MPa"));
    d.Finish();
  }
  fs::path tyre_file;
  {
    YamlReader w = y.Map("wheel");
    c.plant.wheel = ReadWheel(w, tyre_file);
  }
  c.plant.tyre = tyre::LoadTyreForceModel(tyre_file);
  c.brake = brake::LoadBrakeFile(y.FilePath("brake_file"));
  {
    YamlReader h = y.Map("hydraulics");
    c.plant.hydraulics = brake::ReadBrakeHydraulicsParams(h);
  }
  {
    YamlReader k = y.Map("controller");
    c.controller = brake::ReadAbsControllerParams(k);
    c.controller.wheel_radius_m = c.plant.wheel.radius;  // the wheel's R_l, read once
  }
  if (y.Has("wheel_speed_filter")) {
    YamlReader f = y.Map("wheel_speed_filter");
    c.wheel_speed_filter = brake::ReadWheelSpeedFilterParams(f, c.controller.period_s);
  }
  // The delay is applied per controller tick, so it must be a whole number of periods.
  const double ticks = c.plant.hydraulics.delay / c.controller.period_s;
  if (std::abs(ticks - std::round(ticks)) > 1e-6) {
    y.Fail("hydraulics.delay_s",
           fmt::format("{:g} s is not a whole number of controller periods ({:g} s)",
                       c.plant.hydraulics.delay, c.controller.period_s));
  }

  // Friction laws, each also a uniform surface; then the surfaces made of segments.
  const auto taken = [&](const std::string& name) {
    for (const Surface& s : c.surfaces) {
      if (s.name == name) return true;
    }
    return false;
  };
  std::vector<YamlReader> laws = y.MapList("friction_laws", 1);
  for (size_t i = 0; i < laws.size(); ++i) {
    YamlReader& l = laws[i];
    NamedFrictionLaw named{l.String("name"), ReadLaw(l)};
    if (taken(named.name)) l.Fail("name", fmt::format("'{}' is used twice", named.name));
    l.Finish();
    c.surfaces.push_back({named.name, {{0.0, named.name, named.law}}});
    c.friction_laws.push_back(std::move(named));
  }
  if (y.Has("surfaces")) {
    for (YamlReader& s : y.MapList("surfaces", 1)) {
      Surface surface;
      surface.name = s.String("name");
      if (taken(surface.name)) s.Fail("name", fmt::format("'{}' is used twice", surface.name));
      for (YamlReader& seg : s.MapList("segments", 1)) {
        const double from = seg.Number("from_m", Range::NonNegative("m"));
        const std::string law_name = seg.String("law");
        const auto it = std::find_if(c.friction_laws.begin(), c.friction_laws.end(),
                                     [&](const NamedFrictionLaw& l) { return l.name == law_name; });
        if (it == c.friction_laws.end()) {
          std::vector<std::string> names;
          for (const NamedFrictionLaw& l : c.friction_laws) names.push_back(l.name);
          seg.Fail("law",
                   fmt::format("no friction law '{}'; there are {}", law_name, QuotedList(names)));
        }
        const double previous = surface.segments.empty() ? -1.0 : surface.segments.back().start_m;
        if (surface.segments.empty() ? from != 0.0 : !(from > previous)) {
          seg.Fail("from_m", surface.segments.empty()
                                 ? fmt::format("{:g}: the first segment must start at 0 m", from)
                                 : fmt::format("{:g} must be beyond the previous segment's {:g} m",
                                               from, previous));
        }
        surface.segments.push_back({from, law_name, it->law});
        seg.Finish();
      }
      s.Finish();
      c.surfaces.push_back(std::move(surface));
    }
  }
  {
    YamlReader s = y.Map("scenarios");
    c.scenarios.max_duration_s = s.Number("max_duration_s", Range::OpenClosed(0.0, 600.0, "s"));
    const double count = s.Number("stop_series_count", Range::Closed(1.0, 100.0, ""));
    if (count != std::floor(count)) {
      s.Fail("stop_series_count", fmt::format("{:g} is not a whole number", count));
    }
    c.scenarios.stop_series_count = static_cast<int>(count);
    c.scenarios.stop_series_interval_s =
        s.Number("stop_series_interval_s", Range::NonNegative("s"));
    c.scenarios.stop_series_surface = s.String("stop_series_surface");
    s.Finish();
  }
  y.Finish();

  // Names that refer to surfaces must exist.
  if (!taken(c.event.surface)) {
    throw InputError(fmt::format("{}: field 'event.surface': no surface '{}'; the file has {}",
                                 path.string(), c.event.surface,
                                 QuotedList(SurfaceNames(c.surfaces))));
  }
  if (!taken(c.scenarios.stop_series_surface)) {
    throw InputError(fmt::format(
        "{}: field 'scenarios.stop_series_surface': no surface '{}'; the file has {}",
        path.string(), c.scenarios.stop_series_surface, QuotedList(SurfaceNames(c.surfaces))));
  }
  return c;
}

fs::path DefaultAbsConfigPath() { return DataDir() / "abs" / "paper.yaml"; }

}  // namespace hotlap::sim
