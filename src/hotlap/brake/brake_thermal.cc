#include "hotlap/brake/brake_thermal.h"

#include <algorithm>
#include <cmath>

#include "hotlap/common/units.h"

namespace hotlap::brake {

template <Scalar T>
typename ConvectionPolynomial<T>::AtSpeed ConvectionPolynomial<T>::ForSpeed(const T& speed) const {
  using std::abs;
  const T z2 = abs(speed) * 1e-2;
  return {l11 + l21 * z2, l22 * z2};
}

template <Scalar T>
T ConvectionPolynomial<T>::Conductance(const AtSpeed& s, const T& temp) const {
  // z = [1, u/100, (T - 273.15)/1000]; y = L' z; hA = y'y = z' L L' z (spec section 5).
  const T z3 = (temp - kZeroCelsius) * 1e-3;
  const T y1 = s.a + l31 * z3;
  const T y2 = s.b + l32 * z3;
  const T y3 = l33 * z3;
  return y1 * y1 + y2 * y2 + y3 * y3;
}

template <Scalar T>
T ConvectionPolynomial<T>::Conductance(const T& speed, const T& temp) const {
  return Conductance(ForSpeed(speed), temp);
}

template <Scalar T>
T CalcBrakePower(const T& speed, const T& fx) {
  using std::abs;
  return ValueOf(fx) < 0.0 ? T(-abs(speed) * fx) : T(0.0);  // (000:26)
}

double BrakeFxFromPower(double speed, double power, double fx) {
  const double u = std::abs(speed);
  if (!(u >= 0.1)) return std::min(fx, 0.0);
  return -std::max(power, 0.0) / u;
}

template <Scalar T>
BrakeConstants<T> CalcBrakeConstants(const BrakeThermalParams<T>& p) {
  BrakeConstants<T> k;
  k.pad_conductance = 2.0 * p.pad_conductivity * p.pad_area / p.pad_thickness;  // (000:27)
  k.disc_radiation = p.disc_emissivity * kStefanBoltzmann * p.disc_radiating_area;
  k.calliper_radiation = p.calliper_emissivity * kStefanBoltzmann * p.calliper_radiating_area;
  k.inv_disc_capacity = 1.0 / (p.mass_participation * p.disc_mass * p.disc_heat_capacity);
  k.inv_calliper_capacity = 1.0 / (p.calliper_mass * p.calliper_heat_capacity);
  return k;
}

template <Scalar T>
BrakeInputTerms<T> CalcBrakeInputTerms(const BrakeThermalParams<T>& p, const BrakeConstants<T>& k,
                                       const BrakeInput<T>& in) {
  using std::abs;
  BrakeInputTerms<T> t;
  t.input = in;
  t.power = CalcBrakePower(in.speed, in.fx);
  t.disc_at_speed = p.disc_convection.ForSpeed(in.speed);
  t.calliper_at_speed = p.calliper_convection.ForSpeed(in.speed);
  const T t0_2 = in.cooling_air_temp * in.cooling_air_temp;
  t.cooling_air_temp4 = t0_2 * t0_2;
  t.constants = k;
  if (p.HasBulk()) {
    // Vane flow: G (still + (1 - still) (|u| / 50 m/s)^0.8), as the tyre's conductances.
    using std::exp;
    using std::log;
    const T u = abs(in.speed);
    t.vane_factor = ValueOf(u) == 0.0
                        ? p.bulk_still_air_fraction
                        : p.bulk_still_air_fraction +
                              (1.0 - p.bulk_still_air_fraction) * exp(0.8 * log(T(u / 50.0)));
  }
  return t;
}

template <Scalar T>
BrakeInputTerms<T> CalcBrakeInputTerms(const BrakeThermalParams<T>& p, const BrakeInput<T>& in) {
  return CalcBrakeInputTerms(p, CalcBrakeConstants(p), in);
}

template <Scalar T>
BrakeHeatFlows<T> CalcBrakeHeatFlows(const BrakeThermalParams<T>& p, const BrakeState<T>& x,
                                     const BrakeInputTerms<T>& t, const T& rim_temp) {
  const T& td = x.disc_temp;
  const T& tk = x.calliper_temp;
  const T& t0 = t.input.cooling_air_temp;
  const T td2 = td * td;
  const T tk2 = tk * tk;
  BrakeHeatFlows<T> q;
  q.q1 = t.power;                                                                 // (000:26)
  q.q2 = t.constants.pad_conductance * (td - tk);                                 // (000:27)
  q.q3 = t.constants.disc_radiation * (td2 * td2 - t.cooling_air_temp4);          // (000:28)
  q.q4 = p.disc_convection.Conductance(t.disc_at_speed, td) * (td - t0);          // (000:30)
  q.q5 = t.constants.calliper_radiation * (tk2 * tk2 - t.cooling_air_temp4);      // (000:29)
  q.q6 = p.calliper_convection.Conductance(t.calliper_at_speed, tk) * (tk - t0);  // (000:31)
  if (p.HasBulk()) {
    const T& tb = x.bulk_temp;
    // The share of the surface's radiation that the rim sees leaves against the rim's temperature.
    const T tr2 = rim_temp * rim_temp;
    q.radiation_to_rim = p.rim_view_fraction * t.constants.disc_radiation * (td2 * td2 - tr2 * tr2);
    q.q3 = (1.0 - p.rim_view_fraction) * q.q3;
    q.to_bulk = p.bulk_conductance * (td - tb);
    q.bulk_convection = p.bulk_convection * t.vane_factor * (tb - t0);
    q.hub_to_rim = p.hub_conductance * (tb - rim_temp);
  }
  return q;
}

template <Scalar T>
BrakeHeatFlows<T> CalcBrakeHeatFlows(const BrakeThermalParams<T>& p, const BrakeState<T>& x,
                                     const BrakeInput<T>& in) {
  return CalcBrakeHeatFlows(p, x, CalcBrakeInputTerms(p, in));
}

template <Scalar T>
BrakeState<T> CalcBrakeDerivatives(const BrakeThermalParams<T>& p, const BrakeState<T>& x,
                                   const BrakeInputTerms<T>& t, BrakeHeatFlows<T>* flows,
                                   const T& rim_temp) {
  const BrakeHeatFlows<T> q = CalcBrakeHeatFlows(p, x, t, rim_temp);
  if (flows != nullptr) *flows = q;
  BrakeState<T> dx;
  if (p.HasBulk()) {
    dx.disc_temp = (p.heat_partition * q.q1 - q.q2 - q.q3 - q.q4 - q.to_bulk - q.radiation_to_rim) *
                   t.constants.inv_disc_capacity;
    dx.bulk_temp = (q.to_bulk - q.bulk_convection - q.hub_to_rim) /
                   ((1.0 - p.mass_participation) * p.disc_mass * p.disc_heat_capacity);
  } else {
    dx.disc_temp =
        (p.heat_partition * q.q1 - q.q2 - q.q3 - q.q4) * t.constants.inv_disc_capacity;  // (000:24)
  }
  dx.calliper_temp = ((1.0 - p.heat_partition) * q.q1 + q.q2 - q.q5 - q.q6) *
                     t.constants.inv_calliper_capacity;  // (000:25)
  return dx;
}

template <Scalar T>
BrakeState<T> CalcBrakeDerivatives(const BrakeThermalParams<T>& p, const BrakeState<T>& x,
                                   const BrakeInput<T>& in, BrakeHeatFlows<T>* flows) {
  return CalcBrakeDerivatives(p, x, CalcBrakeInputTerms(p, in), flows);
}

#define HOTLAP_INSTANTIATE_BRAKE_THERMAL(T)                                                       \
  template struct ConvectionPolynomial<T>;                                                        \
  template T CalcBrakePower<T>(const T&, const T&);                                               \
  template BrakeConstants<T> CalcBrakeConstants<T>(const BrakeThermalParams<T>&);                 \
  template BrakeInputTerms<T> CalcBrakeInputTerms<T>(                                             \
      const BrakeThermalParams<T>&, const BrakeConstants<T>&, const BrakeInput<T>&);              \
  template BrakeInputTerms<T> CalcBrakeInputTerms<T>(const BrakeThermalParams<T>&,                \
                                                     const BrakeInput<T>&);                       \
  template BrakeHeatFlows<T> CalcBrakeHeatFlows<T>(const BrakeThermalParams<T>&,                  \
                                                   const BrakeState<T>&, const BrakeInput<T>&);   \
  template BrakeHeatFlows<T> CalcBrakeHeatFlows<T>(                                               \
      const BrakeThermalParams<T>&, const BrakeState<T>&, const BrakeInputTerms<T>&, const T&);   \
  template BrakeState<T> CalcBrakeDerivatives<T>(const BrakeThermalParams<T>&,                    \
                                                 const BrakeState<T>&, const BrakeInput<T>&,      \
                                                 BrakeHeatFlows<T>*);                             \
  template BrakeState<T> CalcBrakeDerivatives<T>(const BrakeThermalParams<T>&,                    \
                                                 const BrakeState<T>&, const BrakeInputTerms<T>&, \
                                                 BrakeHeatFlows<T>*, const T&);
HOTLAP_FOR_EACH_SCALAR(HOTLAP_INSTANTIATE_BRAKE_THERMAL)
// The optimal-control lap's brake elements have 5 inputs, its wheel elements 15.
HOTLAP_INSTANTIATE_BRAKE_THERMAL(::hotlap::SecondOrder<5>)
HOTLAP_INSTANTIATE_BRAKE_THERMAL(::hotlap::SecondOrder<15>)
HOTLAP_INSTANTIATE_BRAKE_THERMAL(::hotlap::Jet15)

}  // namespace hotlap::brake
