#pragma once
/// @file
/// The two-mass brake disc / calliper thermal model of the NASCAR paper (000:24-34; spec
/// section 5), one instance per corner.
///
/// The convective conductances hA(u, T) = z' P z, z = [1, u/(100 m/s), (T - 273.15 K)/(1000 K)],
/// are stored and fitted through the lower-triangular Cholesky factor L of P = L L', so they are
/// sums of squares and never negative for any speed or temperature (the second law holds without
/// inequality constraints). The braking power uses the exact max(-Fx, 0) of (000:26).

#include <tuple>

#include "hotlap/common/field_cast.h"
#include "hotlap/common/scalar.h"

namespace hotlap::brake {

/// Lower-triangular Cholesky factor L of the 3x3 matrix P of hA = z' P z, entries in sqrt(W/K).
template <Scalar T>
struct ConvectionPolynomial {
  T l11{}, l21{}, l22{}, l31{}, l32{}, l33{};

  /// hA(u, T) in W/K: the squared norm of L' z (spec section 5).
  T Conductance(const T& speed, const T& temp) const;
  /// The speed-dependent parts of L' z: y1 = a + l31 z3, y2 = b + l32 z3 with a = l11 + l21 z2,
  /// b = l22 z2, z2 = |u| / (100 m/s). Computed once per input by an integrator.
  struct AtSpeed {
    T a{}, b{};
  };
  AtSpeed ForSpeed(const T& speed) const;
  /// hA at temperature `temp` for a speed given by ForSpeed, W/K.
  T Conductance(const AtSpeed& at_speed, const T& temp) const;

  template <class Self>
  static auto FieldsOf(Self& s) {
    return std::tie(s.l11, s.l21, s.l22, s.l31, s.l32, s.l33);
  }
};

/// Which disc a brake runs (the brake file's `disc_model`, docs/models.md).
enum class DiscModel {
  /// The paper's lumped disc (000:24): only its surface layer, xi m_d, with no conduction into the
  /// rest of the disc.
  kLumped,
  /// The surface layer on the disc's bulk ((1 - xi) m_d), which soaks heat from it, is cooled by
  /// the vanes' air, conducts heat through the hub into the rim; a share of the surface's
  /// radiation falls on the rim. The paper's lumped disc is the case without a bulk.
  kSurfaceBulk,
};

/// Parameters of one corner's brake, SI.
template <Scalar T>
struct BrakeThermalParams {
  T heat_partition{};           ///< gamma: share of braking power into the disc (000:24)
  T mass_participation{};       ///< xi: share of the disc mass at the surface temperature (000:24)
  T disc_mass{};                ///< m_d, kg
  T disc_heat_capacity{};       ///< c_d, J/(kg K)
  T calliper_mass{};            ///< m_k, kg (calliper and pads)
  T calliper_heat_capacity{};   ///< c_k, J/(kg K)
  T pad_conductivity{};         ///< k_p, W/(m K) (000:27)
  T pad_area{};                 ///< A_pad, m^2 (000:27)
  T pad_thickness{};            ///< l_pad, m (000:27)
  T disc_emissivity{};          ///< eps_d (000:28)
  T calliper_emissivity{};      ///< eps_k (000:29)
  T disc_radiating_area{};      ///< A_disc, m^2 (000:28)
  T calliper_radiating_area{};  ///< A_cal, m^2 (000:29)
  ConvectionPolynomial<T> disc_convection;      ///< hA_d(u, T_d) (000:30, 32)
  ConvectionPolynomial<T> calliper_convection;  ///< hA_k(u, T_k) (000:31, 33)
  // The surface-and-bulk disc (DiscModel::kSurfaceBulk); unused by the lumped disc.
  T bulk_conductance{};         ///< surface layer -> bulk, W/K
  T bulk_convection{};          ///< bulk -> cooling air through the vanes at 50 m/s, W/K
  T bulk_still_air_fraction{};  ///< share of bulk_convection left at standstill, 1
  T hub_conductance{};          ///< bulk -> rim through the hat and hub, W/K
  T rim_view_fraction{};        ///< share of the surface's radiation that falls on the rim, 1
  DiscModel disc_model = DiscModel::kLumped;

  bool HasBulk() const { return disc_model == DiscModel::kSurfaceBulk; }

  template <class Self>
  static auto FieldsOf(Self& s) {
    return std::tuple_cat(
        std::tie(s.heat_partition, s.mass_participation, s.disc_mass, s.disc_heat_capacity,
                 s.calliper_mass, s.calliper_heat_capacity, s.pad_conductivity, s.pad_area,
                 s.pad_thickness, s.disc_emissivity, s.calliper_emissivity, s.disc_radiating_area,
                 s.calliper_radiating_area, s.bulk_conductance, s.bulk_convection,
                 s.bulk_still_air_fraction, s.hub_conductance, s.rim_view_fraction),
        decltype(s.disc_convection)::FieldsOf(s.disc_convection),
        decltype(s.calliper_convection)::FieldsOf(s.calliper_convection));
  }
  template <Scalar U>
  BrakeThermalParams<U> Cast() const {
    BrakeThermalParams<U> out;
    CastFields(*this, out);
    out.disc_model = disc_model;
    return out;
  }
};

/// What one corner's brake sees: speed m/s (|u| used), tyre Fx N (negative braking),
/// cooling-air temperature T_0 in K.
template <Scalar T>
struct BrakeInput {
  T speed{};
  T fx{};
  T cooling_air_temp{};
};

/// Disc surface, calliper and (surface-and-bulk disc only) disc bulk temperatures, K; the same
/// struct holds their derivatives (K/s).
template <Scalar T>
struct BrakeState {
  T disc_temp{};
  T calliper_temp{};
  T bulk_temp{};

