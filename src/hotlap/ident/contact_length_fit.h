#pragma once
/// @file
/// Fitting one corner's contact-length law c_l = p_cp1 |Fz|^p_cp2 (000:14, Table 2) to measured
/// rolling radii (spec section 6; docs/fitting.md). The residual is in the measured quantity:
/// r_model = sqrt(r0^2 - (c_l / 2)^2) (the patch as a chord of the unloaded circle, the inverse of
/// c_l = 2 sqrt(r0^2 - r_r^2)) minus the measured r_r. Samples with |Fz| below 200 N (a wheel
/// off the ground) or a radius at or above r0 are left out. Starts: the car's values and the
/// straight line through log c_l against log |Fz|.
///
/// Pitfall: p_cp1 is the contact length at 1 N, far outside any log, so it and p_cp2 are almost
/// perfectly correlated and p_cp1's interval is wide even when the curve is tight over the loads
/// logged; the report shows the correlation.

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "hotlap/ident/channel_fit.h"
#include "hotlap/ident/fit_log.h"
#include "hotlap/tyre/tyre_params_io.h"

namespace hotlap::ident {

struct ContactLengthFitResult {
  std::optional<FitResult> fit;  ///< p_cp1, p_cp2
  double p_cp1 = 0.0, p_cp2 = 0.0;
  std::vector<std::string> warnings;
  std::vector<double> radius_model;  ///< m at every sample
  int samples_used = 0;
};

/// Fits one corner from its loads `fz` (N) and logged rolling radius (m). InputError if the
/// sizes differ.
ContactLengthFitResult FitContactLength(const tyre::TyreFile& tyre, std::span<const double> fz,
                                        const LoggedChannel& radius, const FitOptions& options);

}  // namespace hotlap::ident
