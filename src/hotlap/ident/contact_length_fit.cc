#include "hotlap/ident/contact_length_fit.h"
#include "hotlap/common/special_values.h"

#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/ident/jet_predictor.h"
#include "hotlap/tyre/tyre_thermal_fields.h"

namespace hotlap::ident {

namespace {

constexpr double kMinLoad = 200.0;  // N: below this the wheel is taken as off the ground

// Rolling radius from the load through the contact-length law.
class RadiusModel {
 public:
  RadiusModel(const tyre::TyreFile& tyre, std::span<const double> fz) : tyre_(tyre), fz_(fz) {}
  size_t num_samples() const { return fz_.size(); }
  int num_channels() const { return 1; }

  template <Scalar T, class Emit>
  void Run(std::span<const T> x, Emit&& emit) const {
    using std::sqrt;
    tyre::TyreThermalParams<T> p = tyre_.params.Cast<T>();
    p.contact_length_coeff = x[0];
    p.contact_length_exponent = x[1];
    const double r0 = tyre_.params.unloaded_radius;
    for (size_t k = 0; k < fz_.size(); ++k) {
      const T half = 0.5 * tyre::CalcContactLength(p, T(fz_[k]));
      emit(0, k, sqrt(r0 * r0 - half * half));  // NaN past the circle: the step is rejected
    }
  }

 private:
  const tyre::TyreFile& tyre_;
  std::span<const double> fz_;
};

}  // namespace

ContactLengthFitResult FitContactLength(const tyre::TyreFile& tyre, std::span<const double> fz,
                                        const LoggedChannel& radius, const FitOptions& options) {
  if (radius.values.size() != fz.size()) {
    throw InputError("contact-length fit: the radius and load channels differ in length");
  }
  ContactLengthFitResult r;
  r.p_cp1 = tyre.params.contact_length_coeff;
  r.p_cp2 = tyre.params.contact_length_exponent;
  if (const std::string s = DescribeChannelProblems(radius); !s.empty()) r.warnings.push_back(s);
  const double r0 = tyre.params.unloaded_radius;
  MeasuredChannel ch{.name = "rolling_radius",
                     .unit = "mm",
                     .display_scale = 1000.0,
                     .values = radius.values,
                     .weights = {},
                     .prior_sigma = 1e-4,
                     .min_sigma = 1e-7};
  int unloaded = 0, beyond = 0;
  double sxx = 0.0, sx = 0.0, sy = 0.0, sxy = 0.0;
  for (size_t k = 0; k < fz.size(); ++k) {
    double& v = ch.values[k];
    if (!std::isfinite(v)) continue;
    if (std::abs(fz[k]) < kMinLoad) {
      ++unloaded;
      v = kNaN;
    } else if (v >= r0) {
      ++beyond;
      v = kNaN;
    } else {
      // The straight line through log c_l against log |Fz|, for the starting guess.
      const double x = std::log(std::abs(fz[k])), y = std::log(2.0 * std::sqrt(r0 * r0 - v * v));
      sx += x;
      sy += y;
      sxx += x * x;
      sxy += x * y;
      ++r.samples_used;
    }
  }
  if (unloaded + beyond > 0) {
    r.warnings.push_back(fmt::format(
        "{}: {} samples with |Fz| < {:.0f} N and {} with a radius at or above r0 = {:.4f} m left "
        "out",
        radius.column.empty() ? "rolling_radius" : radius.column, unloaded, kMinLoad, beyond, r0));
  }
  r.radius_model.assign(fz.size(), kNaN);
  const RadiusModel model(tyre, fz);
  if (r.samples_used < 10) {
    r.warnings.push_back(
        fmt::format("only {} usable rolling-radius samples: p_cp1 and p_cp2 kept from the car file",
                    r.samples_used));
  } else {
    // p_cp1, p_cp2 as the field table describes them.
    std::vector<FitParameter> params;
    for (const tyre::TyreThermalField* f : tyre::FittedTyreThermalFields("contact_length")) {
      params.push_back(FitParameterOf(std::string(f->key), *f->fit, f->Of(tyre.params)));
    }
    std::vector<std::vector<double>> starts = {{r.p_cp1, r.p_cp2}};
    const double n = r.samples_used, den = n * sxx - sx * sx;
    if (den > 0.0) {
      const double slope = (n * sxy - sx * sy) / den;
      starts.push_back({std::exp((sy - slope * sx) / n), slope});
    }
    const JetPredictor<RadiusModel> predictor(model, {r.p_cp1, r.p_cp2}, {0, 1}, {0});
    const std::vector<MeasuredChannel> channels = {ch};
    r.fit = FitChannels(predictor, params, channels, starts, {}, options);
    r.p_cp1 = r.fit->estimates[0].value;
    r.p_cp2 = r.fit->estimates[1].value;
  }
  const std::vector<double> x = {r.p_cp1, r.p_cp2};
  model.Run<double>(x, [&](int, size_t k, double v) { r.radius_model[k] = v; });
  return r;
}

}  // namespace hotlap::ident
