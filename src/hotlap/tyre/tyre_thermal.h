#pragma once
/// @file
/// The two-mass tyre thermal model and wear law of the NASCAR paper (000:7-23; spec sections 2-3).
///
/// How to use: load TyreThermalParams<double> and a TyreCompound from YAML (tyre_params_io.h),
/// then call CalcTyreDerivatives at every integration stage. Every function is templated on the
/// scalar and instantiated for double and the ceres::Jet sizes in scalar.h, so the same code
/// serves simulation and fitting.
///
/// Pitfalls: the paper's `D = 0.4572 m` is the rim diameter, not the tyre's (2 r0 = 0.7226 m), but
/// the fitted p-values were identified with it, so it is used as printed. `c_s` is not clamped
/// (as in the paper), so above about 11 deg of slip the "non-sliding" area exceeds the patch.

#include <array>
#include <tuple>

#include "hotlap/common/field_cast.h"
#include "hotlap/common/scalar.h"
#include "hotlap/tyre/compound.h"

namespace hotlap::tyre {

/// Smooth stand-ins for the model's |x| where an optimiser needs second derivatives: |x| becomes
/// sqrt(x^2 + eps^2) - eps (exact at 0, within eps of |x| everywhere). Zero (the default, and what
/// every file loads) is the exact model; only the optimal-control lap sets them, and it reports the
/// difference by replaying its solution through the exact model.
struct TyreThermalSmoothing {
  double force_N = 0.0;    ///< eps for |Fx kappa|, |Fy tan(alpha)|, |Fx| and |Fy|, N
  double angle_rad = 0.0;  ///< eps for |alpha| in the non-sliding share (000:19), rad
};

/// Which equations a tyre runs (the tyre file's `thermal_model`, docs/models.md).
enum class TyreThermalModel {
  /// The paper's two masses (000:7-22) as published: the carcass heated by (000:10), cooled only
  /// through the tread and by sidewall radiation. Fitted on one lap; over a run its carcass has
  /// no exit for its heat.
  kPaper,
  /// The same two masses with the inflation gas (quasi-static, with an inner liner where one is
  /// run), the rim (heated by the gas and the brake, cooled by the air) and the sidewalls'
  /// convection; the carcass heated only by power the car spends on the tyre: a share of the
  /// sliding power and the rolling resistance, whose coefficient falls with carcass temperature
  /// and inflation pressure (000, beside equation 10: "a nonlinear function of the temperature and
  /// the inflation-induced initial stress"). The hot pressure shortens the contact patch.
  kGasRim,
};

/// Reference speed of the speed-dependent conductances of the gas-and-rim model, m/s: each is
/// G (still + (1 - still) (|u| / 50 m/s)^0.8), the turbulent forced-convection law.
inline constexpr double kConductanceReferenceSpeed = 50.0;
/// Standard atmosphere, Pa: gauge pressures are above it.
inline constexpr double kAtmosphericPressure = 101325.0;

/// Parameters of one tyre; SI units (angles in rad).
template <Scalar T>
struct TyreThermalParams {
  // Fitted per corner (000 Table 4).
  T p1{};             ///< share of the sliding power that heats the tread, 1 (000:9)
  T p2{};             ///< carcass hysteresis per |Fx|, J/(kg N) (000:10)
  T p3{};             ///< carcass hysteresis per |Fy|, J/(kg N) (000:10)
  T p4{};             ///< carcass hysteresis per |Fz|, J/(kg N) (000:10)
  T p5{};             ///< tread-carcass conductance per tread area, W/(m^2 K) (000:20)
  T wear_coeff{};     ///< wp1, mm/s (000:23)
  T wear_exponent{};  ///< wp2, 1 (000:23)
  // Contact length c_l = p_cp1 |Fz|^p_cp2 (000:14, Table 2), Fz in N, c_l in m.
  T contact_length_coeff{};     ///< p_cp1
  T contact_length_exponent{};  ///< p_cp2
  // Constants (000 Table 3).
  T tread_mass{};                 ///< m_t, kg
  T carcass_mass{};               ///< m_c, kg
  T tread_heat_capacity{};        ///< c_t, J/(kg K)
  T carcass_heat_capacity{};      ///< c_c, J/(kg K)
  T track_conductance{};          ///< h_tt, W/(m^2 K) (000:17)
  T contact_width{};              ///< c_w, m
  T reference_slip_angle{};       ///< alpha_c, rad (000:19)
  T non_sliding_fraction_low{};   ///< c_s1 (000:19)
  T non_sliding_fraction_high{};  ///< c_s2 (000:19)
  T unloaded_radius{};            ///< r0, m (000:22)
  T rim_radius{};                 ///< r_rim, m (000:22)
  T diameter{};                   ///< D, m, as printed (see the file comment)
  T width{};                      ///< W, m
  T emissivity{};                 ///< eps of rubber, 1
  // The gas-and-rim model (TyreThermalModel::kGasRim); unused by the paper's.
  T carcass_slip_share{};  ///< share of the sliding power not in the tread that heats the carcass,
                           ///< 1
  T rolling_resistance{};  ///< c_rr at the reference carcass temperature and pressure, 1
  T rolling_reference_temp{};            ///< K
  T rolling_reference_pressure{};        ///< gauge, Pa
  T rolling_temp_coefficient{};          ///< k_T of exp(-k_T (T_c - T_ref)), 1/K
  T rolling_temp_floor{};                ///< share of c_rr that does not fall with temperature, 1
  T rolling_pressure_exponent{};         ///< n of (p / p_ref)^-n, 1
  T contact_length_pressure_exponent{};  ///< c_l times (p / p_cold)^-n, 1
  T cold_set_temp{};                     ///< gas temperature at which the cold pressure is set, K
  T cold_pressure{};                     ///< gauge, Pa: the car's tyre_forces.<c>.pressure_kPa
  T liner_pressure_offset{};             ///< the liner's cold pressure above the tyre's, Pa
  T carcass_gas_conductance{};           ///< carcass -> gas at 50 m/s, W/K
  T gas_rim_conductance{};               ///< gas -> rim at 50 m/s, W/K
  T gas_liner_conductance{};  ///< gas -> liner gas through the liner at 50 m/s, W/K (0: no liner)
  T liner_rim_conductance{};  ///< liner gas -> rim at 50 m/s, W/K
  T sidewall_air_conductance{};  ///< carcass (sidewalls) -> air at 50 m/s, W/K
  T rim_air_conductance{};       ///< rim -> air at 50 m/s, W/K
  T still_air_fraction{};        ///< share of those conductances left at standstill, 1
  T rim_mass{};                  ///< kg
  T rim_heat_capacity{};         ///< J/(kg K)
  TyreThermalModel model = TyreThermalModel::kPaper;
  TyreThermalSmoothing smoothing;  ///< exact model unless an optimiser sets it

