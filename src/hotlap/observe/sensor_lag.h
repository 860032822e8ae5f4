#pragma once
/// @file
/// First-order sensor lags as extra filter states (docs/observer.md, "Sensor lag"): a sensor of
/// time constant tau reads y with tau dy/dt = x - y, x the state it measures. Over an interval dt
/// with x linear between the samples (as the models' inputs are taken) the exact solution is
///   y1 = a y0 + c x0 + b x1,  a = exp(-dt / tau),  b = 1 - tau (1 - a) / dt,  c = 1 - a - b,
/// the formula `hotlap synth`'s sensors use (sim/synth_sensor.h), so a synthetic log's lagged
/// readings are described exactly. The filter carries y beside the model's states, with its
/// covariance and its cross-covariance with them, and corrects through y: a reading is compared
/// with what the lagging sensor should read now, not with the state itself.
///
/// How to use (inside a filter of N states with M sensors): Reset() with the states' Gaussian
/// (each sensor starts settled: y = its state, fully correlated with it); in the prediction, call
/// Predict() with the states' Gaussian *before* it is propagated, the transition F and the new
/// means, then propagate the states as usual; Update() in place of UpdateScalar for a reading.
/// With every tau zero the sensors are not carried (Active() is false) and the filter reads its
/// states directly, at no cost.

#include <algorithm>
#include <array>
#include <cmath>

#include <Eigen/Core>

namespace hotlap::observe {

/// The joint Kalman update of states `x` and lagging sensors (means y, cross-covariance X with
/// the states, covariance Y) with a reading `z` of sensor j of variance r: rejected (nothing
/// changed) beyond the gate. Returns as UpdateScalar.
template <class Outcome, class G, class Y, class X, class C>
Outcome LaggedUpdate(G& x, Y& y, X& cross, C& cov, int j, double z, double r, double gate_nis) {
  Outcome out;
  const double s = cov(j, j) + r;
  out.innovation = z - y(j);
  out.nis = out.innovation * out.innovation / s;
  if (!(out.nis <= gate_nis)) {
    out.rejected = true;
    return out;
  }
  const auto kx = (cross.col(j) / s).eval();
  const auto ky = (cov.col(j) / s).eval();
  x.mean += kx * out.innovation;
  y += ky * out.innovation;
  x.cov.noalias() -= (s * kx) * kx.transpose();
  cross.noalias() -= (s * kx) * ky.transpose();
  cov.noalias() -= (s * ky) * ky.transpose();
  cov(j, j) = std::max(cov(j, j), 0.0);
  out.used = true;
  return out;
}

template <int N, int M>
class SensorLags {
 public:
  /// Sensor j reads state `index[j]` with time constant `tau_s[j]` (s, >= 0).
  SensorLags(const std::array<int, M>& index, const std::array<double, M>& tau_s)
      : index_(index), tau_(tau_s) {
    for (double t : tau_) active_ = active_ || t > 0.0;
  }

  bool Active() const { return active_; }
  double tau(int j) const { return tau_[j]; }

  /// The sensors settled on the states of `x`.
  template <class G>
  void Reset(const G& x) {
    if (!active_) return;
    for (int j = 0; j < M; ++j) {
      mean_(j) = x.mean(index_[j]);
      cross_.col(j) = x.cov.col(index_[j]);
      for (int k = 0; k < M; ++k) cov_(j, k) = x.cov(index_[j], index_[k]);
    }
  }

  /// Over an interval of length dt: `before` is the states' Gaussian at its start, `f` the
  /// transition of the states' means, `after_mean` their means at its end, `q_dt` the process
  /// noise added to the states over it (diagonal). Call before the states' covariance is
  /// propagated (it needs the old one).
  template <class G, class F, class V>
  void Predict(const G& before, const F& f, const V& after_mean, const V& q_dt, double dt) {
    if (!active_) return;
    Eigen::Matrix<double, M, N> g = Eigen::Matrix<double, M, N>::Zero();  // dy1/dx0
    Eigen::Matrix<double, M, 1> a, b;
    for (int j = 0; j < M; ++j) {
      const int i = index_[j];
      if (tau_[j] > 0.0) {
        a(j) = std::exp(-dt / tau_[j]);
        b(j) = 1.0 - tau_[j] * (1.0 - a(j)) / dt;
      } else {
        a(j) = 0.0;  // reads the state itself: y1 = x1
        b(j) = 1.0;
      }
      const double c = 1.0 - a(j) - b(j);
      g.row(j) = b(j) * f.row(i);
      g(j, i) += c;
      mean_(j) = a(j) * mean_(j) + c * before.mean(i) + b(j) * after_mean(i);
    }
    const auto& p = before.cov;
    // Cov(x1, y1) = F P G' + F X A + Q E B, Cov(y1, y1) = G P G' + G X A + A X' G' + A Y A + B E'Q
    // E B.
    const Eigen::Matrix<double, N, M> fx = f * cross_;
    Eigen::Matrix<double, N, M> cross = f * p * g.transpose() + fx * a.asDiagonal();
    Eigen::Matrix<double, M, M> gx = g * cross_ * a.asDiagonal();
    Eigen::Matrix<double, M, M> cov =
        g * p * g.transpose() + gx + gx.transpose() + a.asDiagonal() * cov_ * a.asDiagonal();
    for (int j = 0; j < M; ++j) {
      cross(index_[j], j) += b(j) * q_dt(index_[j]);
      for (int k = 0; k < M; ++k) {
        if (index_[j] == index_[k]) cov(j, k) += b(j) * b(k) * q_dt(index_[j]);
      }
    }
    cross_ = cross;
    cov_ = 0.5 * (cov + cov.transpose());
  }

  /// A reading `z` of sensor j with variance r: the joint Kalman update of the states `x` and the
  /// sensors; rejected (nothing changed) beyond the gate. Returns as UpdateScalar.
  template <class Outcome, class G>
  Outcome Update(G& x, int j, double z, double r, double gate_nis) {
    return LaggedUpdate<Outcome>(x, mean_, cross_, cov_, j, z, r, gate_nis);
  }

  /// What sensor j should read now, and that reading's variance without the sensor's noise.
  double mean(int j) const { return mean_(j); }
  double var(int j) const { return cov_(j, j); }
  /// Covariance of state `i` with sensor j.
  double cross(int i, int j) const { return cross_(i, j); }

 private:
  std::array<int, M> index_;
  std::array<double, M> tau_;
  bool active_ = false;
  Eigen::Matrix<double, M, 1> mean_ = Eigen::Matrix<double, M, 1>::Zero();
  Eigen::Matrix<double, N, M> cross_ = Eigen::Matrix<double, N, M>::Zero();
  Eigen::Matrix<double, M, M> cov_ = Eigen::Matrix<double, M, M>::Zero();
};

}  // namespace hotlap::observe
