#pragma once
/// @file
/// The paper's front brake for the brake model's tests.

#include <cmath>

#include "hotlap/brake/brake_thermal.h"

namespace hotlap::test {

// Front brake, 000 Table 5 and the assumed values of spec section 5, typed in here (not loaded).
// The Cholesky factors are those of P_disc = [[6,3,2],[3,12,2],[2,2,10]] and
// P_cal = [[1,.5,.2],[.5,4,.2],[.2,.2,2]], computed exactly.
inline brake::BrakeThermalParams<double> PaperFrontBrakeParams() {
  brake::BrakeThermalParams<double> p;
  p.heat_partition = 0.95;
  p.mass_participation = 0.1;
  p.disc_mass = 8.8;
  p.disc_heat_capacity = 480;
  p.calliper_mass = 5.0312;
  p.calliper_heat_capacity = 921.1;
  p.pad_conductivity = 0.5;
  p.pad_area = 9472e-6;
  p.pad_thickness = 0.025;
  p.disc_emissivity = 0.48;
  p.calliper_emissivity = 0.25;
  p.disc_radiating_area = 0.6302;
  p.calliper_radiating_area = 12.81e-4;
  {
    brake::ConvectionPolynomial<double>& l = p.disc_convection;
    l.l11 = std::sqrt(6.0);
    l.l21 = 3.0 / l.l11;
    l.l22 = std::sqrt(12.0 - l.l21 * l.l21);
    l.l31 = 2.0 / l.l11;
    l.l32 = (2.0 - l.l31 * l.l21) / l.l22;
    l.l33 = std::sqrt(10.0 - l.l31 * l.l31 - l.l32 * l.l32);
  }
  {
    brake::ConvectionPolynomial<double>& l = p.calliper_convection;
    l.l11 = 1.0;
    l.l21 = 0.5;
    l.l22 = std::sqrt(4.0 - 0.25);
    l.l31 = 0.2;
    l.l32 = (0.2 - 0.2 * 0.5) / l.l22;
    l.l33 = std::sqrt(2.0 - 0.04 - l.l32 * l.l32);
  }
  return p;
}

}  // namespace hotlap::test
