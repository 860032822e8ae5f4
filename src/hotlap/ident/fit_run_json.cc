#include "hotlap/ident/fit_run_json.h"

#include <cmath>
#include <map>
#include <string>

#include "hotlap/common/json_output.h"

namespace hotlap::ident {

namespace {

nlohmann::json Num(double v) {
  if (!std::isfinite(v)) return nullptr;
  return RoundSignificant(v);
}

nlohmann::json ParameterJson(const FitParameter& p, const ParameterEstimate& e,
                             const std::map<std::string, double>& truth) {
  nlohmann::json j = {
      {"value", Num(e.value + p.display_offset)},
      {"std_error", Num(e.std_error)},
      {"ci95", {Num(e.ci_low + p.display_offset), Num(e.ci_high + p.display_offset)}},
      {"well_determined", e.well_determined},
      {"undetermined", e.undetermined},
      {"at_bound", e.at_bound},
      {"start", Num(e.start + p.display_offset)},
      {"unit", p.unit},
  };
  // Only model parameters are in the joint family (nuisance ones get null).
  j["ci95_joint"] = p.role == ParameterRole::kModel
                        ? nlohmann::json{Num(e.joint_low + p.display_offset),
                                         Num(e.joint_high + p.display_offset)}
                        : nlohmann::json(nullptr);
  if (auto it = truth.find(p.key); it != truth.end()) {
    j["truth"] = Num(it->second);
    const double t = it->second - p.display_offset;
    j["in_ci95"] = t >= e.ci_low && t <= e.ci_high;
    j["in_ci95_joint"] = t >= e.joint_low && t <= e.joint_high;
  }
  return j;
}

nlohmann::json FitJson(const ReportedFit& r) {
  const FitResult& f = r.fit;
  nlohmann::json nuisance = nlohmann::json::object(), names = nlohmann::json::array();
  for (size_t i = 0; i < f.parameters.size(); ++i) {
    names.push_back(f.parameters[i].key);
    if (f.parameters[i].role == ParameterRole::kNuisance) {
      nuisance[f.parameters[i].key] = ParameterJson(f.parameters[i], f.estimates[i], {});
    }
  }
  nlohmann::json matrix = nlohmann::json::array();
  for (Eigen::Index i = 0; i < f.correlation.rows(); ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (Eigen::Index k = 0; k < f.correlation.cols(); ++k) {
      row.push_back(std::isfinite(f.correlation(i, k))
                        ? nlohmann::json(std::round(f.correlation(i, k) * 1e4) / 1e4)
                        : nlohmann::json(nullptr));
    }
    matrix.push_back(row);
  }
  nlohmann::json channels = nlohmann::json::object();
  for (const ChannelStats& c : f.channels) {
    channels[c.name] = {{"samples", c.samples},
                        {"rms", Num(c.rms)},
                        {"noise", Num(c.sigma)},
                        {"outliers", c.outliers},
                        {"autocorrelation", Num(c.autocorrelation)},
                        {"apparent_lag_s", Num(c.apparent_lag)}};
  }
  nlohmann::json held = nlohmann::json::object();
  for (const auto& [k, v] : r.held) held[k] = Num(v);
  return {{"nuisance", nuisance},
          {"held", held},
          {"correlation", {{"parameters", names}, {"matrix", matrix}}},
          {"channels", channels},
          {"converged", f.converged},
          {"iterations", f.iterations},
          {"starts_scored", f.starts_scored},
          {"starts_solved", f.starts_solved},
          {"warnings", f.AllWarnings()}};
}

}  // namespace

nlohmann::json FitRunJson(const FitRun& run) {
  nlohmann::json corners = nlohmann::json::object();
  nlohmann::json all_warnings = nlohmann::json::array();
  for (const CornerFitOutcome& c : run.result.corners) {
    const std::string name(CornerName(c.corner));
    nlohmann::json j = {{"fitted", c.fitted}};
    for (const auto& [key, value] : c.rms) j[key] = Num(value);
    nlohmann::json params = nlohmann::json::object(), fits = nlohmann::json::object();
    for (const ReportedFit& r : c.fits) {
      for (size_t i = 0; i < r.fit.parameters.size(); ++i) {
        if (r.fit.parameters[i].role == ParameterRole::kModel) {
          params[r.fit.parameters[i].key] =
              ParameterJson(r.fit.parameters[i], r.fit.estimates[i], c.truth);
        }
      }
      for (const auto& [k, v] : r.held) {
        params[k] = {{"value", Num(v)},          {"std_error", nullptr},
                     {"ci95", nullptr},          {"ci95_joint", nullptr},
                     {"well_determined", false}, {"undetermined", false},
                     {"at_bound", false},        {"held", true}};
      }
      fits[r.title] = FitJson(r);
    }
    j["parameters"] = params;
    j["fits"] = fits;
    j["warnings"] = CornerWarnings(c);
    for (const std::string& w : CornerWarnings(c)) all_warnings.push_back(name + ": " + w);
    corners[name] = j;
  }
  return {{"command", run.command},
          {"telemetry", run.telemetry},
          {"car", run.car_name},
          {"out", run.out},
          {"samples", run.time.size()},
          {"duration_s", Num(run.time.empty() ? 0.0 : run.time.back() - run.time.front())},
          {"options", run.options},
          {"joint_family_size", run.result.joint_family_size},
          {"elapsed_s", Num(run.elapsed_s)},
          {"warnings", all_warnings},
          {"corners", corners}};
}

}  // namespace hotlap::ident
