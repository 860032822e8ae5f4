#include "hotlap/ident/fit_run.h"

#include <cmath>

#include <fmt/format.h>

namespace hotlap::ident {

std::string ShortNumber(double v) {
  if (!std::isfinite(v)) return v > 0 ? "inf" : (v < 0 ? "-inf" : "n/a");
  return fmt::format("{:.4g}", v);
}

std::string IntervalText(const FitParameter& p, const ParameterEstimate& e) {
  return fmt::format("[{}, {}]", ShortNumber(e.ci_low + p.display_offset),
                     ShortNumber(e.ci_high + p.display_offset));
}

std::string JointIntervalText(const FitParameter& p, const ParameterEstimate& e) {
  if (p.role != ParameterRole::kModel) return "";
  return fmt::format("[{}, {}]", ShortNumber(e.joint_low + p.display_offset),
                     ShortNumber(e.joint_high + p.display_offset));
}

std::string VerdictText(const ParameterEstimate& e) {
  if (e.undetermined) return "undetermined";
  if (e.at_bound) return "at bound";
  return e.well_determined ? "yes" : "no";
}

}  // namespace hotlap::ident