  bool HasGasAndRim() const { return model == TyreThermalModel::kGasRim; }

  template <class Self>
  static auto FieldsOf(Self& s) {
    return std::tie(s.p1, s.p2, s.p3, s.p4, s.p5, s.wear_coeff, s.wear_exponent,
                    s.contact_length_coeff, s.contact_length_exponent, s.tread_mass, s.carcass_mass,
                    s.tread_heat_capacity, s.carcass_heat_capacity, s.track_conductance,
                    s.contact_width, s.reference_slip_angle, s.non_sliding_fraction_low,
                    s.non_sliding_fraction_high, s.unloaded_radius, s.rim_radius, s.diameter,
                    s.width, s.emissivity, s.carcass_slip_share, s.rolling_resistance,
                    s.rolling_reference_temp, s.rolling_reference_pressure,
                    s.rolling_temp_coefficient, s.rolling_temp_floor, s.rolling_pressure_exponent,
                    s.contact_length_pressure_exponent, s.cold_set_temp, s.cold_pressure,
                    s.liner_pressure_offset, s.carcass_gas_conductance, s.gas_rim_conductance,
                    s.gas_liner_conductance, s.liner_rim_conductance, s.sidewall_air_conductance,
                    s.rim_air_conductance, s.still_air_fraction, s.rim_mass, s.rim_heat_capacity);
  }
  /// The same parameters in another scalar type (derivative parts start at zero).
  template <Scalar U>
  TyreThermalParams<U> Cast() const {
    TyreThermalParams<U> out;
    CastFields(*this, out);
    out.model = model;
    out.smoothing = smoothing;
    return out;
  }
};

/// What one corner's tyre sees, SI: speeds m/s, forces N (ISO axes), angles rad, temperatures K.
template <Scalar T>
struct TyreInput {
  T speed{};         ///< u_n, longitudinal speed of the wheel centre, m/s (|u| is used)
  T fx{};            ///< N
  T fy{};            ///< N
  T fz{};            ///< N (|Fz| is used)
  T slip_angle{};    ///< alpha, rad (only |alpha| matters)
  T slip_ratio{};    ///< kappa, negative when braking
  T ambient_temp{};  ///< T_amb, K
  T track_temp{};    ///< T_tra, K
};

/// The state of one tyre: temperatures in K, wear (tread depth lost) in mm. The same struct holds
/// its time derivative (K/s, mm/s). The rim is a state of the gas-and-rim model only (the paper's
/// leaves it as it is).
template <Scalar T>
struct TyreState {
  T tread_temp{};
  T carcass_temp{};
  T wear{};
  T rim_temp{};

