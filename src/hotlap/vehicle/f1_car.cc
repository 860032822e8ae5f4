#include "hotlap/vehicle/f1_car.h"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/common/yaml_reader.h"

namespace hotlap::vehicle {

namespace {

constexpr const char* kModel = "limebeer-2014-f1";

F1TyreParams ReadTyre(YamlReader y) {
  F1TyreParams t;
  t.radius_m = y.Number("radius_m", Range::OpenClosed(0.0, 2.0, "m"));
  t.load_1_N = y.Number("reference_load_1_N", Range::Positive("N"));
  t.load_2_N = y.Number("reference_load_2_N", Range::Positive("N"));
  if (!(t.load_2_N > t.load_1_N)) {
    y.Fail("reference_load_2_N", fmt::format("must be above reference_load_1_N ({:g} N), is {:g} N",
                                             t.load_1_N, t.load_2_N));
  }
  const Range mu = Range::OpenClosed(0.0, 5.0, "");
  t.mu_x_max_1 = y.Number("mu_x_max_1", mu);
  t.mu_x_max_2 = y.Number("mu_x_max_2", mu);
  const Range kappa = Range::OpenClosed(0.0, 1.0, "");
  t.kappa_max_1 = y.Number("kappa_max_1", kappa);
  t.kappa_max_2 = y.Number("kappa_max_2", kappa);
  t.mu_y_max_1 = y.Number("mu_y_max_1", mu);
  t.mu_y_max_2 = y.Number("mu_y_max_2", mu);
  const Range angle = Range::OpenClosed(0.0, 45.0, "deg");
  t.lambda_max_1_rad = DegToRad(y.Number("lambda_max_1_deg", angle));
  t.lambda_max_2_rad = DegToRad(y.Number("lambda_max_2_deg", angle));
  const Range shape = Range::OpenClosed(0.0, 10.0, "");
  t.qx = y.Number("qx", shape);
  t.qy = y.Number("qy", shape);
  t.mu_min = y.Number("mu_min", Range::NonNegative(""));
  y.Finish();
  return t;
}

}  // namespace

bool IsF1CarFile(const std::filesystem::path& car_yaml) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(car_yaml.string());
  } catch (const YAML::Exception& e) {
    throw InputError(fmt::format("{}: cannot read: {}", car_yaml.string(), e.what()));
  }
  return root.IsMap() && root["model"] && root["model"].IsScalar() &&
         root["model"].as<std::string>() == kModel;
}

F1CarParams LoadF1Car(const std::filesystem::path& car_yaml) {
  YamlReader y = YamlReader::Load(car_yaml);
  F1CarParams p;
  p.path = car_yaml;
  p.name = y.String("name");
  y.Choice("model", {kModel});
  {
    YamlReader c = y.Map("chassis");
    p.mass_kg = c.Number("mass_kg", Range::Positive("kg"));
    p.yaw_inertia_kgm2 = c.Number("yaw_inertia_kgm2", Range::Positive("kg m^2"));
    p.cog_height_m = c.Number("cog_height_m", Range::Closed(0.0, 2.0, "m"));
    p.front_axle_x_m = c.Number("front_axle_x_m", Range::OpenClosed(0.0, 5.0, "m"));
    p.rear_axle_x_m = -c.Number("rear_axle_behind_cog_m", Range::OpenClosed(0.0, 5.0, "m"));
    p.pressure_centre_x_m = c.Number("pressure_centre_x_m", Range::Closed(-5.0, 5.0, "m"));
    p.roll_balance = c.Number("roll_balance", Range{0.0, 1.0, false, false, ""});
    p.brake_bias_front = c.Number("brake_bias_front", Range::Closed(0.0, 1.0, ""));
    c.Finish();
  }
  {
    YamlReader a = y.Map("aero");
    p.air_density_kg_per_m3 = a.Number("air_density_kg_per_m3", Range::Positive("kg/m^3"));
    p.frontal_area_m2 = a.Number("frontal_area_m2", Range::Positive("m^2"));
    p.drag_coefficient = a.Number("drag_coefficient", Range::NonNegative(""));
    p.lift_coefficient = a.Number("lift_coefficient", Range::Any(""));
    a.Finish();
  }
  {
    YamlReader f = y.Map("front_axle");
    p.track_front_m = f.Number("track_m", Range::OpenClosed(0.0, 5.0, "m"));
    p.brake_torque_front_Nm = f.Number("brake_max_torque_Nm", Range::Positive("N m"));
    f.Finish();
  }
  {
    YamlReader r = y.Map("rear_axle");
    p.track_rear_m = r.Number("track_m", Range::OpenClosed(0.0, 5.0, "m"));
    p.brake_torque_rear_Nm = r.Number("brake_max_torque_Nm", Range::Positive("N m"));
    p.engine_power_W = r.Number("engine_power_W", Range::Positive("W"));
    p.differential_stiffness_Nms =
        r.Number("differential_stiffness_Nms_per_rad", Range::NonNegative("N m s/rad"));
    p.throttle_smoothing = r.Number("throttle_smoothing", Range::Positive(""));
    r.Finish();
  }
  {
    YamlReader t = y.Map("tyres");
    p.front_tyre = ReadTyre(t.Map("front"));
    p.rear_tyre = ReadTyre(t.Map("rear"));
    t.Finish();
  }
  y.Finish();
  return p;
}

}  // namespace hotlap::vehicle
