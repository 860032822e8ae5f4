#pragma once
/// @file
/// The paper's rear-right tyre for the tyre model's tests.

#include "hotlap/tyre/tyre_thermal.h"

namespace hotlap::test {

// Rear-right tyre: 000 Tables 2-4 as printed in spec section 2, typed in here (not loaded) so the
// test does not depend on the loader.
inline tyre::TyreThermalParams<double> PaperRearRightParams() {
  tyre::TyreThermalParams<double> p;
  p.p1 = 0.328;
  p.p2 = 0.0042;
  p.p3 = 1.641e-05;
  p.p4 = 1.797e-05;
  p.p5 = 427.5;
  p.wear_coeff = 5.506e-06;
  p.wear_exponent = 1.785;
  p.contact_length_coeff = 0.0001508;
  p.contact_length_exponent = 0.795321;
  p.tread_mass = 0.9;
  p.carcass_mass = 11.0;
  p.tread_heat_capacity = 900;
  p.carcass_heat_capacity = 1600;
  p.track_conductance = 1200;
  p.contact_width = 0.2286;
  p.reference_slip_angle = 8.0 * 3.14159265358979323846 / 180.0;
  p.non_sliding_fraction_low = 0.3;
  p.non_sliding_fraction_high = 0.8;
  p.unloaded_radius = 0.3613;
  p.rim_radius = 0.229;
  p.diameter = 0.4572;
  p.width = 0.2921;
  p.emissivity = 0.93;
  return p;
}

}  // namespace hotlap::test