  friend TyreState operator+(const TyreState& a, const TyreState& b) {
    return {a.tread_temp + b.tread_temp, a.carcass_temp + b.carcass_temp, a.wear + b.wear,
            a.rim_temp + b.rim_temp};
  }
  friend TyreState operator*(double k, const TyreState& a) {
    return {k * a.tread_temp, k * a.carcass_temp, k * a.wear, k * a.rim_temp};
  }
};

/// The seven heat flows of (000:7-8), W, signed as they enter those equations:
/// m_t c_t dT_t/dt = q1 - q3 - q4 + q5 - q6,  m_c c_c dT_c/dt = q2 - q5 - q7.
template <Scalar T>
struct TyreHeatFlows {
  T q1{};  ///< sliding friction heating of the tread (000:9)
  T q2{};  ///< carcass hysteresis heating (000:10)
  T q3{};  ///< forced convection from the tread (000:11)
  T q4{};  ///< conduction from the tread to the track (000:17)
  T q5{};  ///< conduction from the carcass to the tread (000:20)
  T q6{};  ///< radiation from the tread (000:21)
  T q7{};  ///< radiation from the sidewalls (000:22)
  // The gas-and-rim model's further flows (zero in the paper's).
  T sidewall_convection{};  ///< carcass -> air by the sidewalls
  T carcass_to_gas{};       ///< carcass -> gas, = gas (and liner gas) -> rim (quasi-static gas)
  T rim_to_air{};           ///< rim -> air
  T brake_to_rim{};         ///< brake -> rim (hub conduction and the disc's radiation), an input
  T rolling_power{};        ///< u c_rr |Fz|: the rolling resistance's power, all of it in q2
};

/// The inflation gas of the gas-and-rim model at one instant (quasi-static: its heat capacity,
/// about 0.1 kJ/K, settles in seconds against the carcass's 17.6 kJ/K).
template <Scalar T>
struct TyreGas {
  T gas_temp{};            ///< K
  T liner_temp{};          ///< the liner's gas, K (the gas's own where there is no liner)
  T pressure{};            ///< hot gauge pressure, Pa (constant volume from the cold set)
  T liner_pressure{};      ///< the liner's hot gauge pressure, Pa (0 where there is no liner)
  T carcass_to_gas{};      ///< W, = heat into the rim from the gases
  T rolling_resistance{};  ///< c_rr at this carcass temperature and pressure, 1
};

/// What the car spends on one tyre, W: the sliding power u (|Fx kappa| + |Fy tan(alpha)|) (the
/// force times the slip velocity, longitudinal and lateral) and the rolling resistance's power.
template <Scalar T>
struct TyreMechanicalPower {
  T sliding{};
  T rolling{};
};

/// Coefficients C(a, n), n = 0..8, of the binomial series (1 + r)^a = sum C(a, n) r^n.
template <Scalar T>
struct BinomialSeries {
  static constexpr int kTerms = 9;
  T exponent{};
  std::array<T, kTerms> coefficients{};
  static BinomialSeries For(const T& exponent);
};

/// The parts of the model that depend only on the parameters, computed once per integration.
template <Scalar T>
struct TyreConstants {
  T tread_area{};            ///< A_tot = pi D W, m^2 (000:13)
  T length{};                ///< L of (000:16), m
  T convection_scale{};      ///< 0.0239 / L, 1/m (000:15)
  T tread_to_carcass{};      ///< p5 A_tot, W/K (000:20)
  T sidewall_radiation{};    ///< eps sigma 2 pi (r0^2 - r_rim^2), W/K^4 (000:22)
  T inv_tread_capacity{};    ///< 1 / (m_t c_t), K/J
  T inv_carcass_capacity{};  ///< 1 / (m_c c_c), K/J
  T carcass_heating{};       ///< m_c / (pi D), kg/m (000:10)
  // Series of the three powers of the model, for CalcTyreInputTerms' `near`.
  BinomialSeries<T> load_series;   ///< exponent p_cp2 (000:14)
  BinomialSeries<T> speed_series;  ///< exponent 0.805 (000:15)
  BinomialSeries<T> wear_series;   ///< exponent wp2 (000:23)
};

/// The parts of the model that depend only on the parameters and the inputs, not on the state.
/// An integrator computes them once per distinct input time (RK4's two middle stages share one
/// set, and a step's last stage is the next step's first); the results are identical to
/// evaluating the model from the raw input.
template <Scalar T>
struct TyreInputTerms {
  TyreInput<T> input;
  T tread_area{};       ///< A_tot = pi D W, m^2 (000:13)
  T convection_area{};  ///< A_conv, m^2 (000:12)
  T adhesion_area{};    ///< A_cp, m^2 (000:18)
  T patch_area{};       ///< c_w c_l, m^2 (000:12)
  T sliding_power{};    ///< u (|Fx kappa| + |Fy tan(alpha)|), W (000:9 without p1)
  T speed_factor{};  ///< the gas-and-rim model's S(u) of its speed-dependent conductances (else 0)
  T q1{};            ///< W (000:9)
  T q2{};            ///< W (000:10)
  T wear_power_factor{};  ///< (Q1 / Q_ref)^wp2 (000:23)
  T load_pow{};           ///< |Fz|^p_cp2 of (000:14), N^p_cp2
  T speed_length_pow{};   ///< (|u| L)^0.805 of (000:15), (m^2/s)^0.805
  T length{};             ///< L of (000:16), m
  // Products of the above with parameters, so that the state-dependent part is multiplications.
  T convection_factor{};     ///< 0.0239 (|u| L)^0.805 A_conv / L: q3 = it k nu^-0.805 (T_t - T_amb)
  T track_conductance{};     ///< h_tt A_cp, W/K (000:17)
  T tread_to_carcass{};      ///< p5 A_tot, W/K (000:20)
  T tread_radiation{};       ///< eps sigma (A_tot - A_cp), W/K^4 (000:21)
  T sidewall_radiation{};    ///< eps sigma 2 pi (r0^2 - r_rim^2), W/K^4 (000:22)
  T ambient_temp4{};         ///< T_amb^4, K^4
  T inv_tread_capacity{};    ///< 1 / (m_t c_t), K/J
  T inv_carcass_capacity{};  ///< 1 / (m_c c_c), K/J
  T wear_rate_factor{};      ///< wp1 (Q1 / Q_ref)^wp2, mm/s (000:23)
};

/// Contact patch length c_l = p_cp1 |Fz|^p_cp2, m (000:14). Zero for Fz = 0.
template <Scalar T>
T CalcContactLength(const TyreThermalParams<T>& params, const T& fz);

/// Forced-convection coefficient h_forc, W/(m^2 K) (000:15-16), with air properties at the
/// film temperature (T_t + T_amb)/2. Zero at zero speed.
template <Scalar T>
T CalcForcedConvectionCoefficient(const TyreThermalParams<T>& params, const T& speed,
                                  const T& tread_temp, const T& ambient_temp);

/// The parameter-only terms.
template <Scalar T>
TyreConstants<T> CalcTyreConstants(const TyreThermalParams<T>& params);

/// The state-independent terms for one input.
template <Scalar T>
TyreInputTerms<T> CalcTyreInputTerms(const TyreThermalParams<T>& params,
                                     const TyreCompound& compound, const TyreInput<T>& input);
/// The same with the parameter-only terms given (they must be those of `params`). If `near` is
/// given (the terms of a nearby input, such as the previous integrator stage's), the three powers
/// are taken from its powers by a series when the bases differ by at most 2% (same value within
/// 1e-15 relative, several times cheaper than exp and log).
template <Scalar T>
TyreInputTerms<T> CalcTyreInputTerms(const TyreThermalParams<T>& params,
                                     const TyreConstants<T>& constants,
                                     const TyreCompound& compound, const TyreInput<T>& input,
                                     const TyreInputTerms<T>* near = nullptr);

/// All seven heat flows (000:9-22).
template <Scalar T>
TyreHeatFlows<T> CalcTyreHeatFlows(const TyreThermalParams<T>& params, const TyreState<T>& state,
                                   const TyreInput<T>& input);
/// All seven heat flows from precomputed input terms; with the gas-and-rim model also its further
/// flows, `brake_to_rim` (W) the heat the brake gives the rim.
template <Scalar T>
TyreHeatFlows<T> CalcTyreHeatFlows(const TyreThermalParams<T>& params, const TyreState<T>& state,
                                   const TyreInputTerms<T>& terms, const T& brake_to_rim = T(0.0));

/// The gas-and-rim model's gas at carcass temperature `carcass_temp`, rim `rim_temp` and speed
/// `speed` (quasi-static balance of the gas, and of the liner's gas where there is a liner).
template <Scalar T>
TyreGas<T> CalcTyreGas(const TyreThermalParams<T>& params, const T& carcass_temp, const T& rim_temp,
                       const T& speed);

/// Rolling-resistance coefficient of the gas-and-rim model at a carcass temperature and hot gauge
/// pressure: c_rr (f + (1 - f) exp(-k_T (T_c - T_ref))) (p / p_ref)^-n.
template <Scalar T>
T CalcRollingResistance(const TyreThermalParams<T>& params, const T& carcass_temp,
                        const T& pressure);

/// What the car spends on the tyre for an input, W; the rolling part with `rolling_coefficient`
/// (the gas-and-rim model's own c_rr, or the vehicle model's for the paper's).
template <Scalar T>
TyreMechanicalPower<T> CalcTyreMechanicalPower(const TyreInput<T>& input,
                                               const T& rolling_coefficient);

/// Wear rate, mm/s: wp1 * w(T_t) * (Q1 / Q_ref)^wp2 (000:23).
template <Scalar T>
T CalcWearRate(const TyreThermalParams<T>& params, const TyreCompound& compound,
               const T& tread_temp, const T& q1);

/// Time derivative of the tyre state (000:7-8, 000:23). If `flows` is given, the heat flows used
/// are written there.
template <Scalar T>
TyreState<T> CalcTyreDerivatives(const TyreThermalParams<T>& params, const TyreCompound& compound,
                                 const TyreState<T>& state, const TyreInput<T>& input,
                                 TyreHeatFlows<T>* flows = nullptr);
/// As above, from precomputed input terms; `brake_to_rim` as in CalcTyreHeatFlows.
template <Scalar T>
TyreState<T> CalcTyreDerivatives(const TyreThermalParams<T>& params, const TyreCompound& compound,
                                 const TyreState<T>& state, const TyreInputTerms<T>& terms,
                                 TyreHeatFlows<T>* flows = nullptr, const T& brake_to_rim = T(0.0));

}  // namespace hotlap::tyre
