// Synthetic rig data for the two rig fits (declared in mf_fit.h and unitire_fit.h): the models
// evaluated over a grid of operating points, with Gaussian noise scaled to each curve's peak.

#include <algorithm>
#include <cmath>
#include <random>

#include "hotlap/ident/mf_fit.h"
#include "hotlap/ident/rig_fit_common.h"
#include "hotlap/ident/unitire_fit.h"
#include "hotlap/tyre/magic_formula.h"

namespace hotlap::ident {

namespace {

// Appends one noise-free curve to `out` with noise of `noise_fraction` times the curve's peak
// |Fy|, |Mz| and |Fx| added to each row's Fy, Mz and (where set) Fx, drawn in that order.
void AppendWithNoise(std::vector<RigSample> curve, double noise_fraction, std::mt19937& rng,
                     std::normal_distribution<double>& normal, std::vector<RigSample>& out) {
  double fy_peak = 0.0, mz_peak = 0.0, fx_peak = 0.0;
  for (const RigSample& s : curve) {
    fy_peak = std::max(fy_peak, std::abs(s.fy));
    mz_peak = std::max(mz_peak, std::abs(s.mz));
    if (s.fx) fx_peak = std::max(fx_peak, std::abs(*s.fx));
  }
  for (RigSample& s : curve) {
    s.fy += noise_fraction * fy_peak * normal(rng);
    s.mz += noise_fraction * mz_peak * normal(rng);
    if (s.fx) *s.fx += noise_fraction * fx_peak * normal(rng);
    out.push_back(s);
  }
}

}  // namespace

std::vector<RigSample> SynthesizeMagicFormulaRigData(const tyre::MagicFormulaParams<double>& truth,
                                                     std::span<const double> loads,
                                                     std::span<const double> cambers,
                                                     std::span<const double> slip_angles,
                                                     std::span<const double> slip_ratios,
                                                     double speed, double tread_temp,
                                                     double noise_fraction, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<RigSample> out;
  const auto curve = [&](double fz, double camber, bool lateral) {
    std::vector<RigSample> rows;
    for (double x : lateral ? slip_angles : slip_ratios) {
      RigSample s;
      s.fz = fz;
      s.camber = camber;
      s.speed = speed;
      s.tread_temp = tread_temp;
      (lateral ? s.slip_angle : s.slip_ratio) = x;
      const tyre::TyreForces<double> f =
          tyre::CalcMagicFormula(truth, internal::RigOperatingPoint<double>(s), {});
      s.fy = f.fy;
      s.mz = f.mz;
      s.fx = f.fx;
      rows.push_back(s);
    }
    AppendWithNoise(std::move(rows), noise_fraction, rng, normal, out);
  };
  for (double fz : loads) {
    for (double camber : cambers) {
      curve(fz, camber, /*lateral=*/true);
      curve(fz, camber, /*lateral=*/false);
    }
  }
  return out;
}

std::vector<RigSample> SynthesizeRigData(const tyre::UniTireParams<double>& truth,
                                         std::span<const double> temps,
                                         std::span<const double> loads,
                                         std::span<const double> slip_angles, double noise_fraction,
                                         std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<RigSample> out;
  for (double temp : temps) {
    for (double fz : loads) {
      std::vector<RigSample> curve;
      for (double alpha : slip_angles) {
        RigSample s;
        s.slip_angle = alpha;
        s.fz = fz;
        s.speed = kRigSpeed;
        s.tread_temp = temp;
        const tyre::TyreForces<double> f =
            tyre::CalcUniTireForces(truth, internal::RigOperatingPoint<double>(s));
        s.fy = f.fy;
        s.mz = f.mz;
        curve.push_back(s);
      }
      AppendWithNoise(std::move(curve), noise_fraction, rng, normal, out);
    }
  }
  return out;
}

}  // namespace hotlap::ident
