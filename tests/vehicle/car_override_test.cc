// Car parameters overridden by their dotted keys: each override changes exactly its value (in SI
// after the file's own conversion) and nothing else, corners sharing a file keep their own values,
// the duct factor scales the convective conductance, and every refusal names the override.

#include "hotlap/vehicle/car_override.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/brake/brake_thermal_fields.h"
#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/common/yaml_reader.h"
#include "hotlap/tyre/tyre_thermal_fields.h"
#include "hotlap/vehicle/car.h"
#include "test_util.h"

namespace hotlap::vehicle {
namespace {

namespace fs = std::filesystem;
using test::Contains;
using test::InputErrorOf;

fs::path Gen7() { return test::Gen7Dir() / "car.yaml"; }

// Every number of a loaded car, SI, by a name that follows the override keys: the tyre and brake
// thermal parameters of each corner (their field tables' paths), the starting temperatures and
// the vehicle parameters.
std::map<std::string, double> Numbers(const Car& car) {
  std::map<std::string, double> n;
  for (Corner c : kAllCorners) {
    const std::string corner(CornerName(c));
    for (const tyre::TyreThermalField& f : tyre::TyreThermalFields()) {
      n["tyres." + corner + "." + f.Path()] = f.Of(car.tyre(c).params);
    }
    for (const brake::BrakeThermalField& f : brake::BrakeThermalFields()) {
      n["brakes." + corner + "." + f.Path()] = f.Of(car.brake(c).params);
    }
    const brake::BrakeGeometry& g = car.brake(c).geometry;
    n["brakes." + corner + ".geometry.disc_diameter"] = g.disc_diameter;
    n["brakes." + corner + ".geometry.mounting_hole_diameter"] = g.mounting_hole_diameter;
    n["brakes." + corner + ".geometry.disc_thickness"] = g.disc_thickness;
    const CornerSetup& s = car.vehicle->corner(c);
    n["tyre_forces." + corner + ".pressure"] = s.pressure;
    n["tyre_forces." + corner + ".camber"] = s.camber;
    n["tyre_forces." + corner + ".rolling_radius"] = s.rolling_radius;
  }
  n["initial_state.tread_temp"] = car.initial.tread_temp;
  n["initial_state.carcass_temp"] = car.initial.carcass_temp;
  n["initial_state.disc_temp"] = car.initial.disc_temp;
  n["initial_state.calliper_temp"] = car.initial.calliper_temp;
  const VehicleParams& v = *car.vehicle;
  n["chassis.mass"] = v.chassis.mass;
  n["chassis.yaw_inertia"] = v.chassis.yaw_inertia;
  n["chassis.wheelbase"] = v.chassis.wheelbase;
  n["chassis.front_weight_fraction"] = v.chassis.front_weight_fraction;
  n["chassis.left_weight_fraction"] = v.chassis.left_weight_fraction;
  n["chassis.cog_height"] = v.chassis.cog_height;
  n["chassis.track_front"] = v.chassis.track_front;
  n["chassis.track_rear"] = v.chassis.track_rear;
  n["chassis.roll_stiffness_front_share"] = v.chassis.roll_stiffness_front_share;
  n["aero.air_density"] = v.aero.air_density;
  n["aero.drag_area"] = v.aero.drag_area;
  n["aero.downforce_area"] = v.aero.downforce_area;
  n["aero.front_downforce_share"] = v.aero.front_downforce_share;
  n["powertrain.engine_power"] = v.powertrain.engine_power;
  n["powertrain.driveline_efficiency"] = v.powertrain.driveline_efficiency;
  n["brake_system.front_share"] = v.brakes.front_share;
  return n;
}

// The names whose values differ between two cars' Numbers.
std::set<std::string> Differences(const std::map<std::string, double>& a,
                                  const std::map<std::string, double>& b) {
  std::set<std::string> out;
  for (const auto& [name, value] : a) {
    if (b.at(name) != value) out.insert(name);
  }
  return out;
}

std::string LoadError(const std::vector<CarOverride>& overrides) {
  return InputErrorOf([&] { LoadCar(Gen7(), overrides); });
}

struct Case {
  std::string key;
  double value;      // in the key's unit
  std::string name;  // in Numbers
  double si;         // expected there
};

// One override at a time, in each kind of place: the car's sections, a corner's set-up, a corner's
// brake and tyre files (with their unit conversions), the starting temperatures.
TEST(CarOverride, ChangesExactlyThatValue) {
  const std::map<std::string, double> plain = Numbers(LoadCar(Gen7()));
  const std::vector<Case> cases = {
      {"chassis.mass_kg", 1600, "chassis.mass", 1600},
      {"aero.drag_area_m2", 0.9, "aero.drag_area", 0.9},
      {"brake_system.front_share", 0.55, "brake_system.front_share", 0.55},
      {"tyre_forces.rr.pressure_kPa", 280, "tyre_forces.rr.pressure", 280e3},
      {"tyre_forces.fl.camber_deg", -2, "tyre_forces.fl.camber", DegToRad(-2.0)},
      // Not in the car file (its .tir gives the radius): an optional number, added (stagger).
      {"tyre_forces.rr.rolling_radius_m", 0.3677, "tyre_forces.rr.rolling_radius", 0.3677},
      {"initial_state.disc_temp_C", 300, "initial_state.disc_temp", CelsiusToKelvin(300.0)},
      {"brakes.fl.heat_partition", 0.9, "brakes.fl.heat_partition", 0.9},
      {"brakes.fr.disc_convection_cholesky_sqrtW_per_K.l33", 5,
       "brakes.fr.disc_convection_cholesky_sqrtW_per_K.l33", 5},
      {"brakes.rl.pad_area_mm2", 6000, "brakes.rl.pad_area_mm2", 6000e-6},
      {"tyres.rr.heat_generation.p1", 0.3, "tyres.rr.heat_generation.p1", 0.3},
      {"tyres.fl.construction.reference_slip_angle_deg", 6,
       "tyres.fl.construction.reference_slip_angle_deg", DegToRad(6.0)},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.key);
    const Car car = LoadCar(Gen7(), {{c.key, c.value}});
    const std::map<std::string, double> n = Numbers(car);
    ASSERT_NE(plain.at(c.name), c.si) << "the case must change the value";
    EXPECT_EQ(Differences(plain, n), std::set<std::string>{c.name});
    EXPECT_NEAR(n.at(c.name), c.si, 1e-12 * std::abs(c.si));
    ASSERT_EQ(car.overrides.size(), 1u);
    EXPECT_EQ(car.overrides[0].key, c.key);
    EXPECT_EQ(car.overrides[0].value, c.value);
  }
}

// gen7's rear corners share brakes/rear.yaml and tyres/right.tir; each corner is read for itself.
TEST(CarOverride, CornersSharingAFileGetTheirOwnValues) {
  const Car plain = LoadCar(Gen7());
  ASSERT_EQ(plain.brake(Corner::kRearLeft).path, plain.brake(Corner::kRearRight).path);
  const Car car = LoadCar(Gen7(), {{"brakes.rl.heat_partition", 0.5},
                                   {"brakes.rl.disc_convection_cholesky_sqrtW_per_K.l11", 3}});
  EXPECT_EQ(car.brake(Corner::kRearLeft).params.heat_partition, 0.5);
  EXPECT_EQ(car.brake(Corner::kRearLeft).params.disc_convection.l11, 3.0);
  EXPECT_EQ(Differences(Numbers(plain), Numbers(car)),
            (std::set<std::string>{"brakes.rl.heat_partition",
                                   "brakes.rl.disc_convection_cholesky_sqrtW_per_K.l11"}));
  EXPECT_EQ(car.brake(Corner::kRearRight).params.heat_partition, 0.95);  // the file's
}

// Loading a car parses each of its YAML files once, however many corners name one and though
// the override plan, its optional-number probe and the readers each read them all: every file
// the load reads is in the cache's list once (it holds each path once, by construction), and the
// list is the same with overrides that need the probe as without any.
TEST(CarOverride, LoadingTheCarParsesEachFileOnce) {
  std::vector<fs::path> plain, overridden;
  {
    const YamlParseCache cache;
    (void)LoadCar(Gen7());
    plain = cache.parsed();
  }
  {
    const YamlParseCache cache;
    const Car car = LoadCar(Gen7(), {{"chassis.mass_kg", 1600},
                                     {"brakes.rl.heat_partition", 0.5},
                                     {"tyre_forces.rl.rolling_radius_m", 0.36}});
    EXPECT_EQ(car.brake(Corner::kRearLeft).params.heat_partition, 0.5);
    EXPECT_EQ(car.brake(Corner::kRearRight).params.heat_partition, 0.95);
    overridden = cache.parsed();
  }
  // The same files (in another order: the plan lists the corners' files before the readers read
  // the compound), the car file first.
  const std::set<fs::path> distinct(plain.begin(), plain.end());
  EXPECT_EQ(distinct, std::set<fs::path>(overridden.begin(), overridden.end()));
  EXPECT_EQ(plain.front(), Gen7().lexically_normal());
  EXPECT_EQ(distinct.size(), plain.size());
  EXPECT_GE(plain.size(), 8u);
}

// hA = z' L L' z: a factor of 0.5 halves it at every speed and temperature, for the disc and the
// calliper of that corner alone; nothing else moves.
TEST(CarOverride, DuctFactorScalesTheConvectiveConductance) {
  const Car plain = LoadCar(Gen7());
  const Car car = LoadCar(Gen7(), {{"brakes.fl.duct_factor", 0.5}});
  const brake::BrakeThermalParams<double>& p = plain.brake(Corner::kFrontLeft).params;
  const brake::BrakeThermalParams<double>& q = car.brake(Corner::kFrontLeft).params;
  for (const double u : {0.0, 40.0, 80.0}) {
    for (const double t : {CelsiusToKelvin(100.0), CelsiusToKelvin(600.0)}) {
      SCOPED_TRACE(testing::Message() << u << " m/s, " << t << " K");
      const double disc = p.disc_convection.Conductance(u, t);
      const double calliper = p.calliper_convection.Conductance(u, t);
      ASSERT_GT(disc, 0.0);
      EXPECT_NEAR(q.disc_convection.Conductance(u, t), 0.5 * disc, 1e-12 * disc);
      EXPECT_NEAR(q.calliper_convection.Conductance(u, t), 0.5 * calliper, 1e-12 * calliper);
    }
  }
  // The duct's air also cools a bulk disc's vanes: their conductance scales with it.
  EXPECT_NEAR(q.bulk_convection, 0.5 * p.bulk_convection, 1e-12);
  std::set<std::string> expected = {"brakes.fl.disc_bulk.vane_convection_W_per_K"};
  for (const brake::BrakeThermalField& f : brake::BrakeThermalFields()) {
    if (f.polynomial && f.Of(p) != 0.0) expected.insert("brakes.fl." + f.Path());
  }
  EXPECT_EQ(expected.size(), 13u);
  EXPECT_EQ(Differences(Numbers(plain), Numbers(car)), expected);
  EXPECT_EQ(car.vehicle->chassis.mass, plain.vehicle->chassis.mass);
}

// The factor applies to the entries as read, explicit overrides included.
TEST(CarOverride, DuctFactorScalesAnOverriddenEntryToo) {
  const Car car = LoadCar(Gen7(), {{"brakes.fr.duct_factor", 4.0},
                                   {"brakes.fr.disc_convection_cholesky_sqrtW_per_K.l11", 3}});
  EXPECT_EQ(car.brake(Corner::kFrontRight).params.disc_convection.l11, 6.0);
}

// Each key of OverrideKeys set to the value its file holds (the duct factors to 1) loads the very
// same car: every listed key is accepted and reaches the value the file gives it.
TEST(CarOverride, EveryListedKeyReachesItsValue) {
  const Car plain = LoadCar(Gen7());
  std::map<std::string, double> file_values;
  const auto add = [&](const fs::path& file, const std::string& prefix) {
    for (const YamlScalarField& f : ListYamlScalars(file)) {
      if (f.number) file_values[prefix + f.field] = *ParseYamlNumber(f.text);
    }
  };
  add(Gen7(), "");
  for (Corner c : kAllCorners) {
    add(plain.tyre(c).path, "tyres." + std::string(CornerName(c)) + ".");
    add(plain.brake(c).path, "brakes." + std::string(CornerName(c)) + ".");
  }
  // The optional numbers the files leave out: the rolling radii the .tir files give.
  for (Corner c : kAllCorners) {
    file_values["tyre_forces." + std::string(CornerName(c)) + ".rolling_radius_m"] =
        plain.vehicle->corner(c).rolling_radius;
  }
  const std::vector<std::string> keys = OverrideKeys(Gen7());
  std::vector<CarOverride> all;
  for (const std::string& key : keys) {
    const bool duct = key.ends_with(".duct_factor");
    ASSERT_TRUE(duct || file_values.contains(key)) << key;
    all.push_back({key, duct ? 1.0 : file_values.at(key)});
  }
  // Every number of every file, the 4 optional radii and the 4 factors.
  EXPECT_EQ(all.size(), file_values.size() + 4);
  const Car car = LoadCar(Gen7(), all);
  EXPECT_EQ(Differences(Numbers(plain), Numbers(car)), std::set<std::string>{});
  EXPECT_EQ(car.overrides.size(), all.size());
}

TEST(CarOverride, KeysAreTheNumbersInFileOrder) {
  const std::vector<std::string> keys = OverrideKeys(Gen7());
  const auto has = [&](const std::string& k) {
    return std::find(keys.begin(), keys.end(), k) != keys.end();
  };
  for (const char* k :
       {"chassis.mass_kg", "aero.drag_area_m2", "brake_system.front_share",
        "tyre_forces.rr.pressure_kPa", "tyre_forces.fl.camber_deg", "initial_state.disc_temp_C",
        "brakes.fl.heat_partition", "brakes.fl.disc_convection_cholesky_sqrtW_per_K.l33",
        "brakes.rr.geometry.disc_diameter_mm", "brakes.rl.duct_factor",
        "tyres.rr.construction.tread_mass_kg", "tyres.fl.wear.wp2",
        "tyre_forces.rl.rolling_radius_m"}) {
    EXPECT_TRUE(has(k)) << k;
  }
  for (const char* k : {"name", "model", "brakes.fl", "tyres.rr", "tyre_forces.fl.file",
                        "powertrain.drive", "tyres.fl.compound", "brakes.fl.name"}) {
    EXPECT_FALSE(has(k)) << k;
  }
  EXPECT_EQ(keys.front(), "tyres.fl.heat_generation.p1");  // the car file names the tyres first
}

TEST(CarOverride, OutOfRangeGivesTheFilesMessageNamingTheOverride) {
  std::string m = LoadError({{"chassis.mass_kg", 50}});
  EXPECT_TRUE(Contains(m, "override 'chassis.mass_kg=50': "));
  EXPECT_TRUE(Contains(m,
                       "car.yaml: field 'chassis.mass_kg': value 50 is out of range: must be "
                       "in [100, 5000] kg"));
  m = LoadError({{"chassis.mass_kg", 1600}, {"tyres.rr.construction.tread_mass_kg", -0.9}});
  EXPECT_TRUE(Contains(m, "override 'tyres.rr.construction.tread_mass_kg=-0.9': "));
  EXPECT_TRUE(Contains(m,
                       "tyres/rr.yaml: field 'construction.tread_mass_kg': value -0.9 is out "
                       "of range: must be > 0 kg"));
  m = LoadError({{"brakes.rr.heat_partition", 1.5}});
  EXPECT_TRUE(Contains(m, "override 'brakes.rr.heat_partition=1.5': "));
  EXPECT_TRUE(Contains(m, "brakes/rear.yaml: field 'heat_partition': value 1.5 is out of range"));
  m = LoadError({{"brakes.fl.duct_factor", 0}});
  EXPECT_TRUE(Contains(m,
                       "override 'brakes.fl.duct_factor=0': value 0 is out of range: must be "
                       "> 0"));
  // A check across fields of the file: the message says which overrides were in place.
  m = LoadError({{"tyres.fr.construction.unloaded_radius_m", 0.2}});
  EXPECT_TRUE(Contains(m, "with override 'tyres.fr.construction.unloaded_radius_m=0.2': "));
  EXPECT_TRUE(Contains(m, "must be smaller than unloaded_radius_m"));
}

TEST(CarOverride, UnknownKeySaysWhichPartAndSuggests) {
  std::string m = LoadError({{"chassis.mass", 1600}});
  EXPECT_TRUE(Contains(m, "override 'chassis.mass=1600': unknown key: 'chassis'"));
  EXPECT_TRUE(Contains(m, "has no field 'mass' (did you mean 'chassis.mass_kg'?)"));
  m = LoadError({{"brakes.fl.duct_factr", 0.5}});
  EXPECT_TRUE(Contains(m, "'brakes.fl'"));
  EXPECT_TRUE(Contains(m, "front_left.yaml) has no field 'duct_factr'"));
  EXPECT_TRUE(Contains(m, "(did you mean 'brakes.fl.duct_factor'?)"));
  m = LoadError({{"chasis.mass_kg", 1600}});
  EXPECT_TRUE(Contains(m, "has no section or field 'chasis' (did you mean 'chassis.mass_kg'?)"));
  m = LoadError({{"tyres.rr.heat_generation.p6_J_per_kgN", 1}});
  EXPECT_TRUE(Contains(m, "'tyres.rr.heat_generation'"));
  EXPECT_TRUE(Contains(m, "has no field 'p6_J_per_kgN'"));
  EXPECT_TRUE(Contains(m, "'tyres.rr.heat_generation.p2_J_per_kgN'"));
  m = LoadError({{"chassis.mass_kg.x", 1}});
  EXPECT_TRUE(Contains(m, "'chassis.mass_kg'"));
  EXPECT_TRUE(Contains(m, "is a value, not a section"));
  m = LoadError({{"chassis", 1}});
  EXPECT_TRUE(Contains(m, "'chassis' is a section, not a number"));
  EXPECT_TRUE(Contains(m, "'chassis.mass_kg'"));
  // An optional number the file leaves out is a key like the others: suggested for a typo, and
  // its value goes through the reader's range.
  m = LoadError({{"tyre_forces.rr.rolling_radius_mm", 0.37}});
  EXPECT_TRUE(Contains(m, "has no field 'rolling_radius_mm'"));
  EXPECT_TRUE(Contains(m, "(did you mean 'tyre_forces.rr.rolling_radius_m'?)"));
  m = LoadError({{"tyre_forces.rr.rolling_radius_m", 2}});
  EXPECT_TRUE(Contains(m, "override 'tyre_forces.rr.rolling_radius_m=2': "));
  EXPECT_TRUE(Contains(m, "field 'tyre_forces.rr.rolling_radius_m': value 2 is out of range"));
}

// The optional numbers are found by reading the car with the overrides of the keys its files
// hold, so a car that reads only with those (here a mass out of range, mended by its override)
// still takes an optional number; a car that does not read at all says why.
TEST(CarOverride, OptionalNumberOfACarThatReadsOnlyWithItsOverrides) {
  const test::TempDir dir;
  fs::copy(test::Gen7Dir(), dir.path() / "gen7", fs::copy_options::recursive);
  const fs::path car = dir.path() / "gen7" / "car.yaml";
  std::string text = test::ReadTextFile(car);
  const size_t at = text.find("mass_kg:");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, text.find('\n', at) - at, "mass_kg: 50");
  // The right rear's rolling radius left out, so that it is an optional number.
  const size_t rr = text.find(", rolling_radius_m:", text.find("  rr: {"));
  ASSERT_NE(rr, std::string::npos);
  text.erase(rr, text.find('}', rr) - rr);
  test::WriteTextFile(car, text);
  const Car mended =
      LoadCar(car, {{"chassis.mass_kg", 1500}, {"tyre_forces.rr.rolling_radius_m", 0.3677}});
  EXPECT_EQ(mended.vehicle->corner(Corner::kRearRight).rolling_radius, 0.3677);
  EXPECT_EQ(mended.vehicle->chassis.mass, 1500.0);
  const std::string m = InputErrorOf([&] {
    LoadCar(car, {{"tyre_forces.rr.rolling_radius_m", 0.3677}});
  });
  EXPECT_TRUE(Contains(m, "override 'tyre_forces.rr.rolling_radius_m=0.3677': "));
  EXPECT_TRUE(Contains(m, "does not read"));
  EXPECT_TRUE(Contains(m, "value 50 is out of range"));
}

