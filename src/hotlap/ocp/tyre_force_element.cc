#include "hotlap/ocp/tyre_force_element.h"

namespace hotlap::ocp {

namespace {
// Input positions.
constexpr int kFz = 0, kKappa = 1, kAlpha = 2, kTread = 3, kWear = 4, kFx = 5, kFy = 6;
}  // namespace

struct TyreForceElement::Local {
  SecondOrder<3> fx, fy;  // model forces over (Fz, kappa, alpha)
  SecondOrder<2> grip;    // g(T_t) h(wear) over (T_t, wear)
};

TyreForceElement::TyreForceElement(const vehicle::CornerSetup& corner,
                                   const tyre::TyreCompound& compound, double speed)
    : corner_(&corner),
      compound_(&compound),
      speed_(speed),
      model_(corner.forces.Cast<SecondOrder<3>>()) {}

TyreForceElement::Local TyreForceElement::Evaluate(const double* in) const {
  using S3 = SecondOrder<3>;
  tyre::TyreOperatingPoint<S3> op;
  op.fz = S3::Variable(in[kFz], 0);
  op.slip_ratio = S3::Variable(in[kKappa], 1);
  op.slip_angle = S3::Variable(in[kAlpha], 2);
  op.camber = S3(corner_->camber);
  op.speed = S3(speed_);
  op.pressure = S3(corner_->pressure);
  op.tread_temp = S3(in[kTread]);
  const tyre::TyreForces<S3> f = tyre::CalcTyreForces(model_, op);
  using S2 = SecondOrder<2>;
  const S2 grip = compound_->GripFactor(S2::Variable(in[kTread], 0), S2::Variable(in[kWear], 1));
  return {f.fx, f.fy, grip};
}

void TyreForceElement::Values(const double* in, double* out) const {
  tyre::TyreOperatingPoint<double> op;
  op.fz = in[kFz];
  op.slip_ratio = in[kKappa];
  op.slip_angle = in[kAlpha];
  op.camber = corner_->camber;
  op.speed = speed_;
  op.pressure = corner_->pressure;
  op.tread_temp = in[kTread];
  const tyre::TyreForces<double> f = tyre::CalcTyreForces(corner_->forces, op);
  const double grip = compound_->GripFactor(in[kTread], in[kWear]);
  out[0] = in[kFx] - grip * f.fx;
  out[1] = in[kFy] - grip * f.fy;
}

void TyreForceElement::Jacobian(const double* in, double* out, double* jac) const {
  const Local l = Evaluate(in);
  const SecondOrder<3>* forces[2] = {&l.fx, &l.fy};
  for (int o = 0; o < 2; ++o) {
    const SecondOrder<3>& f = *forces[o];
    double* row = jac + o * 7;
    out[o] = in[o == 0 ? kFx : kFy] - l.grip.a * f.a;
    for (int i = 0; i < 3; ++i) row[i] = -l.grip.a * f.v[i];
    row[kTread] = -l.grip.v[0] * f.a;
    row[kWear] = -l.grip.v[1] * f.a;
    row[kFx] = o == 0 ? 1.0 : 0.0;
    row[kFy] = o == 1 ? 1.0 : 0.0;
  }
}

void TyreForceElement::Hessian(const double* in, const double* weights, double* hess) const {
  const Local l = Evaluate(in);
  for (int k = 0; k < 49; ++k) hess[k] = 0.0;
  const SecondOrder<3>* forces[2] = {&l.fx, &l.fy};
  for (int o = 0; o < 2; ++o) {
    const double w = -weights[o];  // r = F - G f: the Hessian is that of -G f
    if (w == 0.0) continue;
    const SecondOrder<3>& f = *forces[o];
    // d2(G f): G d2f on the model's block, f d2G on the grip's, dG df' across.
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j <= i; ++j) {
        const double h = w * l.grip.a * f.Hessian(i, j);
        hess[i * 7 + j] += h;
        if (i != j) hess[j * 7 + i] += h;
      }
    }
    for (int i = 0; i < 2; ++i) {
      for (int j = 0; j <= i; ++j) {
        const double h = w * f.a * l.grip.Hessian(i, j);
        hess[(3 + i) * 7 + (3 + j)] += h;
        if (i != j) hess[(3 + j) * 7 + (3 + i)] += h;
      }
    }
    for (int i = 0; i < 2; ++i) {
      for (int j = 0; j < 3; ++j) {
        const double h = w * l.grip.v[i] * f.v[j];
        hess[(3 + i) * 7 + j] += h;
        hess[j * 7 + (3 + i)] += h;
      }
    }
  }
}

}  // namespace hotlap::ocp
