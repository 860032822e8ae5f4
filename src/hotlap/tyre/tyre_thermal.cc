#include "hotlap/tyre/tyre_thermal.h"

#include <cmath>

#include "hotlap/common/units.h"
#include "hotlap/tyre/air_properties.h"

namespace hotlap::tyre {

template <Scalar T>
T CalcContactLength(const TyreThermalParams<T>& params, const T& fz) {
  using std::abs;
  using std::pow;
  if (ValueOf(fz) == 0.0) return T(0.0);  // pow's derivative is singular at 0
  return params.contact_length_coeff * pow(abs(fz), params.contact_length_exponent);  // (000:14)
}

template <Scalar T>
T CalcForcedConvectionCoefficient(const TyreThermalParams<T>& params, const T& speed,
                                  const T& tread_temp, const T& ambient_temp) {
  using std::abs;
  using std::pow;
  if (ValueOf(speed) == 0.0) return T(0.0);
  const T film_temp = 0.5 * (tread_temp + ambient_temp);
  const T conductivity = AirConductivity(film_temp);
  const T viscosity = AirKinematicViscosity(film_temp);
  const T length = 1.0 / (1.0 / params.diameter + 1.0 / params.width);  // (000:16)
  const T reynolds = abs(speed) * length / viscosity;
  return conductivity / length * 0.0239 * pow(reynolds, 0.805);  // (000:15)
}

template <Scalar T>
TyreHeatFlows<T> CalcTyreHeatFlows(const TyreThermalParams<T>& p, const TyreState<T>& x,
                                   const TyreInput<T>& in) {
  using std::abs;
  using std::tan;
  const T speed = abs(in.speed);
  const T tread_area = kPi * p.diameter * p.width;                     // A_tot (000:13)
  const T contact_length = CalcContactLength(p, in.fz);                // c_l (000:14)
  const T convection_area = tread_area - p.contact_width * contact_length;  // A_conv (000:12)
  // Share of the patch that does not slide, (000:19), unclamped as in the paper.
  const T non_sliding = abs(in.slip_angle) / p.reference_slip_angle *
                            (p.non_sliding_fraction_high - p.non_sliding_fraction_low) +
                        p.non_sliding_fraction_low;
  const T adhesion_area = p.contact_width * non_sliding * contact_length;  // A_cp (000:18)
  const T h_forced = CalcForcedConvectionCoefficient(p, in.speed, x.tread_temp, in.ambient_temp);
  const T tread4 = x.tread_temp * x.tread_temp * x.tread_temp * x.tread_temp;
  const T carcass4 = x.carcass_temp * x.carcass_temp * x.carcass_temp * x.carcass_temp;
  const T ambient4 = in.ambient_temp * in.ambient_temp * in.ambient_temp * in.ambient_temp;
  const T sidewall_area = 2.0 * kPi *
                          (p.unloaded_radius * p.unloaded_radius - p.rim_radius * p.rim_radius);

  TyreHeatFlows<T> q;
  q.q1 = p.p1 * speed * (abs(in.fx * in.slip_ratio) + abs(in.fy * tan(in.slip_angle)));  // (000:9)
  q.q2 = speed * p.carcass_mass / (kPi * p.diameter) *
         (p.p2 * abs(in.fx) + p.p3 * abs(in.fy) + p.p4 * abs(in.fz));                  // (000:10)
  q.q3 = h_forced * convection_area * (x.tread_temp - in.ambient_temp);                // (000:11)
  q.q4 = p.track_conductance * adhesion_area * (x.tread_temp - in.track_temp);         // (000:17)
  q.q5 = p.p5 * tread_area * (x.carcass_temp - x.tread_temp);                          // (000:20)
  q.q6 = p.emissivity * kStefanBoltzmann * (tread_area - adhesion_area) * (tread4 - ambient4);
  q.q7 = p.emissivity * kStefanBoltzmann * sidewall_area * (carcass4 - ambient4);      // (000:22)
  return q;
}

template <Scalar T>
T CalcWearRate(const TyreThermalParams<T>& params, const TyreCompound& compound,
               const T& tread_temp, const T& q1) {
  using std::pow;
  if (ValueOf(q1) <= 0.0) return T(0.0);  // no sliding power, no wear; pow is singular at 0
  return params.wear_coeff * compound.wear_rate.Evaluate(tread_temp) *
         pow(q1 / compound.wear_reference_power, params.wear_exponent);  // (000:23)
}

template <Scalar T>
TyreState<T> CalcTyreDerivatives(const TyreThermalParams<T>& p, const TyreCompound& compound,
                                 const TyreState<T>& x, const TyreInput<T>& in,
                                 TyreHeatFlows<T>* flows) {
  const TyreHeatFlows<T> q = CalcTyreHeatFlows(p, x, in);
  if (flows != nullptr) *flows = q;
  TyreState<T> dx;
  dx.tread_temp = (q.q1 - q.q3 - q.q4 + q.q5 - q.q6) / (p.tread_mass * p.tread_heat_capacity);
  dx.carcass_temp = (q.q2 - q.q5 - q.q7) / (p.carcass_mass * p.carcass_heat_capacity);
  dx.wear = CalcWearRate(p, compound, x.tread_temp, q.q1);
  return dx;
}

#define HOTLAP_INSTANTIATE_TYRE_THERMAL(T)                                                      \
  template T CalcContactLength<T>(const TyreThermalParams<T>&, const T&);                       \
  template T CalcForcedConvectionCoefficient<T>(const TyreThermalParams<T>&, const T&,          \
                                                const T&, const T&);                            \
  template TyreHeatFlows<T> CalcTyreHeatFlows<T>(const TyreThermalParams<T>&,                   \
                                                 const TyreState<T>&, const TyreInput<T>&);     \
  template T CalcWearRate<T>(const TyreThermalParams<T>&, const TyreCompound&, const T&,        \
                             const T&);                                                         \
  template TyreState<T> CalcTyreDerivatives<T>(const TyreThermalParams<T>&, const TyreCompound&, \
                                               const TyreState<T>&, const TyreInput<T>&,        \
                                               TyreHeatFlows<T>*);
HOTLAP_FOR_EACH_SCALAR(HOTLAP_INSTANTIATE_TYRE_THERMAL)

}  // namespace hotlap::tyre
