#include "hotlap/tyre/tyre_force_params_io.h"

#include <functional>

#include <cmath>
#include <sstream>
#include <vector>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "hotlap/common/atomic_file.h"
#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/common/yaml_reader.h"

namespace hotlap::tyre {

namespace {

const Range kTempC = Range::Closed(-100.0, 300.0, "degC");
const Range kDecay = Range::Closed(-1.0, 1.0, "1/K");

// A temperature factor f(T) = a exp(-b (T - T_ref)) read from the mapping `key`, with `a` under
// `scale_key` (its unit in the key) within `scale_range`.
TemperatureFactor<double> ReadTemperatureFactor(YamlReader& parent, std::string_view key,
                                                std::string_view scale_key,
                                                const Range& scale_range) {
  YamlReader y = parent.Map(key);
  TemperatureFactor<double> f;
  f.scale = y.Number(scale_key, scale_range);
  f.decay = y.Number("decay_per_K", kDecay);
  f.reference_temp = CelsiusToKelvin(y.Number("reference_temp_C", kTempC));
  y.Finish();
  return f;
}

// One plain number of a UniTire file: its key (unit included), field and allowed range. The
// reader and the writer share this table, so the two cannot drift apart.
struct UniTireKey {
  const char* key;
  double UniTireParams<double>::*field;
  Range range;
  const char* name;  // the field's name in kUniTireFieldNames
};

const std::vector<UniTireKey>& UniTireKeys() {
  using P = UniTireParams<double>;
  static const std::vector<UniTireKey> keys = {
      {"nominal_load_N", &P::nominal_load, Range::Positive("N"), "nominal_load"},
      {"cornering_stiffness_per_load_1_per_rad", &P::cornering_stiffness_per_load,
       Range::Positive("1/rad"), "cornering_stiffness_per_load"},
      {"cornering_stiffness_load_quad", &P::cornering_stiffness_load_quad,
       Range::Closed(-10.0, 10.0, ""), "cornering_stiffness_load_quad"},
      {"cornering_stiffness_load_lin", &P::cornering_stiffness_load_lin,
       Range::Closed(-10.0, 10.0, ""), "cornering_stiffness_load_lin"},
      {"cornering_stiffness_camber", &P::cornering_stiffness_camber, Range::Closed(0.0, 100.0, ""), "cornering_stiffness_camber"},
      {"slip_stiffness_per_load", &P::slip_stiffness_per_load, Range::Positive(""), "slip_stiffness_per_load"},
      {"slip_stiffness_load_quad", &P::slip_stiffness_load_quad, Range::Closed(-10.0, 10.0, ""), "slip_stiffness_load_quad"},
      {"slip_stiffness_load_lin", &P::slip_stiffness_load_lin, Range::Closed(-10.0, 10.0, ""), "slip_stiffness_load_lin"},
      {"friction_x", &P::friction_x, Range::OpenClosed(0.0, 5.0, ""), "friction_x"},
      {"friction_y", &P::friction_y, Range::OpenClosed(0.0, 5.0, ""), "friction_y"},
      {"friction_load_decay", &P::friction_load_decay, Range::Closed(-5.0, 5.0, ""), "friction_load_decay"},
      {"friction_sliding_ratio", &P::friction_sliding_ratio, Range::OpenClosed(0.0, 1.0, ""), "friction_sliding_ratio"},
      {"friction_peak_speed_m_per_s", &P::friction_peak_speed, Range::Positive("m/s"), "friction_peak_speed"},
      {"friction_speed_shape", &P::friction_speed_shape, Range::Closed(0.0, 100.0, ""), "friction_speed_shape"},
      {"curvature_x", &P::curvature_x, Range::Closed(-10.0, 10.0, ""), "curvature_x"},
      {"curvature_y", &P::curvature_y, Range::Closed(-10.0, 10.0, ""), "curvature_y"},
      {"trail_m", &P::trail, Range::Closed(0.0, 1.0, "m"), "trail"},
      {"trail_load_exponent", &P::trail_load_exponent, Range::Closed(0.0, 3.0, ""), "trail_load_exponent"},
      {"trail_offset_m", &P::trail_offset, Range::Closed(-1.0, 1.0, "m"), "trail_offset"},
      {"trail_decay_lin", &P::trail_decay_lin, Range::Closed(0.0, 100.0, ""), "trail_decay_lin"},
      {"trail_decay_quad", &P::trail_decay_quad, Range::Closed(0.0, 100.0, ""), "trail_decay_quad"},
  };
  return keys;
}

struct UniTireFactorKey {
  const char* key;
  TemperatureFactor<double> UniTireParams<double>::*field;
};

constexpr UniTireFactorKey kUniTireFactorKeys[] = {
    {"stiffness_temperature", &UniTireParams<double>::stiffness_temperature},
    {"trail_temperature", &UniTireParams<double>::trail_temperature},
    {"friction_temperature", &UniTireParams<double>::friction_temperature},
};

const Range kFactorScale = Range::Positive("");

// YAML text for `name`, quoted if it needs to be.
std::string YamlScalar(const std::string& text) {
  YAML::Emitter e;
  e << text;
  return e.c_str();
}

}  // namespace

BrushParamsFile LoadBrushParams(const std::filesystem::path& path) {
  YamlReader y = YamlReader::Load(path);
  BrushParamsFile out;
  out.name = y.String("name");
  y.Choice("model", {"brush"});
  BrushParams<double>& p = out.params;
  p.contact_half_length = y.Number("contact_half_length_m", Range::OpenClosed(0.0, 1.0, "m"));
  p.reference_load = y.Number("reference_load_N", Range::Positive("N"));
  p.contact_length_exponent = y.Number("contact_length_load_exponent", Range::Closed(0, 2, ""));
  {
    YamlReader r = y.Map("rubber");
    RubberParams<double>& g = p.rubber;
    g.modulus_amplitude = r.Number("modulus_amplitude_Pa", Range::NonNegative("Pa"));
    g.modulus_decay = r.Number("modulus_decay_per_K", kDecay);
    g.modulus_reference_temp = CelsiusToKelvin(r.Number("modulus_reference_temp_C", kTempC));
    g.modulus_limit = r.Number("modulus_limit_Pa", Range::NonNegative("Pa"));
    g.geometry_factor = r.Number("geometry_factor", Range::Positive(""));
    if (!(g.modulus_amplitude + g.modulus_limit > 0.0)) {
      r.Fail("modulus_limit_Pa",
             "modulus_amplitude_Pa and modulus_limit_Pa are both 0: the modulus must be positive");
    }
    r.Finish();
  }
  p.friction = y.Number("friction", Range::OpenClosed(0.0, 5.0, ""));
  p.carcass_lateral_stiffness = ReadTemperatureFactor(y, "carcass_lateral_stiffness",
                                                      "value_N_per_m", Range::Positive("N/m"));
  p.carcass_torsional_stiffness = ReadTemperatureFactor(
      y, "carcass_torsional_stiffness", "value_Nm_per_rad", Range::Positive("N m/rad"));
  y.Finish();
  return out;
}

UniTireParamsFile LoadUniTireParams(const std::filesystem::path& path) {
  YamlReader y = YamlReader::Load(path);
  UniTireParamsFile out;
  out.name = y.String("name");
  y.Choice("model", {"unitire"});
  for (const UniTireKey& k : UniTireKeys()) out.params.*k.field = y.Number(k.key, k.range);
  for (const UniTireFactorKey& k : kUniTireFactorKeys) {
    out.params.*k.field = ReadTemperatureFactor(y, k.key, "scale", kFactorScale);
  }
  y.Finish();
  return out;
}

void WriteUniTireParams(const std::filesystem::path& path, const UniTireParamsFile& file,
                        std::string_view header_comment, std::string_view value_source,
                        const std::function<std::string(std::string_view)>& source_of) {
  const auto source = [&](std::string_view name) {
    return source_of ? source_of(name) : std::string(value_source);
  };
  const UniTireParams<double>& p = file.params;
  auto check = [&](std::string_view key, double value, const Range& range) {
    if (!range.Contains(value)) {
      throw InputError(fmt::format("{}: field '{}': value {:g} is out of range: must be {}",
                                   path.string(), key, value, range.Describe()));
    }
  };
  if (file.name.empty()) {
    throw InputError(fmt::format("{}: field 'name': must not be empty", path.string()));
  }
  std::ostringstream text;
  std::istringstream header{std::string(header_comment)};
  for (std::string line; std::getline(header, line);) {
    text << (line.empty() ? "#" : "# " + line) << "\n";
  }
  text << "name: " << YamlScalar(file.name) << "\n";
  text << "model: unitire\n";
  for (const UniTireKey& k : UniTireKeys()) {
    check(k.key, p.*k.field, k.range);
    text << fmt::format("{}: {}  # {}\n", k.key, p.*k.field, source(k.name));
  }
  for (const UniTireFactorKey& k : kUniTireFactorKeys) {
    const TemperatureFactor<double>& f = p.*k.field;
    const double temp_c = KelvinToCelsius(f.reference_temp);
    check(fmt::format("{}.scale", k.key), f.scale, kFactorScale);
    check(fmt::format("{}.decay_per_K", k.key), f.decay, kDecay);
    check(fmt::format("{}.reference_temp_C", k.key), temp_c, kTempC);
    text << k.key << ":  # f(T) = scale exp(-decay (T - T_ref))\n";
    const std::string stem(k.key);
    text << fmt::format("  scale: {}  # {}\n", f.scale, source(stem + ".scale"));
    text << fmt::format("  decay_per_K: {}  # {}\n", f.decay, source(stem + ".decay"));
    text << fmt::format("  reference_temp_C: {}  # {}\n", temp_c,
                        source(stem + ".reference_temp"));
  }
  const std::string content = text.str();
  WriteFileAtomically(path, [&](std::ostream& out) { out << content; });
}

}  // namespace hotlap::tyre
