#pragma once
/// @file
/// The Magic Formula's effective rolling radius and how the inflation pressure moves it: the
/// radius a free-rolling wheel turns at (its forward speed over its spin), between the loaded and
/// the free radius, since a radial's belt hardly stretches as the carcass deflects. MF-Swift's
/// form (Besselink, Schmeitz and Pacejka, VSD 48 S1 (2010); Pacejka, Tyre and Vehicle Dynamics,
/// 3rd ed. 2012, section 9.3):
///
///   C_z = VERTICAL_STIFFNESS (1 + PFZ1 dpi),     dpi = (p - NOMPRES) / NOMPRES
///   R_e = R_0 Q_RE0 - (F_z0 / C_z) (DREFF atan(BREFF F_z / F_z0) + FREFF F_z / F_z0)
///
/// with the deflection taken as linear in the load (Q_FZ2 and the force terms of C_z at zero,
/// so rho_z / rho_Fz0 = F_z / F_z0) and no speed growth (the free radius at rest). The pressure
/// acts through C_z: a harder tyre deflects less and rolls on a larger radius, so as the gas heats
/// a run's tyres their rollouts grow, the soft left sides most, and an oval car's stagger (the
/// right rear's rollout over the left rear's) moves with the air.

#include <cmath>

#include "hotlap/common/scalar.h"
#include "hotlap/tyre/magic_formula.h"

namespace hotlap::tyre {

/// R_e (m) of a Magic Formula tyre at load `fz` (N, clamped at 0) and inflation `pressure` (Pa;
/// 0 means the file's INFLPRES).
template <Scalar T>
T CalcEffectiveRollingRadius(const MagicFormulaParams<T>& p, const T& fz, const T& pressure) {
  using std::atan;
  const T load = fz > T(0.0) ? fz : T(0.0);
  const T inflation = pressure == T(0.0) ? T(p.INFLPRES) : pressure;
  const T dpi = (inflation - p.NOMPRES) / p.NOMPRES;
  const T cz = p.VERTICAL_STIFFNESS * (1.0 + p.PFZ1 * dpi);
  const T fz0 = p.LFZO * p.FNOMIN;
  const T rho = load / fz0;
  return p.UNLOADED_RADIUS * p.Q_RE0 - (fz0 / cz) * (p.DREFF * atan(p.BREFF * rho) + p.FREFF * rho);
}

/// How far the effective rolling radius at load `fz` (N) moves from inflation `from` to `to`
/// (Pa), m: what a measured rollout at the cold set gains at the hot pressure.
template <Scalar T>
T CalcRollingRadiusChange(const MagicFormulaParams<T>& p, const T& fz, const T& from, const T& to) {
  return CalcEffectiveRollingRadius(p, fz, to) - CalcEffectiveRollingRadius(p, fz, from);
}

}  // namespace hotlap::tyre
