#pragma once
/// @file
/// Yeoh hyperelastic rubber, nearly incompressible, as used by the FE/ABS paper (002 Table 1).
///
/// Strain energy per unit reference volume (spec section 9):
///   W = C10 (I1b - 3) + C20 (I1b - 3)^2 + C30 (I1b - 3)^3 + (K / 2) (J - 1)^2,
/// with J = det F, I1b = J^(-2/3) tr(F F^T) and K = 2 / D1 the bulk modulus. The initial shear
/// modulus is mu0 = 2 C10. The paper gives no D1; Abaqus/Explicit then takes K = 20 mu0
/// (Poisson's ratio about 0.475), the default of MakeYeohMaterial.
///
/// Cauchy stress: sigma = (2 / J) W1 dev(Bb) + K (J - 1) I, with Bb = J^(-2/3) F F^T and
/// W1 = dW/dI1b = C10 + 2 C20 (I1b - 3) + 3 C30 (I1b - 3)^2. SI units throughout.

#include <bit>
#include <cmath>
#include <cstdint>

#include <Eigen/Core>

namespace hotlap::fe {

/// Abaqus/Explicit's bulk-to-shear modulus ratio when a hyperelastic material gives no D1.
inline constexpr double kAbaqusDefaultBulkToShearRatio = 20.0;

/// One Yeoh rubber. SI units.
struct YeohMaterial {
  double c10_Pa = 0.0;             ///< C10 (the paper's C1), Pa (> 0)
  double c20_Pa = 0.0;             ///< C20 (C2), Pa
  double c30_Pa = 0.0;             ///< C30 (C3), Pa
  double bulk_modulus_Pa = 0.0;    ///< K = 2 / D1, Pa (> 0)
  double density_kg_per_m3 = 0.0;  ///< rho, kg/m^3 (> 0)
};

/// A Yeoh material whose bulk modulus is `bulk_to_shear_ratio` times the initial shear modulus.
YeohMaterial MakeYeohMaterial(double c10_Pa, double c20_Pa, double c30_Pa, double density_kg_per_m3,
                              double bulk_to_shear_ratio);

/// Initial shear modulus mu0 = 2 C10, Pa.
double InitialShearModulus(const YeohMaterial& m);
/// Initial Poisson's ratio from K and mu0, 1.
double InitialPoissonRatio(const YeohMaterial& m);
/// Dilatational wave speed sqrt((K + 4/3 mu0) / rho), m/s: sets the stable time step.
double DilatationalWaveSpeed(const YeohMaterial& m);

/// W(F), J/m^3 of reference volume. F must have det F > 0.
double CalcYeohEnergyDensity(const YeohMaterial& m, const Eigen::Matrix3d& F);
/// Cauchy stress sigma(F), Pa.
Eigen::Matrix3d CalcYeohCauchyStress(const YeohMaterial& m, const Eigen::Matrix3d& F);
/// First Piola-Kirchhoff stress P = J sigma F^-T, Pa (dW/dF).
Eigen::Matrix3d CalcYeohFirstPiola(const YeohMaterial& m, const Eigen::Matrix3d& F);

/// x^(1/3) for the solver's element loop, where glibc's cbrt (with its frexp and scalbn calls)
/// was about 7% of a step: a first guess from the exponent bits (within 3.2%), then three
/// Halley steps (cubic convergence: 3e-2, 3e-5, 3e-14, round-off). Within 3 ulp of std::cbrt;
/// falls back to it outside [1e-300, 1e300].
inline double CubeRoot(double x) {
  if (!(x >= 1e-300 && x <= 1e300)) return std::cbrt(x);
  double y = std::bit_cast<double>(std::bit_cast<std::uint64_t>(x) / 3 + 0x2a9f7893782da1ceULL);
  for (int k = 0; k < 3; ++k) {
    const double y3 = y * y * y;
    y *= (y3 + 2.0 * x) / (2.0 * y3 + x);
  }
  return y;
}

/// The solver's fused form: given F, J = det F and F^-T, sets P (Pa) and returns W (J/m^3),
///   P = 2 W1 J^(-2/3) F - (2/3) W1 I1b F^-T + K (J - 1) J F^-T,
/// the same P as J sigma F^-T without forming B. `cbrt_j` is J^(1/3) (the caller needs it too).
/// Inline: the solver's element loop is compiled for two instruction sets and inlines it into
/// each (explicit_solver.cc).
inline double CalcYeohPiolaAndEnergy(const YeohMaterial& m, const Eigen::Matrix3d& F, double j,
                                     double cbrt_j, const Eigen::Matrix3d& f_inv_t,
                                     Eigen::Matrix3d& P) {
  const double jm23 = 1.0 / (cbrt_j * cbrt_j);  // J^(-2/3)
  const double i1b = jm23 * F.squaredNorm();
  const double d = i1b - 3.0;
  const double w1 = m.c10_Pa + 2.0 * m.c20_Pa * d + 3.0 * m.c30_Pa * d * d;
  const double vol = m.bulk_modulus_Pa * (j - 1.0);
  P.noalias() = (2.0 * w1 * jm23) * F + (vol * j - 2.0 / 3.0 * w1 * i1b) * f_inv_t;
  return m.c10_Pa * d + m.c20_Pa * d * d + m.c30_Pa * d * d * d + 0.5 * vol * (j - 1.0);
}

}  // namespace hotlap::fe
