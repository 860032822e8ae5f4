#include "hotlap/fe/yeoh.h"

#include <cmath>

#include <Eigen/LU>

namespace hotlap::fe {

YeohMaterial MakeYeohMaterial(double c10_Pa, double c20_Pa, double c30_Pa, double density_kg_per_m3,
                              double bulk_to_shear_ratio) {
  YeohMaterial m;
  m.c10_Pa = c10_Pa;
  m.c20_Pa = c20_Pa;
  m.c30_Pa = c30_Pa;
  m.density_kg_per_m3 = density_kg_per_m3;
  m.bulk_modulus_Pa = bulk_to_shear_ratio * 2.0 * c10_Pa;
  return m;
}

double InitialShearModulus(const YeohMaterial& m) { return 2.0 * m.c10_Pa; }

double InitialPoissonRatio(const YeohMaterial& m) {
  const double k = m.bulk_modulus_Pa, mu = InitialShearModulus(m);
  return (3.0 * k - 2.0 * mu) / (2.0 * (3.0 * k + mu));
}

double DilatationalWaveSpeed(const YeohMaterial& m) {
  return std::sqrt((m.bulk_modulus_Pa + 4.0 / 3.0 * InitialShearModulus(m)) / m.density_kg_per_m3);
}

double CalcYeohEnergyDensity(const YeohMaterial& m, const Eigen::Matrix3d& F) {
  const double j = F.determinant();
  const double i1b = std::pow(j, -2.0 / 3.0) * (F * F.transpose()).trace();
  const double d = i1b - 3.0;
  return m.c10_Pa * d + m.c20_Pa * d * d + m.c30_Pa * d * d * d +
         0.5 * m.bulk_modulus_Pa * (j - 1.0) * (j - 1.0);
}

Eigen::Matrix3d CalcYeohCauchyStress(const YeohMaterial& m, const Eigen::Matrix3d& F) {
  const double j = F.determinant();
  const Eigen::Matrix3d bb = std::pow(j, -2.0 / 3.0) * (F * F.transpose());
  const double i1b = bb.trace();
  const double d = i1b - 3.0;
  const double w1 = m.c10_Pa + 2.0 * m.c20_Pa * d + 3.0 * m.c30_Pa * d * d;
  const Eigen::Matrix3d dev = bb - (i1b / 3.0) * Eigen::Matrix3d::Identity();
  return (2.0 / j) * w1 * dev + m.bulk_modulus_Pa * (j - 1.0) * Eigen::Matrix3d::Identity();
}

Eigen::Matrix3d CalcYeohFirstPiola(const YeohMaterial& m, const Eigen::Matrix3d& F) {
  return F.determinant() * CalcYeohCauchyStress(m, F) * F.inverse().transpose();
}

}  // namespace hotlap::fe
