#pragma once
/// @file
/// The scalar types every model is templated on, and the few helpers that let one piece of model
/// code run on all of them.
///
/// How to use: write a model as `template <Scalar T> ... Calc...(const Params<T>&, ...)`, call the
/// math functions unqualified after `using std::exp;` etc. so that argument-dependent lookup picks
/// ceres' overloads for Jets, and use ValueOf(x) only to choose a branch or a table interval (never
/// inside the arithmetic, or derivatives are lost). Definitions live in the .cc file and are
/// instantiated for every type in HOTLAP_FOR_EACH_SCALAR.
///
/// Pitfall: a branch chosen on ValueOf(x) is exact for forward-mode AD at every point except on
/// the switching surface itself, where the one-sided derivative is returned.

#include <concepts>
#include <type_traits>

#include <ceres/jet.h>

#include "hotlap/common/second_order.h"

namespace hotlap {

template <typename T>
struct IsJet : std::false_type {};
template <typename T, int N>
struct IsJet<ceres::Jet<T, N>> : std::true_type {};

template <typename T>
struct IsSecondOrder : std::false_type {};
template <int N>
struct IsSecondOrder<SecondOrder<N>> : std::true_type {};

/// A scalar a model can be evaluated on: double (simulation), a ceres::Jet (fitting) or a
/// SecondOrder (exact Hessians for optimal control).
template <typename T>
concept Scalar = std::same_as<T, double> || IsJet<T>::value || IsSecondOrder<T>::value;

/// The plain value of a scalar, for branching and table look-up.
inline double ValueOf(double x) { return x; }
template <typename T, int N>
double ValueOf(const ceres::Jet<T, N>& x) {
  return ValueOf(x.a);
}

/// Jet sizes the library is compiled for: 2 (two-parameter fits and state derivatives),
/// 5 (tyre p1..p5), 7 (tyre thermal and wear), 14 (brake gamma, xi and 12 convection entries).
using Jet2 = ceres::Jet<double, 2>;
using Jet5 = ceres::Jet<double, 5>;
using Jet7 = ceres::Jet<double, 7>;
using Jet14 = ceres::Jet<double, 14>;
/// First derivatives of the optimal-control lap's 10-input elements.
using Jet10 = ceres::Jet<double, 10>;
/// First derivatives of the optimal-control lap's 15-input wheel elements (a tyre with its rim
/// and its brake).
using Jet15 = ceres::Jet<double, 15>;

}  // namespace hotlap

/// The scalars the optimal-control elements (ocp/element.h) evaluate models on, by the element's
/// input count: tyre forces on (Fz, kappa, alpha): 3; a brake or a tyre's rolling resistance: 5;
/// a tyre's thermal model: 10; a tyre with its rim and its brake: 15.
/// Only the models an element uses are instantiated for them (see each .cc).
#define HOTLAP_FOR_EACH_OCP_SCALAR(MACRO) \
  MACRO(::hotlap::SecondOrder<3>)         \
  MACRO(::hotlap::SecondOrder<5>)         \
  MACRO(::hotlap::SecondOrder<10>)        \
  MACRO(::hotlap::SecondOrder<15>)        \
  MACRO(::hotlap::Jet10)                  \
  MACRO(::hotlap::Jet15)

/// Calls MACRO(T) once for every scalar type the models are instantiated for.
#define HOTLAP_FOR_EACH_SCALAR(MACRO) \
  MACRO(double)                       \
  MACRO(::hotlap::Jet2)               \
  MACRO(::hotlap::Jet5)               \
  MACRO(::hotlap::Jet7)               \
  MACRO(::hotlap::Jet14)
