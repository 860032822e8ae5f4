#pragma once
/// @file
/// The statistics of an ensemble of runs (docs/fe-tyre.md, "ABS stop"): one figure's mean, its
/// standard error and spread over the members, and the equivalence test by which two ensembles
/// (two time steps, two kinds of perturbation) are judged to agree.
///
///   const sim::EnsembleStat a = sim::CalcEnsembleStat(values_at_full_step);
///   const sim::EnsembleStat b = sim::CalcEnsembleStat(values_at_half_step);
///   const bool same = sim::EquivalenceBound(a, b) < margin;

#include <vector>

namespace hotlap::sim {

/// One figure over the members of an ensemble.
struct EnsembleStat {
  int n = 0;                    ///< members with a value
  double mean = 0.0;            ///< 0 without members
  double sd = 0.0;              ///< sample standard deviation (n - 1); 0 with fewer than two
  double standard_error = 0.0;  ///< sd / sqrt(n)
  double min = 0.0, max = 0.0;  ///< the spread
};

/// The statistic of `values` (each member's figure; members without one left out).
EnsembleStat CalcEnsembleStat(const std::vector<double>& values);

/// How far apart two ensembles' means can be, at about 95%: |mean_a - mean_b| + 2 sqrt(se_a^2 +
/// se_b^2), each standard error taken as at least `se_floor` (a floor keeps two ensembles whose
/// members happen to agree from claiming a precision the member count cannot give). Two
/// ensembles are equivalent within a margin when this is below it. Infinite if either has no
/// member.
double EquivalenceBound(const EnsembleStat& a, const EnsembleStat& b, double se_floor = 0.0);

/// The p-quantile (0 <= p <= 1) of `values`, linear between order statistics (the sample at
/// rank p (n - 1)); 0 for none.
double Quantile(std::vector<double> values, double p);

}  // namespace hotlap::sim
