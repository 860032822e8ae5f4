#include "hotlap/tyre/tyre_thermal.h"

#include <cmath>

#include "hotlap/common/units.h"
#include "hotlap/tyre/air_properties.h"

namespace hotlap::tyre {

namespace {

// x^y for x > 0 as exp(y log x): the same value to rounding, faster than pow in glibc, and
// differentiable in both arguments for Jets.
template <Scalar T, class E>
T PowPositive(const T& x, const E& y) {
  using std::exp;
  using std::log;
  return exp(y * log(x));
}

// Exponent of the Reynolds number in (000:15).
constexpr double kReynoldsExponent = 0.805;

// The forced-convection coefficient from its state-independent factor (000:15):
// h = k/L 0.0239 (|u| L / nu)^0.805 = k/L 0.0239 (|u| L)^0.805 nu^-0.805.
template <Scalar T>
T ForcedConvection(const T& length, const T& speed_length_pow, const T& tread_temp,
                   const T& ambient_temp) {
  if (ValueOf(speed_length_pow) == 0.0) return T(0.0);
  const T film_temp = 0.5 * (tread_temp + ambient_temp);
  const T conductivity = AirConductivity(film_temp);
  const T viscosity = AirKinematicViscosity(film_temp);
  return conductivity / length * 0.0239 * speed_length_pow *
         PowPositive(viscosity, -kReynoldsExponent);
}

template <Scalar T>
T CharacteristicLength(const TyreThermalParams<T>& p) {
  return 1.0 / (1.0 / p.diameter + 1.0 / p.width);  // (000:16)
}

}  // namespace

template <Scalar T>
T CalcContactLength(const TyreThermalParams<T>& params, const T& fz) {
  using std::abs;
  if (ValueOf(fz) == 0.0) return T(0.0);  // the power's derivative is singular at 0
  return params.contact_length_coeff *
         PowPositive(T(abs(fz)), params.contact_length_exponent);  // (000:14)
}

template <Scalar T>
T CalcForcedConvectionCoefficient(const TyreThermalParams<T>& params, const T& speed,
                                  const T& tread_temp, const T& ambient_temp) {
  using std::abs;
  const T length = CharacteristicLength(params);
  const T speed_length_pow =
      ValueOf(speed) == 0.0 ? T(0.0) : PowPositive(T(abs(speed) * length), kReynoldsExponent);
  return ForcedConvection(length, speed_length_pow, tread_temp, ambient_temp);
}

namespace {

// Every input term except the wear factor, which needs the compound.
template <Scalar T>
TyreInputTerms<T> CalcHeatInputTerms(const TyreThermalParams<T>& p, const TyreInput<T>& in) {
  using std::abs;
  using std::tan;
  TyreInputTerms<T> t;
  t.input = in;
  const T speed = abs(in.speed);
  t.tread_area = kPi * p.diameter * p.width;                            // A_tot (000:13)
  const T contact_length = CalcContactLength(p, in.fz);                 // c_l (000:14)
  t.convection_area = t.tread_area - p.contact_width * contact_length;  // A_conv (000:12)
  // Share of the patch that does not slide, (000:19), unclamped as in the paper.
  const T non_sliding = abs(in.slip_angle) / p.reference_slip_angle *
                            (p.non_sliding_fraction_high - p.non_sliding_fraction_low) +
                        p.non_sliding_fraction_low;
  t.adhesion_area = p.contact_width * non_sliding * contact_length;  // A_cp (000:18)
  t.q1 = p.p1 * speed * (abs(in.fx * in.slip_ratio) + abs(in.fy * tan(in.slip_angle)));  // (000:9)
  t.q2 = speed * p.carcass_mass / (kPi * p.diameter) *
         (p.p2 * abs(in.fx) + p.p3 * abs(in.fy) + p.p4 * abs(in.fz));  // (000:10)
  t.length = CharacteristicLength(p);
  t.speed_length_pow =
      ValueOf(speed) == 0.0 ? T(0.0) : PowPositive(T(speed * t.length), kReynoldsExponent);
  return t;
}

}  // namespace

template <Scalar T>
TyreInputTerms<T> CalcTyreInputTerms(const TyreThermalParams<T>& p, const TyreCompound& compound,
                                     const TyreInput<T>& in) {
  TyreInputTerms<T> t = CalcHeatInputTerms(p, in);
  // (000:23); no sliding power, no wear (the power's derivative is singular at 0).
  t.wear_power_factor = ValueOf(t.q1) <= 0.0
                            ? T(0.0)
                            : PowPositive(T(t.q1 / compound.wear_reference_power), p.wear_exponent);
  return t;
}

template <Scalar T>
TyreHeatFlows<T> CalcTyreHeatFlows(const TyreThermalParams<T>& p, const TyreState<T>& x,
                                   const TyreInputTerms<T>& t) {
  const TyreInput<T>& in = t.input;
  const T h_forced = ForcedConvection(t.length, t.speed_length_pow, x.tread_temp, in.ambient_temp);
  const T tread4 = x.tread_temp * x.tread_temp * x.tread_temp * x.tread_temp;
  const T carcass4 = x.carcass_temp * x.carcass_temp * x.carcass_temp * x.carcass_temp;
  const T ambient4 = in.ambient_temp * in.ambient_temp * in.ambient_temp * in.ambient_temp;
  const T sidewall_area =
      2.0 * kPi * (p.unloaded_radius * p.unloaded_radius - p.rim_radius * p.rim_radius);
  TyreHeatFlows<T> q;
  q.q1 = t.q1;                                                                    // (000:9)
  q.q2 = t.q2;                                                                    // (000:10)
  q.q3 = h_forced * t.convection_area * (x.tread_temp - in.ambient_temp);         // (000:11)
  q.q4 = p.track_conductance * t.adhesion_area * (x.tread_temp - in.track_temp);  // (000:17)
  q.q5 = p.p5 * t.tread_area * (x.carcass_temp - x.tread_temp);                   // (000:20)
  q.q6 = p.emissivity * kStefanBoltzmann * (t.tread_area - t.adhesion_area) *
         (tread4 - ambient4);                                                      // (000:21)
  q.q7 = p.emissivity * kStefanBoltzmann * sidewall_area * (carcass4 - ambient4);  // (000:22)
  return q;
}

template <Scalar T>
TyreHeatFlows<T> CalcTyreHeatFlows(const TyreThermalParams<T>& p, const TyreState<T>& x,
                                   const TyreInput<T>& in) {
  return CalcTyreHeatFlows(p, x, CalcHeatInputTerms(p, in));
}

template <Scalar T>
T CalcWearRate(const TyreThermalParams<T>& params, const TyreCompound& compound,
               const T& tread_temp, const T& q1) {
  if (ValueOf(q1) <= 0.0) return T(0.0);  // no sliding power, no wear; the power is singular at 0
  return params.wear_coeff * compound.wear_rate.Evaluate(tread_temp) *
         PowPositive(T(q1 / compound.wear_reference_power), params.wear_exponent);  // (000:23)
}

template <Scalar T>
TyreState<T> CalcTyreDerivatives(const TyreThermalParams<T>& p, const TyreCompound& compound,
                                 const TyreState<T>& x, const TyreInputTerms<T>& t,
                                 TyreHeatFlows<T>* flows) {
  const TyreHeatFlows<T> q = CalcTyreHeatFlows(p, x, t);
  if (flows != nullptr) *flows = q;
  TyreState<T> dx;
  dx.tread_temp = (q.q1 - q.q3 - q.q4 + q.q5 - q.q6) / (p.tread_mass * p.tread_heat_capacity);
  dx.carcass_temp = (q.q2 - q.q5 - q.q7) / (p.carcass_mass * p.carcass_heat_capacity);
  dx.wear = p.wear_coeff * compound.wear_rate.Evaluate(x.tread_temp) * t.wear_power_factor;
  return dx;
}

template <Scalar T>
TyreState<T> CalcTyreDerivatives(const TyreThermalParams<T>& p, const TyreCompound& compound,
                                 const TyreState<T>& x, const TyreInput<T>& in,
                                 TyreHeatFlows<T>* flows) {
  return CalcTyreDerivatives(p, compound, x, CalcTyreInputTerms(p, compound, in), flows);
}

#define HOTLAP_INSTANTIATE_TYRE_THERMAL(T)                                                         \
  template T CalcContactLength<T>(const TyreThermalParams<T>&, const T&);                          \
  template T CalcForcedConvectionCoefficient<T>(const TyreThermalParams<T>&, const T&, const T&,   \
                                                const T&);                                         \
  template TyreInputTerms<T> CalcTyreInputTerms<T>(const TyreThermalParams<T>&,                    \
                                                   const TyreCompound&, const TyreInput<T>&);      \
  template TyreHeatFlows<T> CalcTyreHeatFlows<T>(const TyreThermalParams<T>&, const TyreState<T>&, \
                                                 const TyreInput<T>&);                             \
  template TyreHeatFlows<T> CalcTyreHeatFlows<T>(const TyreThermalParams<T>&, const TyreState<T>&, \
                                                 const TyreInputTerms<T>&);                        \
  template T CalcWearRate<T>(const TyreThermalParams<T>&, const TyreCompound&, const T&,           \
                             const T&);                                                            \
  template TyreState<T> CalcTyreDerivatives<T>(const TyreThermalParams<T>&, const TyreCompound&,   \
                                               const TyreState<T>&, const TyreInput<T>&,           \
                                               TyreHeatFlows<T>*);                                 \
  template TyreState<T> CalcTyreDerivatives<T>(const TyreThermalParams<T>&, const TyreCompound&,   \
                                               const TyreState<T>&, const TyreInputTerms<T>&,      \
                                               TyreHeatFlows<T>*);
HOTLAP_FOR_EACH_SCALAR(HOTLAP_INSTANTIATE_TYRE_THERMAL)

}  // namespace hotlap::tyre
