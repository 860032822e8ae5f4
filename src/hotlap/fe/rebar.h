#pragma once
/// @file
/// Rebar: cord layers smeared into their host hexahedra as fibre reinforcement (002 Tables 2-3,
/// spec section 9).
///
/// A layer of cords of cross-section A at spacing s is a sheet of equivalent thickness A / s.
/// Inside a host element it occupies the volume fraction phi = (A / s) * (sheet area in the
/// element) / V0. The cords are linear elastic in their Green-Lagrange strain along the cord,
///   E_f = (lambda^2 - 1) / 2,  lambda = |F a0|,  S = phi E E_f a0 (x) a0,  P = F S,
/// energy phi E E_f^2 / 2 per unit reference volume, so the fibre Cauchy stress
/// sigma_f = phi E E_f lambda^2 / J a (x) a acts along the deformed cord direction a = F a0 /
/// lambda. With FibreResponse::kTensionOnly (the default for textile and steel cords, which buckle
/// in compression inside soft rubber) the cord carries nothing when lambda < 1.

#include <cstdint>
#include <string>

#include <Eigen/Core>

namespace hotlap::fe {

/// How a cord responds to compression.
enum class FibreResponse : std::uint8_t {
  kTensionOnly,  ///< no stress when the cord is shorter than in the reference state
  kLinear,       ///< the same modulus in tension and compression
};

/// One cord material and its layer geometry. SI units.
struct RebarMaterial {
  std::string name;
  double youngs_modulus_Pa = 0.0;  ///< E of the cord (002 Table 2), Pa
  double density_kg_per_m3 = 0.0;  ///< cord density (002 Table 2), kg/m^3
  double area_m2 = 0.0;            ///< cord cross-section A (002 Table 3), m^2
  double spacing_m = 0.0;          ///< cord spacing s (002 Table 3), m
  double angle_deg = 0.0;          ///< cord angle from the meridional direction (Table 3)
  FibreResponse response = FibreResponse::kTensionOnly;

  /// Equivalent sheet thickness A / s, m.
  double SheetThickness() const { return area_m2 / spacing_m; }
};

/// A cord layer inside one host element.
struct FibreLayer {
  int element = 0;                                       ///< host element index
  int rebar = 0;                                         ///< index into the rebar materials
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();  ///< reference cord direction a0, unit
  double volume_fraction = 0.0;                          ///< phi in the host element, 1
};

/// Adds the fibre's first Piola stress to `P` and returns its energy per unit reference volume.
/// Inline: the solver's element loop is compiled for two instruction sets and inlines it into
/// each (explicit_solver.cc).
inline double AddFibreStress(const RebarMaterial& rebar, const FibreLayer& layer,
                             const Eigen::Matrix3d& F, Eigen::Matrix3d& P) {
  const Eigen::Vector3d fa = F * layer.direction;
  const double strain = 0.5 * (fa.squaredNorm() - 1.0);  // Green-Lagrange along the cord
  if (strain < 0.0 && rebar.response == FibreResponse::kTensionOnly) return 0.0;
  const double s = layer.volume_fraction * rebar.youngs_modulus_Pa * strain;
  P.noalias() += s * fa * layer.direction.transpose();  // P = F S, S = s a0 a0^T
  return 0.5 * s * strain;
}

}  // namespace hotlap::fe