TEST(CarOverride, OtherRefusalsNameTheOverride) {
  std::string m = LoadError({{"tyre_forces.fl.file", 1}});
  EXPECT_TRUE(Contains(m,
                       "override 'tyre_forces.fl.file=1': 'tyre_forces.fl.file' is text "
                       "('tyres/left.tir'"));
  EXPECT_TRUE(Contains(m, "not a number"));
  m = LoadError({{"brakes.fl", 1}});
  EXPECT_TRUE(Contains(m, "'brakes.fl' is text ('brakes/front_left.yaml'"));
  m = LoadError({{"chassis.mass_kg", 1600}, {"aero.drag_area_m2", 1}, {"chassis.mass_kg", 1700}});
  EXPECT_TRUE(Contains(m,
                       "override 'chassis.mass_kg=1700': the key 'chassis.mass_kg' is given "
                       "twice (first as chassis.mass_kg=1600)"));
  m = LoadError({{"brakes.fx.heat_partition", 0.5}});
  EXPECT_TRUE(Contains(m,
                       "override 'brakes.fx.heat_partition=0.5': 'fx' is not a corner: must "
                       "be 'fl', 'fr', 'rl' or 'rr'"));
  m = LoadError({{"tyre_forces.front.pressure_kPa", 200}});
  EXPECT_TRUE(Contains(m, "'front' is not a corner"));
  m = LoadError({{"chassis..mass_kg", 1600}});
  EXPECT_TRUE(Contains(m, "is not a dotted key"));
}

