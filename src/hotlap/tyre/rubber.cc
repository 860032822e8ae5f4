#include "hotlap/tyre/rubber.h"

#include <cmath>

namespace hotlap::tyre {

template <Scalar T>
T CalcTemperatureFactor(const TemperatureFactor<T>& factor, const T& temp) {
  using std::exp;
  return factor.scale * exp(-factor.decay * (temp - factor.reference_temp));
}

template <Scalar T>
T CalcShearModulus(const RubberParams<T>& rubber, const T& temp) {
  using std::exp;
  // (001:1)
  return rubber.modulus_amplitude *
             exp(-rubber.modulus_decay * (temp - rubber.modulus_reference_temp)) +
         rubber.modulus_limit;
}

template <Scalar T>
T CalcBristleStiffness(const RubberParams<T>& rubber, const T& temp) {
  return rubber.geometry_factor * CalcShearModulus(rubber, temp);  // (001:2)
}

#define HOTLAP_INSTANTIATE_RUBBER(T)                                          \
  template T CalcTemperatureFactor<T>(const TemperatureFactor<T>&, const T&); \
  template T CalcShearModulus<T>(const RubberParams<T>&, const T&);           \
  template T CalcBristleStiffness<T>(const RubberParams<T>&, const T&);

HOTLAP_FOR_EACH_SCALAR(HOTLAP_INSTANTIATE_RUBBER)
// The optimal-control tyre element's scalar: tyre forces over (Fz, kappa, alpha).
HOTLAP_INSTANTIATE_RUBBER(::hotlap::SecondOrder<3>)

}  // namespace hotlap::tyre
