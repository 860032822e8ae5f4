#include "hotlap/ident/fit_run.h"

#include <cmath>
#include <iterator>

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

std::string FitRunText(const FitRun& run) {
  std::string out = fmt::format(
      "hotlap {}: {} ({} samples, {:.2f} s of log) with car '{}'\n", run.command, run.telemetry,
      run.time.size(), run.time.empty() ? 0.0 : run.time.back() - run.time.front(), run.car_name);
  auto it = std::back_inserter(out);
  for (const CornerFitOutcome& c : run.result.corners) {
    fmt::format_to(it, "{}:", CornerName(c.corner));
    for (const auto& [key, value] : c.rms) fmt::format_to(it, "  {} {:.4g}", key, value);
    fmt::format_to(it, "\n");
    for (const auto& [p, e] : ModelParameters(c)) {
      fmt::format_to(
          it,
          "  {:<12} {:>11} {:<10} std error {:>9}  95% {:<24} joint {:<24} well determined: {}\n",
          p->label, ShortNumber(e->value + p->display_offset), p->unit, ShortNumber(e->std_error),
          IntervalText(*p, *e), JointIntervalText(*p, *e), VerdictText(*e));
    }
    for (const ReportedFit& r : c.fits) {
      for (const auto& [k, v] : r.held) {
        fmt::format_to(it, "  {:<12} {:>11} (held)\n", k, ShortNumber(v));
      }
    }
  }
  fmt::format_to(it, "fitted in {:.2f} s\n", run.elapsed_s);
  return out;
}

std::vector<std::string> FitRunWarnings(const FitRun& run) {
  std::vector<std::string> out;
  for (const CornerFitOutcome& c : run.result.corners) {
    for (const std::string& w : CornerWarnings(c)) {
      out.push_back(std::string(CornerName(c.corner)) + ": " + w);
    }
  }
  return out;
}

}  // namespace hotlap::ident