TEST(CarOverride, ParsesKeyEqualsValue) {
  CarOverride o = ParseCarOverride("brakes.fl.duct_factor=0.8");
  EXPECT_EQ(o.key, "brakes.fl.duct_factor");
  EXPECT_EQ(o.value, 0.8);
  EXPECT_EQ(ParseCarOverride("chassis.mass_kg=+1.6e3").value, 1600.0);
  EXPECT_EQ(OverrideText(ParseCarOverride("tyre_forces.fl.camber_deg=-2.5")),
            "tyre_forces.fl.camber_deg=-2.5");
  EXPECT_TRUE(Contains(InputErrorOf([] { ParseCarOverride("chassis.mass_kg"); }),
                       "override 'chassis.mass_kg': expected KEY=VALUE"));
  EXPECT_TRUE(Contains(InputErrorOf([] { ParseCarOverride("=3"); }), "expected KEY=VALUE"));
  for (const char* bad : {"a=", "a=1600kg", "a=nan", "a=inf", "a=1,5", "a= 1"}) {
    EXPECT_TRUE(Contains(InputErrorOf([&] { ParseCarOverride(bad); }), "is not a finite number"))
        << bad;
  }
  const std::vector<CarOverride> all = ParseCarOverrides({"a.b=1", "c.d=2"});
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(all[1].key, "c.d");
  EXPECT_EQ(OverridesJson(all), nlohmann::json({{"a.b", 1.0}, {"c.d", 2.0}}));
  EXPECT_EQ(OverridesJson({}), nlohmann::json::object());
  EXPECT_EQ(OverridesText(all), "a.b=1, c.d=2");
}

}  // namespace
}  // namespace hotlap::vehicle
