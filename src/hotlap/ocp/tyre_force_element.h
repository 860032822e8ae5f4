#pragma once
/// @file
/// The element tying one corner's tyre force variables to its force model in the lifted lap
/// problem:
///
///   r_x = Fx - g(T_t) h(wear) Fx_model(Fz, kappa, alpha),
///   r_y = Fy - g(T_t) h(wear) Fy_model(Fz, kappa, alpha),
///
/// inputs (Fz, kappa, alpha, T_t, wear, Fx, Fy). The force model (Magic Formula, brush or UniTire)
/// is evaluated on SecondOrder<3> over its own three inputs only, and the grip factor on
/// SecondOrder<2>; the product's derivatives are assembled from the two, which costs a fraction
/// of differentiating the whole seven-input element at once.

#include "hotlap/ocp/element.h"
#include "hotlap/tyre/compound.h"
#include "hotlap/vehicle/vehicle_params.h"

namespace hotlap::ocp {

class TyreForceElement final : public Element {
 public:
  /// `speed` is the wheel speed the force model is evaluated at (the forces of the shipped models
  /// do not depend on it above their low-speed limits).
  TyreForceElement(const vehicle::CornerSetup& corner, const tyre::TyreCompound& compound,
                   double speed);

  int inputs() const override { return 7; }
  int outputs() const override { return 2; }
  void Values(const double* in, double* out) const override;
  void Jacobian(const double* in, double* out, double* jac) const override;
  void Hessian(const double* in, const double* weights, double* hess) const override;

 private:
  struct Local;  // the model's and the grip's values and derivatives at one point
  Local Evaluate(const double* in) const;

  const vehicle::CornerSetup* corner_;
  const tyre::TyreCompound* compound_;
  double speed_;
  tyre::TyreForceModel<SecondOrder<3>> model_;
};

}  // namespace hotlap::ocp
