// The limebeer-2014-f1 car: its YAML against fastest-lap's XML, validation errors, and the model
// equations against values worked out by hand from the equations in docs/f1-peer.md.

#include "hotlap/vehicle/f1_car.h"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/common/xml_file.h"
#include "test_util.h"

namespace hotlap::vehicle {
namespace {

using test::Contains;
using test::SourcePath;

std::filesystem::path CarFile() { return SourcePath("data/cars/f1-2014/car.yaml"); }

// A value of the copied fastest-lap XML, by element path.
double XmlValue(const pugi::xml_node& root, const std::string& path) {
  const pugi::xml_node e = root.first_element_by_path(path.c_str());
  if (!e) throw std::runtime_error("no element " + path);
  return std::stod(e.child_value());
}

TEST(F1Car, ShippedYamlMatchesFastestLapXml) {
  const F1CarParams p = LoadF1Car(CarFile());
  const auto xml_path = SourcePath("data/cars/f1-2014/limebeer-2014-f1.xml");
  const XmlFile xml = XmlFile::Load(xml_path);
  const pugi::xml_node root = xml.root();
  EXPECT_EQ(p.name, "f1-2014");
  EXPECT_EQ(p.mass_kg, XmlValue(root, "chassis/mass"));
  EXPECT_EQ(p.yaw_inertia_kgm2, XmlValue(root, "chassis/inertia/Izz"));
  EXPECT_EQ(p.cog_height_m, -XmlValue(root, "chassis/com/z"));
  EXPECT_EQ(p.front_axle_x_m, XmlValue(root, "chassis/front_axle/x"));
  EXPECT_EQ(p.rear_axle_x_m, XmlValue(root, "chassis/rear_axle/x"));
  EXPECT_EQ(p.pressure_centre_x_m, XmlValue(root, "chassis/pressure_center/x"));
  EXPECT_EQ(p.roll_balance, XmlValue(root, "chassis/roll_balance_coefficient"));
  EXPECT_EQ(p.brake_bias_front, XmlValue(root, "chassis/brake_bias"));
  EXPECT_EQ(p.air_density_kg_per_m3, XmlValue(root, "chassis/aerodynamics/rho"));
  EXPECT_EQ(p.frontal_area_m2, XmlValue(root, "chassis/aerodynamics/area"));
  EXPECT_EQ(p.drag_coefficient, XmlValue(root, "chassis/aerodynamics/cd"));
  EXPECT_EQ(p.lift_coefficient, XmlValue(root, "chassis/aerodynamics/cl"));
  EXPECT_EQ(p.track_front_m, XmlValue(root, "front-axle/track"));
  EXPECT_EQ(p.track_rear_m, XmlValue(root, "rear-axle/track"));
  EXPECT_EQ(p.brake_torque_front_Nm, XmlValue(root, "front-axle/brakes/max_torque"));
  EXPECT_EQ(p.brake_torque_rear_Nm, XmlValue(root, "rear-axle/brakes/max_torque"));
  EXPECT_NEAR(p.engine_power_W, 1e3 * XmlValue(root, "rear-axle/engine/maximum-power"), 1e-6);
  EXPECT_EQ(p.differential_stiffness_Nms, XmlValue(root, "rear-axle/differential_stiffness"));
  EXPECT_EQ(p.throttle_smoothing, XmlValue(root, "rear-axle/smooth_throttle_coeff"));
  for (const char* axle : {"front-tire", "rear-tire"}) {
    const F1TyreParams& t = std::string(axle) == "front-tire" ? p.front_tyre : p.rear_tyre;
    const std::string a = std::string(axle) + "/";
    EXPECT_EQ(t.radius_m, XmlValue(root, a + "radius"));
    EXPECT_EQ(t.load_1_N, XmlValue(root, a + "reference-load-1"));
    EXPECT_EQ(t.load_2_N, XmlValue(root, a + "reference-load-2"));
    EXPECT_EQ(t.mu_x_max_1, XmlValue(root, a + "mu-x-max-1"));
    EXPECT_EQ(t.mu_x_max_2, XmlValue(root, a + "mu-x-max-2"));
    EXPECT_EQ(t.kappa_max_1, XmlValue(root, a + "kappa-max-1"));
    EXPECT_EQ(t.kappa_max_2, XmlValue(root, a + "kappa-max-2"));
    EXPECT_EQ(t.mu_y_max_1, XmlValue(root, a + "mu-y-max-1"));
    EXPECT_EQ(t.mu_y_max_2, XmlValue(root, a + "mu-y-max-2"));
    EXPECT_NEAR(t.lambda_max_1_rad, DegToRad(XmlValue(root, a + "lambda-max-1")), 1e-15);
    EXPECT_NEAR(t.lambda_max_2_rad, DegToRad(XmlValue(root, a + "lambda-max-2")), 1e-15);
    EXPECT_EQ(t.qx, XmlValue(root, a + "Qx"));
    EXPECT_EQ(t.qy, XmlValue(root, a + "Qy"));
    EXPECT_EQ(t.mu_min, 1.0);
  }
}

TEST(F1Car, RecognisesItsModelMarker) {
  EXPECT_TRUE(IsF1CarFile(CarFile()));
  EXPECT_FALSE(IsF1CarFile(SourcePath("data/cars/gen7/car.yaml")));
}

TEST(F1Car, ValidationErrorsNameTheField) {
  const std::string text = test::ReadTextFile(CarFile());
  test::TempDir dir;
  {
    // A misspelt key: the missing field and the unknown key are both reported.
    const auto f = dir.Write("a.yaml", test::ReplaceOnce(text, "mass_kg:", "mass_lb:"));
    try {
      LoadF1Car(f);
      FAIL() << "no error";
    } catch (const InputError& e) {
      EXPECT_TRUE(Contains(e.what(), "chassis.mass_kg"));
    }
  }
  {
    // Reference loads in the wrong order.
    const auto f = dir.Write("b.yaml", test::ReplaceOnce(text, "reference_load_2_N: 6000.0",
                                                         "reference_load_2_N: 1000.0"));
    try {
      LoadF1Car(f);
      FAIL() << "no error";
    } catch (const InputError& e) {
      EXPECT_TRUE(Contains(e.what(), "reference_load_2_N"));
    }
  }
  {
    // A negative mass.
    const auto f =
        dir.Write("c.yaml", test::ReplaceOnce(text, "mass_kg: 660.0", "mass_kg: -660.0"));
    EXPECT_THROW(LoadF1Car(f), InputError);
  }
  {
    // Another model.
    const auto f =
        dir.Write("d.yaml", test::ReplaceOnce(text, "model: limebeer-2014-f1", "model: stock_car"));
    EXPECT_FALSE(IsF1CarFile(f));
    EXPECT_THROW(LoadF1Car(f), InputError);
  }
}

TEST(F1Car, TyreForceMidwayBetweenReferenceLoads) {
  const F1CarParams p = LoadF1Car(CarFile());
  // At 4000 N, halfway between 2 and 6 kN: kappa_max 0.105, lambda_max 8.5 deg, and the peak
  // frictions 1.575 and 1.625 through the smooth floor 1 + smooth_pos(mu - 1, 1e-5), which adds
  // 1e-5 / (4 (mu - 1)) (4.3e-6 and 3.2e-6). S = pi / (2 atan 1.9) = 1.445981519;
  // sin(1.9 atan S) = 0.965320682.
  const double sfac = std::sin(1.9 * std::atan(1.445981519));
  EXPECT_NEAR(sfac, 0.965320682, 1e-9);
  const double mu_x = 1.0 + 0.5 * (0.575 + std::sqrt(0.575 * 0.575 + 1e-5));
  const double mu_y = 1.0 + 0.5 * (0.625 + std::sqrt(0.625 * 0.625 + 1e-5));
  EXPECT_NEAR(mu_x, 1.575 + 1e-5 / (4.0 * 0.575), 1e-9);
  const auto pure_x = CalcF1TyreForce(p.front_tyre, 4000.0, 0.105, 0.0);
  EXPECT_NEAR(pure_x.fx, mu_x * 4000.0 * 0.965320682, 1e-3);  // 6081.537 N
  EXPECT_NEAR(pure_x.fy, 0.0, 1e-9);
  const auto pure_y = CalcF1TyreForce(p.front_tyre, 4000.0, 0.0, -DegToRad(8.5));
  EXPECT_NEAR(pure_y.fy, -mu_y * 4000.0 * 0.965320682, 1e-3);
  // Combined at half of each peak slip: rho = sqrt(0.5), force share 0.5 / rho on each axis.
  const double rho = std::sqrt(0.5);
  const double comb = std::sin(1.9 * std::atan(1.445981519 * rho)) * 0.5 / rho;
  const auto f = CalcF1TyreForce(p.front_tyre, 4000.0, 0.0525, DegToRad(4.25));
  EXPECT_NEAR(f.fx, mu_x * 4000.0 * comb, 1e-3);  // 4447.44 N
  EXPECT_NEAR(f.fy, mu_y * 4000.0 * comb, 1e-3);  // 4588.63 N
  // Far above the second reference load the interpolated friction (0.875 at 12 kN) is floored at
  // mu_min = 1 (smoothly: +2e-5).
  const auto high = CalcF1TyreForce(p.rear_tyre, 12000.0, 0.11 - 0.01 * 2.5, 0.0);
  EXPECT_NEAR(high.fx / (12000.0 * 0.965320682), 1.0, 1e-4);
}

TEST(F1Car, NormalLoadsSatisfyTheBalances) {
  const F1CarParams p = LoadF1Car(CarFile());
  const double mg = 660.0 * 9.81;
  // Standing still: the weight split by the axle distances, 1.6 / 3.4 on the front axle.
  const auto still = CalcF1NormalLoads(p, 0.0, 0.0, 0.0);
  EXPECT_NEAR(still[0], 0.5 * mg * 1.6 / 3.4, 1e-9);
  EXPECT_NEAR(still[2], 0.5 * mg * 1.8 / 3.4, 1e-9);
  EXPECT_NEAR(still[0], still[1], 1e-12);
  // At 50 m/s coasting (X = 0): downforce 2.7 u^2 = 6750 N at x = -0.1 m, drag 0.81 u^2 = 2025 N;
  // front axle (1.6 (mg + 6750) - 0.1 6750 + 0.3 2025) / 3.4 = 6203.488 N.
  const auto coast = CalcF1NormalLoads(p, 50.0, 0.0, 0.0);
  EXPECT_NEAR(coast[0] + coast[1], 6203.488235, 1e-3);
  EXPECT_NEAR(coast[2] + coast[3], mg + 6750.0 - 6203.488235, 1e-3);
  // Cornering left with 10 kN: each axle moves 0.3 * 10000 * 0.5 / 0.73 = 2054.79 N to the right.
  const auto turn = CalcF1NormalLoads(p, 50.0, 3000.0, 10000.0);
  EXPECT_NEAR(turn[1] - turn[0], 2054.794521, 1e-3);
  EXPECT_NEAR(turn[3] - turn[2], 2054.794521, 1e-3);
  // Pitch: a N_f - b N_r = x_p L - h (X - D).
  EXPECT_NEAR(1.8 * (turn[0] + turn[1]) - 1.6 * (turn[2] + turn[3]),
              -0.1 * 6750.0 - 0.3 * (3000.0 - 2025.0), 1e-6);
  EXPECT_NEAR(turn[0] + turn[1] + turn[2] + turn[3], mg + 6750.0, 1e-6);
}

TEST(F1Car, ThrottleSplitsIntoDriveAndBrake) {
  const F1CarParams p = LoadF1Car(CarFile());
  const auto full = F1ThrottleSplit(p, 1.0);
  EXPECT_NEAR(full[0], 1.0, 1e-5);
  EXPECT_NEAR(full[1], 0.0, 1e-5);
  const auto brake = F1ThrottleSplit(p, -0.5);
  EXPECT_NEAR(brake[0], 0.0, 1e-5);
  EXPECT_NEAR(brake[1], 0.5, 1e-5);
  // At zero both are sqrt(eps2) / 2.
  EXPECT_NEAR(F1ThrottleSplit(p, 0.0)[0], 0.5 * std::sqrt(1e-5), 1e-12);
}

}  // namespace
}  // namespace hotlap::vehicle
