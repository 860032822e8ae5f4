#pragma once
/// @file
/// A ChannelModel (channel_fit.h) over a scalar-templated model, with exact derivatives by
/// forward-mode automatic differentiation: the model runs once on Jets whose derivative lanes are
/// seeded with the free parameters, so the derivatives of a whole integrated trajectory come out
/// of the same RK4 steps as its values (forward sensitivities, exact to rounding).
///
/// A Model provides:
///   size_t num_samples() const;
///   int num_channels() const;
///   template <Scalar T, class Emit> void Run(std::span<const T> params, Emit&& emit) const;
/// where Run calls emit(channel, sample, value) for every channel and sample it predicts.
///
/// Jet sizes are those the models are compiled for (scalar.h: 2, 5, 7, 14). With more free
/// parameters than 14 the model runs again for the rest (14 lanes, then the smallest size that
/// holds what is left).

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

#include "hotlap/common/scalar.h"
#include "hotlap/ident/channel_fit.h"

namespace hotlap::ident {

template <class Model>
class JetPredictor final : public ChannelModel {
 public:
  /// `all` holds a value for every parameter of the model; `free` the indices of those fitted
  /// (in the fit's order); `channels` the model channels fitted (in the fit's order).
  JetPredictor(const Model& model, std::vector<double> all, std::vector<int> free,
               std::vector<int> channels)
      : model_(model),
        all_(std::move(all)),
        free_(std::move(free)),
        channels_(std::move(channels)) {
    out_index_.assign(model_.num_channels(), -1);
    for (size_t c = 0; c < channels_.size(); ++c) out_index_[channels_[c]] = static_cast<int>(c);
  }

  int num_parameters() const override { return static_cast<int>(free_.size()); }
  int num_channels() const override { return static_cast<int>(channels_.size()); }
  size_t num_samples() const override { return model_.num_samples(); }

  /// Every parameter's value with the free ones at `x`.
  std::vector<double> AllAt(std::span<const double> x) const {
    std::vector<double> all = all_;
    for (size_t i = 0; i < free_.size(); ++i) all[free_[i]] = x[i];
    return all;
  }

  bool Predict(std::span<const double> x, bool with_jacobian, Predictions* out) const override {
    const std::vector<double> all = AllAt(x);
    const size_t n = num_samples(), p = free_.size();
    out->value.assign(channels_.size(), std::vector<double>(n, 0.0));
    if (!with_jacobian) {
      out->jacobian.clear();
      model_.template Run<double>(all, [&](int m, size_t k, const double& v) {
        if (const int c = out_index_[m]; c >= 0) out->value[c][k] = v;
      });
    } else {
      out->jacobian.assign(channels_.size(), std::vector<double>(n * p, 0.0));
      for (size_t first = 0; first < p;) {
        const size_t left = p - first;
        if (left <= 2) {
          first += RunChunk<2>(all, first, out);
        } else if (left <= 5) {
          first += RunChunk<5>(all, first, out);
        } else if (left <= 7) {
          first += RunChunk<7>(all, first, out);
        } else {
          first += RunChunk<14>(all, first, out);
        }
      }
    }
    for (const auto& ch : out->value) {
      if (!std::all_of(ch.begin(), ch.end(), [](double v) { return std::isfinite(v); })) {
        return false;
      }
    }
    for (const auto& ch : out->jacobian) {
      if (!std::all_of(ch.begin(), ch.end(), [](double v) { return std::isfinite(v); })) {
        return false;
      }
    }
    return true;
  }

 private:
  // Runs the model on Jets with lanes for free parameters first..first+N-1; returns how many.
  template <int N>
  size_t RunChunk(const std::vector<double>& all, size_t first, Predictions* out) const {
    using J = ceres::Jet<double, N>;
    const size_t p = free_.size();
    const size_t count = std::min<size_t>(N, p - first);
    std::vector<J> x(all.size());
    for (size_t j = 0; j < all.size(); ++j) x[j] = J(all[j]);
    for (size_t l = 0; l < count; ++l) x[free_[first + l]].v[l] = 1.0;
    model_.template Run<J>(x, [&](int m, size_t k, const J& v) {
      const int c = out_index_[m];
      if (c < 0) return;
      out->value[c][k] = v.a;
      double* row = &out->jacobian[c][k * p + first];
      for (size_t l = 0; l < count; ++l) row[l] = v.v[l];
    });
    return count;
  }

  const Model& model_;
  std::vector<double> all_;
  std::vector<int> free_;
  std::vector<int> channels_;
  std::vector<int> out_index_;
};

}  // namespace hotlap::ident
