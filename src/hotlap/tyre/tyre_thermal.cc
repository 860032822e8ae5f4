#include "hotlap/tyre/tyre_thermal.h"

#include <array>
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

}  // namespace

template <Scalar T>
BinomialSeries<T> BinomialSeries<T>::For(const T& exponent) {
  BinomialSeries<T> s;
  s.exponent = exponent;
  s.coefficients[0] = T(1.0);
  for (int n = 1; n < kTerms; ++n) {
    s.coefficients[n] = s.coefficients[n - 1] * (exponent - (n - 1.0)) / double(n);
  }
  return s;
}

namespace {

// x^y from a nearby x0 > 0 whose power p0 = x0^y is known: x^y = p0 (1 + r)^y, r = x / x0 - 1,
// by the binomial series to r^8 when |r| <= 0.02 (remainder below 1e-15 relative), else
// directly. Between two log samples the tyre's inputs change by much less than 2%, so most of an
// integrator's powers come from the previous stage's at the cost of a few multiplications.
template <Scalar T>
T PowPositiveNear(const T& x, const BinomialSeries<T>& series, const T& x0, const T& p0) {
  constexpr double kMaxRatio = 0.02;
  if (!(ValueOf(x0) > 0.0)) return PowPositive(x, series.exponent);
  const T r = x / x0 - 1.0;
  if (!(std::abs(ValueOf(r)) <= kMaxRatio)) return PowPositive(x, series.exponent);
  // Estrin's scheme for the 9 coefficients.
  const auto& c = series.coefficients;
  const T r2 = r * r;
  const T r4 = r2 * r2;
  const T s01 = c[0] + c[1] * r;
  const T s23 = c[2] + c[3] * r;
  const T s45 = c[4] + c[5] * r;
  const T s67 = c[6] + c[7] * r;
  const T sum = (s01 + s23 * r2) + (s45 + s67 * r2) * r4 + c[8] * (r4 * r4);
  return p0 * sum;
}

// The forced-convection coefficient from its state-independent factor (000:15):
// h = k/L 0.0239 (|u| L / nu)^0.805 = k/L 0.0239 (|u| L)^0.805 nu^-0.805.
template <Scalar T>
T ForcedConvection(const T& length, const T& speed_length_pow, const T& tread_temp,
                   const T& ambient_temp) {
  if (ValueOf(speed_length_pow) == 0.0) return T(0.0);
  const T film_temp = 0.5 * (tread_temp + ambient_temp);
  static_assert(kReynoldsExponent == 0.805, "AirConvectionFactor's series is for 0.805");
  return 0.0239 / length * speed_length_pow * AirConvectionFactor(film_temp);
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

template <Scalar T>
TyreConstants<T> CalcTyreConstants(const TyreThermalParams<T>& p) {
  TyreConstants<T> k;
  k.tread_area = kPi * p.diameter * p.width;  // A_tot (000:13)
  k.length = CharacteristicLength(p);         // (000:16)
  k.convection_scale = 0.0239 / k.length;     // (000:15)
  k.tread_to_carcass = p.p5 * k.tread_area;   // (000:20)
  k.sidewall_radiation = p.emissivity * kStefanBoltzmann * 2.0 * kPi *
                         (p.unloaded_radius * p.unloaded_radius - p.rim_radius * p.rim_radius);
  k.inv_tread_capacity = 1.0 / (p.tread_mass * p.tread_heat_capacity);
  k.inv_carcass_capacity = 1.0 / (p.carcass_mass * p.carcass_heat_capacity);
  k.carcass_heating = p.carcass_mass / (kPi * p.diameter);
  k.load_series = BinomialSeries<T>::For(p.contact_length_exponent);
  k.speed_series = BinomialSeries<T>::For(T(kReynoldsExponent));
  k.wear_series = BinomialSeries<T>::For(p.wear_exponent);
  return k;
}

namespace {

// |x|, or its smooth stand-in sqrt(x^2 + eps^2) - eps when eps > 0 (TyreThermalSmoothing).
template <Scalar T>
T Magnitude(const T& x, double eps) {
  using std::abs;
  using std::sqrt;
  if (eps <= 0.0) return abs(x);
  return sqrt(x * x + eps * eps) - eps;
}

// G (still + (1 - still) (|u| / 50 m/s)^0.8): the gas-and-rim model's speed-dependent
// conductances, turbulent forced convection (Nu ~ Re^0.8) above a still-air share.
template <Scalar T>
T SpeedFactor(const TyreThermalParams<T>& p, const T& speed) {
  using std::abs;
  const T u = abs(speed);
  if (ValueOf(u) == 0.0) return p.still_air_fraction;
  return p.still_air_fraction +
         (1.0 - p.still_air_fraction) * PowPositive(T(u / kConductanceReferenceSpeed), 0.8);
}

// Every input term except the wear factor, which needs the compound.
// With `near` given (terms of a nearby input), its powers seed this input's (PowPositiveNear).
template <Scalar T>
TyreInputTerms<T> CalcHeatInputTerms(const TyreThermalParams<T>& p, const TyreConstants<T>& k,
                                     const TyreInput<T>& in, const TyreInputTerms<T>* near) {
  using std::abs;
  using std::tan;
  TyreInputTerms<T> t;
  t.input = in;
  const T speed = abs(in.speed);
  t.tread_area = k.tread_area;  // A_tot (000:13)
  const T fz = abs(in.fz);
  // c_l = p_cp1 |Fz|^p_cp2 (000:14); zero at Fz = 0, where the power's derivative is singular.
  if (ValueOf(fz) == 0.0) {
    t.load_pow = T(0.0);
  } else if (near != nullptr) {
    t.load_pow = PowPositiveNear(fz, k.load_series, T(abs(near->input.fz)), near->load_pow);
  } else {
    t.load_pow = PowPositive(fz, p.contact_length_exponent);
  }
  const T contact_length = p.contact_length_coeff * t.load_pow;         // c_l (000:14)
  t.convection_area = t.tread_area - p.contact_width * contact_length;  // A_conv (000:12)
  // Share of the patch that does not slide, (000:19), unclamped as in the paper.
  const TyreThermalSmoothing& eps = p.smoothing;
  const T non_sliding = Magnitude(in.slip_angle, eps.angle_rad) / p.reference_slip_angle *
                            (p.non_sliding_fraction_high - p.non_sliding_fraction_low) +
                        p.non_sliding_fraction_low;
  t.adhesion_area = p.contact_width * non_sliding * contact_length;  // A_cp (000:18)
  t.patch_area = p.contact_width * contact_length;
  const T slip_sum = Magnitude(T(in.fx * in.slip_ratio), eps.force_N) +
                     Magnitude(T(in.fy * tan(in.slip_angle)), eps.force_N);
  t.q1 = p.p1 * speed * slip_sum;  // (000:9)
  t.sliding_power = speed * slip_sum;
  if (p.HasGasAndRim()) t.speed_factor = SpeedFactor(p, in.speed);
  t.q2 = speed * k.carcass_heating *
         (p.p2 * Magnitude(in.fx, eps.force_N) + p.p3 * Magnitude(in.fy, eps.force_N) +
          p.p4 * abs(in.fz));  // (000:10)
  t.length = k.length;
  if (ValueOf(speed) == 0.0) {
    t.speed_length_pow = T(0.0);
  } else if (near != nullptr) {
    t.speed_length_pow =
        PowPositiveNear(T(speed * t.length), k.speed_series, T(abs(near->input.speed) * t.length),
                        near->speed_length_pow);
  } else {
    t.speed_length_pow = PowPositive(T(speed * t.length), kReynoldsExponent);
  }
  // h_forc A_conv without the air properties (000:15).
  t.convection_factor = k.convection_scale * t.speed_length_pow * t.convection_area;
  t.track_conductance = p.track_conductance * t.adhesion_area;
  t.tread_to_carcass = k.tread_to_carcass;
  t.tread_radiation = p.emissivity * kStefanBoltzmann * (t.tread_area - t.adhesion_area);
  t.sidewall_radiation = k.sidewall_radiation;
  const T ambient2 = in.ambient_temp * in.ambient_temp;
  t.ambient_temp4 = ambient2 * ambient2;
  t.inv_tread_capacity = k.inv_tread_capacity;
  t.inv_carcass_capacity = k.inv_carcass_capacity;
  return t;
}

}  // namespace

template <Scalar T>
TyreInputTerms<T> CalcTyreInputTerms(const TyreThermalParams<T>& p, const TyreConstants<T>& k,
                                     const TyreCompound& compound, const TyreInput<T>& in,
                                     const TyreInputTerms<T>* near) {
  TyreInputTerms<T> t = CalcHeatInputTerms(p, k, in, near);
  // (000:23); no sliding power, no wear (the power's derivative is singular at 0).
  const T power_ratio = t.q1 / compound.wear_reference_power;
  if (ValueOf(t.q1) <= 0.0) {
    t.wear_power_factor = T(0.0);
  } else if (near != nullptr) {
    t.wear_power_factor =
        PowPositiveNear(power_ratio, k.wear_series, T(near->q1 / compound.wear_reference_power),
                        near->wear_power_factor);
  } else {
    t.wear_power_factor = PowPositive(power_ratio, p.wear_exponent);
  }
  t.wear_rate_factor = p.wear_coeff * t.wear_power_factor;
  return t;
}

template <Scalar T>
TyreInputTerms<T> CalcTyreInputTerms(const TyreThermalParams<T>& p, const TyreCompound& compound,
                                     const TyreInput<T>& in) {
  return CalcTyreInputTerms<T>(p, CalcTyreConstants(p), compound, in, nullptr);
}

namespace {

// The gas at a carcass and rim temperature with the speed-dependent conductances' S(u) given
// (CalcTyreGas).
template <Scalar T>
TyreGas<T> GasAt(const TyreThermalParams<T>& p, const T& carcass_temp, const T& rim_temp,
                 const T& s) {
  const T g_cg = p.carcass_gas_conductance * s;
  const T g_gr = p.gas_rim_conductance * s;
  const T g_gl = p.gas_liner_conductance * s;
  const T g_lr = p.liner_rim_conductance * s;
  TyreGas<T> gas;
  if (ValueOf(g_gl) == 0.0) {
    // G_cg (T_c - T_g) = G_gr (T_g - T_r)
    gas.gas_temp = (g_cg * carcass_temp + g_gr * rim_temp) / (g_cg + g_gr);
    gas.liner_temp = gas.gas_temp;
  } else {
    // The tyre's gas between the carcass and the liner, the liner's gas between the liner and the
    // rim: G_cg (T_c - T_g) = G_gl (T_g - T_l) + G_gr (T_g - T_r), G_gl (T_g - T_l) = G_lr (T_l -
    // T_r).
    const T a11 = g_cg + g_gl + g_gr, a22 = g_gl + g_lr;
    const T b1 = g_cg * carcass_temp + g_gr * rim_temp, b2 = g_lr * rim_temp;
    const T det = a11 * a22 - g_gl * g_gl;
    gas.gas_temp = (b1 * a22 + g_gl * b2) / det;
    gas.liner_temp = (a11 * b2 + g_gl * b1) / det;
  }
  // Constant volume: absolute pressure in proportion to the absolute temperature.
  gas.pressure = (p.cold_pressure + kAtmosphericPressure) * gas.gas_temp / p.cold_set_temp -
                 kAtmosphericPressure;
  gas.liner_pressure = ValueOf(g_gl) == 0.0
                           ? T(0.0)
                           : (p.cold_pressure + p.liner_pressure_offset + kAtmosphericPressure) *
                                     gas.liner_temp / p.cold_set_temp -
                                 kAtmosphericPressure;
  gas.carcass_to_gas = g_cg * (carcass_temp - gas.gas_temp);
  gas.rolling_resistance = CalcRollingResistance(p, carcass_temp, gas.pressure);
  return gas;
}

// The paper's seven flows (000:9-22).
template <Scalar T>
TyreHeatFlows<T> PaperHeatFlows(const TyreState<T>& x, const TyreInputTerms<T>& t) {
  const TyreInput<T>& in = t.input;
  const T film_temp = 0.5 * (x.tread_temp + in.ambient_temp);
  const T tread2 = x.tread_temp * x.tread_temp;
  const T carcass2 = x.carcass_temp * x.carcass_temp;
  TyreHeatFlows<T> q;
  q.q1 = t.q1;  // (000:9)
  q.q2 = t.q2;  // (000:10)
  q.q3 = t.convection_factor * AirConvectionFactor(film_temp) *
         (x.tread_temp - in.ambient_temp);                                // (000:11, 15)
  q.q4 = t.track_conductance * (x.tread_temp - in.track_temp);            // (000:17)
  q.q5 = t.tread_to_carcass * (x.carcass_temp - x.tread_temp);            // (000:20)
  q.q6 = t.tread_radiation * (tread2 * tread2 - t.ambient_temp4);         // (000:21)
  q.q7 = t.sidewall_radiation * (carcass2 * carcass2 - t.ambient_temp4);  // (000:22)
  return q;
}

// The gas-and-rim model's flows (docs/models.md): the paper's tread flows on a contact patch
// shortened by the hot pressure, the carcass heated by the power the car spends on the tyre, and
// the paths through the sidewalls, the gas and the rim.
template <Scalar T>
TyreHeatFlows<T> GasRimHeatFlows(const TyreThermalParams<T>& p, const TyreState<T>& x,
                                 const TyreInputTerms<T>& t, const T& brake_to_rim) {
  using std::abs;
  const TyreInput<T>& in = t.input;
  const TyreGas<T> gas = GasAt(p, x.carcass_temp, x.rim_temp, t.speed_factor);
  // The patch's length scales as (p / p_cold)^-n: a stiffer, hotter tyre has a shorter patch.
  const T pressure_ratio = gas.pressure / p.cold_pressure;
  const T patch_scale = PowPositive(T(ValueOf(pressure_ratio) > 0.1 ? pressure_ratio : T(0.1)),
                                    T(-p.contact_length_pressure_exponent));
  const T convection_area = t.tread_area - patch_scale * t.patch_area;  // A_conv (000:12)
  const T adhesion_area = patch_scale * t.adhesion_area;                // A_cp (000:18)
  const T film_temp = 0.5 * (x.tread_temp + in.ambient_temp);
  const T tread2 = x.tread_temp * x.tread_temp;
  const T carcass2 = x.carcass_temp * x.carcass_temp;
  const T& speed_factor = t.speed_factor;
  TyreHeatFlows<T> q;
  q.q1 = t.q1;  // (000:9)
  // Carcass hysteresis: a share of the sliding power the tread does not take, and all of the
  // rolling resistance's power (what the car pays for it).
  q.rolling_power = abs(in.speed) * gas.rolling_resistance * abs(in.fz);
  q.q2 = p.carcass_slip_share * (1.0 - p.p1) * t.sliding_power + q.rolling_power;
  q.q3 = 0.0239 / t.length * t.speed_length_pow * convection_area * AirConvectionFactor(film_temp) *
         (x.tread_temp - in.ambient_temp);                                      // (000:11, 15)
  q.q4 = p.track_conductance * adhesion_area * (x.tread_temp - in.track_temp);  // (000:17)
  q.q5 = t.tread_to_carcass * (x.carcass_temp - x.tread_temp);                  // (000:20)
  q.q6 = p.emissivity * kStefanBoltzmann * (t.tread_area - adhesion_area) *
         (tread2 * tread2 - t.ambient_temp4);                             // (000:21)
  q.q7 = t.sidewall_radiation * (carcass2 * carcass2 - t.ambient_temp4);  // (000:22)
  q.sidewall_convection =
      p.sidewall_air_conductance * speed_factor * (x.carcass_temp - in.ambient_temp);
  q.carcass_to_gas = gas.carcass_to_gas;
  q.rim_to_air = p.rim_air_conductance * speed_factor * (x.rim_temp - in.ambient_temp);
  q.brake_to_rim = brake_to_rim;
  return q;
}

}  // namespace

template <Scalar T>
TyreGas<T> CalcTyreGas(const TyreThermalParams<T>& p, const T& carcass_temp, const T& rim_temp,
                       const T& speed) {
  return GasAt(p, carcass_temp, rim_temp, SpeedFactor(p, speed));
}

template <Scalar T>
T CalcRollingResistance(const TyreThermalParams<T>& p, const T& carcass_temp, const T& pressure) {
  using std::exp;
  const T temp_factor = p.rolling_temp_floor + (1.0 - p.rolling_temp_floor) *
                                                   exp(-p.rolling_temp_coefficient *
                                                       (carcass_temp - p.rolling_reference_temp));
  // Below a tenth of the reference pressure the law is held (a flat tyre is outside it).
  const T ratio = pressure / p.rolling_reference_pressure;
  const T pressure_factor =
      PowPositive(T(ValueOf(ratio) > 0.1 ? ratio : T(0.1)), T(-p.rolling_pressure_exponent));
  return p.rolling_resistance * temp_factor * pressure_factor;
}

template <Scalar T>
TyreMechanicalPower<T> CalcTyreMechanicalPower(const TyreInput<T>& in,
                                               const T& rolling_coefficient) {
  using std::abs;
  using std::tan;
  const T speed = abs(in.speed);
  return {speed * (abs(T(in.fx * in.slip_ratio)) + abs(T(in.fy * tan(in.slip_angle)))),
          speed * rolling_coefficient * abs(in.fz)};
}

template <Scalar T>
TyreHeatFlows<T> CalcTyreHeatFlows(const TyreThermalParams<T>& p, const TyreState<T>& x,
                                   const TyreInputTerms<T>& t, const T& brake_to_rim) {
  if (p.HasGasAndRim()) return GasRimHeatFlows(p, x, t, brake_to_rim);
  return PaperHeatFlows(x, t);
}

template <Scalar T>
TyreHeatFlows<T> CalcTyreHeatFlows(const TyreThermalParams<T>& p, const TyreState<T>& x,
                                   const TyreInput<T>& in) {
  return CalcTyreHeatFlows(p, x, CalcHeatInputTerms<T>(p, CalcTyreConstants(p), in, nullptr));
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
                                 TyreHeatFlows<T>* flows, const T& brake_to_rim) {
  const TyreHeatFlows<T> q = CalcTyreHeatFlows(p, x, t, brake_to_rim);
  if (flows != nullptr) *flows = q;
  TyreState<T> dx;
  dx.tread_temp = (q.q1 - q.q3 - q.q4 + q.q5 - q.q6) * t.inv_tread_capacity;  // (000:7)
  if (p.HasGasAndRim()) {
    dx.carcass_temp =
        (q.q2 - q.q5 - q.q7 - q.sidewall_convection - q.carcass_to_gas) * t.inv_carcass_capacity;
    dx.rim_temp =
        (q.carcass_to_gas + q.brake_to_rim - q.rim_to_air) / (p.rim_mass * p.rim_heat_capacity);
  } else {
    dx.carcass_temp = (q.q2 - q.q5 - q.q7) * t.inv_carcass_capacity;  // (000:8)
  }
  dx.wear = t.wear_rate_factor * compound.wear_rate.Evaluate(x.tread_temp);  // (000:23)
  return dx;
}

template <Scalar T>
TyreState<T> CalcTyreDerivatives(const TyreThermalParams<T>& p, const TyreCompound& compound,
                                 const TyreState<T>& x, const TyreInput<T>& in,
                                 TyreHeatFlows<T>* flows) {
  return CalcTyreDerivatives(p, compound, x, CalcTyreInputTerms(p, compound, in), flows);
}

#define HOTLAP_INSTANTIATE_TYRE_THERMAL(T)                                                         \
  template struct BinomialSeries<T>;                                                               \
  template T CalcContactLength<T>(const TyreThermalParams<T>&, const T&);                          \
  template T CalcForcedConvectionCoefficient<T>(const TyreThermalParams<T>&, const T&, const T&,   \
                                                const T&);                                         \
  template TyreConstants<T> CalcTyreConstants<T>(const TyreThermalParams<T>&);                     \
  template TyreInputTerms<T> CalcTyreInputTerms<T>(const TyreThermalParams<T>&,                    \
                                                   const TyreCompound&, const TyreInput<T>&);      \
  template TyreInputTerms<T> CalcTyreInputTerms<T>(const TyreThermalParams<T>&,                    \
                                                   const TyreConstants<T>&, const TyreCompound&,   \
                                                   const TyreInput<T>&, const TyreInputTerms<T>*); \
  template TyreHeatFlows<T> CalcTyreHeatFlows<T>(const TyreThermalParams<T>&, const TyreState<T>&, \
                                                 const TyreInput<T>&);                             \
  template TyreHeatFlows<T> CalcTyreHeatFlows<T>(const TyreThermalParams<T>&, const TyreState<T>&, \
                                                 const TyreInputTerms<T>&, const T&);              \
  template TyreGas<T> CalcTyreGas<T>(const TyreThermalParams<T>&, const T&, const T&, const T&);   \
  template T CalcRollingResistance<T>(const TyreThermalParams<T>&, const T&, const T&);            \
  template TyreMechanicalPower<T> CalcTyreMechanicalPower<T>(const TyreInput<T>&, const T&);       \
  template T CalcWearRate<T>(const TyreThermalParams<T>&, const TyreCompound&, const T&,           \
                             const T&);                                                            \
  template TyreState<T> CalcTyreDerivatives<T>(const TyreThermalParams<T>&, const TyreCompound&,   \
                                               const TyreState<T>&, const TyreInput<T>&,           \
                                               TyreHeatFlows<T>*);                                 \
  template TyreState<T> CalcTyreDerivatives<T>(const TyreThermalParams<T>&, const TyreCompound&,   \
                                               const TyreState<T>&, const TyreInputTerms<T>&,      \
                                               TyreHeatFlows<T>*, const T&);
HOTLAP_FOR_EACH_SCALAR(HOTLAP_INSTANTIATE_TYRE_THERMAL)
// The optimal-control lap's elements: a tyre's rolling resistance (5 inputs), its thermal model
// (10), a tyre with its rim and its brake (15).
HOTLAP_INSTANTIATE_TYRE_THERMAL(::hotlap::SecondOrder<5>)
HOTLAP_INSTANTIATE_TYRE_THERMAL(::hotlap::SecondOrder<10>)
HOTLAP_INSTANTIATE_TYRE_THERMAL(::hotlap::Jet10)
HOTLAP_INSTANTIATE_TYRE_THERMAL(::hotlap::SecondOrder<15>)
HOTLAP_INSTANTIATE_TYRE_THERMAL(::hotlap::Jet15)

}  // namespace hotlap::tyre
