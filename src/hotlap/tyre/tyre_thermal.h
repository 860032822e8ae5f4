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
  T tread_mass{};                  ///< m_t, kg
  T carcass_mass{};                ///< m_c, kg
  T tread_heat_capacity{};         ///< c_t, J/(kg K)
  T carcass_heat_capacity{};       ///< c_c, J/(kg K)
  T track_conductance{};           ///< h_tt, W/(m^2 K) (000:17)
  T contact_width{};               ///< c_w, m
  T reference_slip_angle{};        ///< alpha_c, rad (000:19)
  T non_sliding_fraction_low{};    ///< c_s1 (000:19)
  T non_sliding_fraction_high{};   ///< c_s2 (000:19)
  T unloaded_radius{};             ///< r0, m (000:22)
  T rim_radius{};                  ///< r_rim, m (000:22)
  T diameter{};                    ///< D, m, as printed (see the file comment)
  T width{};                       ///< W, m
  T emissivity{};                  ///< eps of rubber, 1
  TyreThermalSmoothing smoothing;  ///< exact model unless an optimiser sets it

  template <class Self>
  static auto FieldsOf(Self& s) {
    return std::tie(s.p1, s.p2, s.p3, s.p4, s.p5, s.wear_coeff, s.wear_exponent,
                    s.contact_length_coeff, s.contact_length_exponent, s.tread_mass, s.carcass_mass,
                    s.tread_heat_capacity, s.carcass_heat_capacity, s.track_conductance,
                    s.contact_width, s.reference_slip_angle, s.non_sliding_fraction_low,
                    s.non_sliding_fraction_high, s.unloaded_radius, s.rim_radius, s.diameter,
                    s.width, s.emissivity);
  }
  /// The same parameters in another scalar type (derivative parts start at zero).
  template <Scalar U>
  TyreThermalParams<U> Cast() const {
    TyreThermalParams<U> out;
    CastFields(*this, out);
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
/// its time derivative (K/s, mm/s).
template <Scalar T>
struct TyreState {
  T tread_temp{};
  T carcass_temp{};
  T wear{};

  friend TyreState operator+(const TyreState& a, const TyreState& b) {
    return {a.tread_temp + b.tread_temp, a.carcass_temp + b.carcass_temp, a.wear + b.wear};
  }
  friend TyreState operator*(double k, const TyreState& a) {
    return {k * a.tread_temp, k * a.carcass_temp, k * a.wear};
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
  T tread_area{};         ///< A_tot = pi D W, m^2 (000:13)
  T convection_area{};    ///< A_conv, m^2 (000:12)
  T adhesion_area{};      ///< A_cp, m^2 (000:18)
  T q1{};                 ///< W (000:9)
  T q2{};                 ///< W (000:10)
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
/// All seven heat flows from precomputed input terms.
template <Scalar T>
TyreHeatFlows<T> CalcTyreHeatFlows(const TyreThermalParams<T>& params, const TyreState<T>& state,
                                   const TyreInputTerms<T>& terms);

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
/// As above, from precomputed input terms.
template <Scalar T>
TyreState<T> CalcTyreDerivatives(const TyreThermalParams<T>& params, const TyreCompound& compound,
                                 const TyreState<T>& state, const TyreInputTerms<T>& terms,
                                 TyreHeatFlows<T>* flows = nullptr);

}  // namespace hotlap::tyre
