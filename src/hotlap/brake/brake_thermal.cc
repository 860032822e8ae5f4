#include "hotlap/brake/brake_thermal.h"

#include <cmath>

#include "hotlap/common/units.h"

namespace hotlap::brake {

template <Scalar T>
T ConvectionPolynomial<T>::Conductance(const T& speed, const T& temp) const {
  // z = [1, u/100, (T - 273.15)/1000]; y = L' z; hA = y'y = z' L L' z (spec section 5).
  const T z2 = speed / 100.0;
  const T z3 = (temp - kZeroCelsius) / 1000.0;
  const T y1 = l11 + l21 * z2 + l31 * z3;
  const T y2 = l22 * z2 + l32 * z3;
  const T y3 = l33 * z3;
  return y1 * y1 + y2 * y2 + y3 * y3;
}

template <Scalar T>
T CalcBrakePower(const T& speed, const T& fx) {
  using std::abs;
  return ValueOf(fx) < 0.0 ? T(-abs(speed) * fx) : T(0.0);  // (000:26)
}

template <Scalar T>
BrakeHeatFlows<T> CalcBrakeHeatFlows(const BrakeThermalParams<T>& p, const BrakeState<T>& x,
                                     const BrakeInput<T>& in) {
  using std::abs;
  const T& td = x.disc_temp;
  const T& tk = x.calliper_temp;
  const T& t0 = in.cooling_air_temp;
  const T t0_4 = t0 * t0 * t0 * t0;
  const T speed = abs(in.speed);
  BrakeHeatFlows<T> q;
  q.q1 = CalcBrakePower(in.speed, in.fx);
  q.q2 = 2.0 * p.pad_conductivity * p.pad_area / p.pad_thickness * (td - tk);  // (000:27)
  q.q3 = p.disc_emissivity * kStefanBoltzmann * p.disc_radiating_area * (td * td * td * td - t0_4);
  q.q4 = p.disc_convection.Conductance(speed, td) * (td - t0);  // (000:30)
  q.q5 = p.calliper_emissivity * kStefanBoltzmann * p.calliper_radiating_area *
         (tk * tk * tk * tk - t0_4);                                // (000:29)
  q.q6 = p.calliper_convection.Conductance(speed, tk) * (tk - t0);  // (000:31)
  return q;
}

template <Scalar T>
BrakeState<T> CalcBrakeDerivatives(const BrakeThermalParams<T>& p, const BrakeState<T>& x,
                                   const BrakeInput<T>& in, BrakeHeatFlows<T>* flows) {
  const BrakeHeatFlows<T> q = CalcBrakeHeatFlows(p, x, in);
  if (flows != nullptr) *flows = q;
  BrakeState<T> dx;
  dx.disc_temp = (p.heat_partition * q.q1 - q.q2 - q.q3 - q.q4) /
                 (p.mass_participation * p.disc_mass * p.disc_heat_capacity);  // (000:24)
  dx.calliper_temp = ((1.0 - p.heat_partition) * q.q1 + q.q2 - q.q5 - q.q6) /
                     (p.calliper_mass * p.calliper_heat_capacity);  // (000:25)
  return dx;
}

#define HOTLAP_INSTANTIATE_BRAKE_THERMAL(T)                                                     \
  template struct ConvectionPolynomial<T>;                                                      \
  template T CalcBrakePower<T>(const T&, const T&);                                             \
  template BrakeHeatFlows<T> CalcBrakeHeatFlows<T>(const BrakeThermalParams<T>&,                \
                                                   const BrakeState<T>&, const BrakeInput<T>&); \
  template BrakeState<T> CalcBrakeDerivatives<T>(const BrakeThermalParams<T>&,                  \
                                                 const BrakeState<T>&, const BrakeInput<T>&,    \
                                                 BrakeHeatFlows<T>*);
HOTLAP_FOR_EACH_SCALAR(HOTLAP_INSTANTIATE_BRAKE_THERMAL)

}  // namespace hotlap::brake