  friend BrakeState operator+(const BrakeState& a, const BrakeState& b) {
    return {a.disc_temp + b.disc_temp, a.calliper_temp + b.calliper_temp,
            a.bulk_temp + b.bulk_temp};
  }
  friend BrakeState operator*(double k, const BrakeState& a) {
    return {k * a.disc_temp, k * a.calliper_temp, k * a.bulk_temp};
  }
};

/// The heat flows of (000:24-25), W, signed as they enter them:
/// xi m_d c_d dT_d/dt = gamma q1 - q2 - q3 - q4,  m_k c_k dT_k/dt = (1-gamma) q1 + q2 - q5 - q6.
template <Scalar T>
struct BrakeHeatFlows {
  T q1{};  ///< braking power u max(-Fx, 0) (000:26)
  T q2{};  ///< conduction disc -> pads/calliper (000:27)
  T q3{};  ///< disc radiation (000:28)
  T q4{};  ///< disc convection (000:30)
  T q5{};  ///< calliper radiation (000:29)
  T q6{};  ///< calliper convection (000:31)
  // The surface-and-bulk disc's further flows (zero for the lumped disc); q3 is then the
  // radiation to the air alone.
  T to_bulk{};           ///< surface -> bulk
  T bulk_convection{};   ///< bulk -> air through the vanes
  T hub_to_rim{};        ///< bulk -> rim through the hub
  T radiation_to_rim{};  ///< surface -> rim by radiation

  /// The heat the brake gives the rim, W.
  T ToRim() const { return hub_to_rim + radiation_to_rim; }
};

/// The parts of the model that depend only on the parameters, computed once per integration.
template <Scalar T>
struct BrakeConstants {
  T pad_conductance{};        ///< 2 k_p A_pad / l_pad, W/K (000:27)
  T disc_radiation{};         ///< eps_d sigma A_disc, W/K^4 (000:28)
  T calliper_radiation{};     ///< eps_k sigma A_cal, W/K^4 (000:29)
  T inv_disc_capacity{};      ///< 1 / (xi m_d c_d), K/J (000:24)
  T inv_calliper_capacity{};  ///< 1 / (m_k c_k), K/J (000:25)
};

/// The parts of the model that depend only on the parameters and the input, computed once per
/// distinct input time by an integrator (as tyre::TyreInputTerms); identical results to the raw
/// input up to rounding.
template <Scalar T>
struct BrakeInputTerms {
  BrakeInput<T> input;
  T power{};                                                    ///< q1 (000:26), W
  typename ConvectionPolynomial<T>::AtSpeed disc_at_speed;      ///< for hA_d (000:30)
  typename ConvectionPolynomial<T>::AtSpeed calliper_at_speed;  ///< for hA_k (000:31)
  T cooling_air_temp4{};                                        ///< T_0^4, K^4
  T vane_factor{};  ///< a bulk disc's vane cooling at this speed over its 50 m/s value (else 0)
  BrakeConstants<T> constants;
};

/// Braking power at one corner, W: |u| max(-Fx, 0) (000:26), exact (non-smooth) form.
template <Scalar T>
T CalcBrakePower(const T& speed, const T& fx);

/// The braking force, N (<= 0), whose CalcBrakePower at `speed` is a logged braking `power`, W:
/// how a log's `brake_power_<corner>` column becomes the brake model's input where it differs
/// from the tyre's own force (the rear discs of a spool share the axle's torque, so each takes
/// half the axle's braking power whatever each tyre's Fx). Below 0.1 m/s, where a power says
/// nothing about a force, the tyre's own min(fx, 0).
double BrakeFxFromPower(double speed, double power, double fx);

/// The parameter-only terms.
template <Scalar T>
BrakeConstants<T> CalcBrakeConstants(const BrakeThermalParams<T>& params);

/// The state-independent terms for one input.
template <Scalar T>
BrakeInputTerms<T> CalcBrakeInputTerms(const BrakeThermalParams<T>& params,
                                       const BrakeInput<T>& input);
/// The same with the parameter-only terms given (they must be those of the parameters).
template <Scalar T>
BrakeInputTerms<T> CalcBrakeInputTerms(const BrakeThermalParams<T>& params,
                                       const BrakeConstants<T>& constants,
                                       const BrakeInput<T>& input);

/// All six heat flows (000:26-31).
template <Scalar T>
BrakeHeatFlows<T> CalcBrakeHeatFlows(const BrakeThermalParams<T>& params,
                                     const BrakeState<T>& state, const BrakeInput<T>& input);
/// All six heat flows from precomputed input terms; the surface-and-bulk disc's further flows
/// with the rim at `rim_temp` (K; ignored by the lumped disc).
template <Scalar T>
BrakeHeatFlows<T> CalcBrakeHeatFlows(const BrakeThermalParams<T>& params,
                                     const BrakeState<T>& state, const BrakeInputTerms<T>& terms,
                                     const T& rim_temp = T(0.0));

/// Time derivative of the brake state (000:24-25). If `flows` is given, the heat flows used are
/// written there.
template <Scalar T>
BrakeState<T> CalcBrakeDerivatives(const BrakeThermalParams<T>& params, const BrakeState<T>& state,
                                   const BrakeInput<T>& input, BrakeHeatFlows<T>* flows = nullptr);
/// As above, from precomputed input terms; `rim_temp` as in CalcBrakeHeatFlows.
template <Scalar T>
BrakeState<T> CalcBrakeDerivatives(const BrakeThermalParams<T>& params, const BrakeState<T>& state,
                                   const BrakeInputTerms<T>& terms,
                                   BrakeHeatFlows<T>* flows = nullptr, const T& rim_temp = T(0.0));

}  // namespace hotlap::brake
