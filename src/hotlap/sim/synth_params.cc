#include "hotlap/sim/synth_params.h"

#include "hotlap/common/yaml_reader.h"

namespace hotlap::sim {

namespace {

void ReadOptional(YamlReader& y, std::string_view key, const Range& range,
                  std::optional<double>& out) {
  out = y.OptionalNumber(key, range);
}

void ReadCholesky(YamlReader& parent, std::string_view key, CholeskyOverrides& out) {
  if (!parent.Has(key)) return;
  YamlReader c = parent.Map(key);
  const Range diagonal = Range::NonNegative("sqrt(W/K)");
  const Range off = Range::Any("sqrt(W/K)");
  ReadOptional(c, "l11", diagonal, out[0]);
  ReadOptional(c, "l21", off, out[1]);
  ReadOptional(c, "l22", diagonal, out[2]);
  ReadOptional(c, "l31", off, out[3]);
  ReadOptional(c, "l32", off, out[4]);
  ReadOptional(c, "l33", diagonal, out[5]);
  c.Finish();
}

TyreOverrides ReadTyre(YamlReader& y) {
  TyreOverrides t;
  if (y.Has("heat_generation")) {
    YamlReader g = y.Map("heat_generation");
    ReadOptional(g, "p1", Range::Closed(0.0, 1.0, ""), t.p1);
    ReadOptional(g, "p2_J_per_kgN", Range::NonNegative("J/(kg N)"), t.p2);
    ReadOptional(g, "p3_J_per_kgN", Range::NonNegative("J/(kg N)"), t.p3);
    ReadOptional(g, "p4_J_per_kgN", Range::NonNegative("J/(kg N)"), t.p4);
    ReadOptional(g, "p5_W_per_m2K", Range::NonNegative("W/(m^2 K)"), t.p5);
    g.Finish();
  }
  if (y.Has("wear")) {
    YamlReader w = y.Map("wear");
    ReadOptional(w, "wp1_mm_per_s", Range::NonNegative("mm/s"), t.wear_coeff);
    ReadOptional(w, "wp2", Range::Closed(0.0, 10.0, ""), t.wear_exponent);
    w.Finish();
  }
  if (y.Has("contact_length")) {
    YamlReader c = y.Map("contact_length");
    ReadOptional(c, "p_cp1", Range::Positive("m/N^p_cp2"), t.contact_length_coeff);
    ReadOptional(c, "p_cp2", Range::Closed(0.0, 2.0, ""), t.contact_length_exponent);
    c.Finish();
  }
  return t;
}

BrakeOverrides ReadBrake(YamlReader& y) {
  BrakeOverrides b;
  ReadOptional(y, "heat_partition", Range::Closed(0.0, 1.0, ""), b.heat_partition);
  ReadOptional(y, "mass_participation", Range::OpenClosed(0.0, 1.0, ""), b.mass_participation);
  ReadCholesky(y, "disc_convection_cholesky_sqrtW_per_K", b.disc_convection);
  ReadCholesky(y, "calliper_convection_cholesky_sqrtW_per_K", b.calliper_convection);
  return b;
}

template <class T>
void Set(T& target, const std::optional<double>& value) {
  if (value) target = *value;
}

void ApplyCholesky(const CholeskyOverrides& o, brake::ConvectionPolynomial<double>& l) {
  Set(l.l11, o[0]);
  Set(l.l21, o[1]);
  Set(l.l22, o[2]);
  Set(l.l31, o[3]);
  Set(l.l32, o[4]);
  Set(l.l33, o[5]);
}

}  // namespace

ParameterOverrides LoadParameterOverrides(const std::filesystem::path& path) {
  YamlReader y = YamlReader::Load(path);
  ParameterOverrides out;
  out.path = path;
  out.name = y.String("name");
  y.Choice("model", {"parameter_overrides"});
  YamlReader corners = y.Map("corners");
  for (Corner c : kAllCorners) {
    if (!corners.Has(CornerName(c))) continue;
    YamlReader corner = corners.Map(CornerName(c));
    if (corner.Has("tyre")) {
      YamlReader t = corner.Map("tyre");
      out.tyres[CornerIndex(c)] = ReadTyre(t);
      t.Finish();
    }
    if (corner.Has("brake")) {
      YamlReader b = corner.Map("brake");
      out.brakes[CornerIndex(c)] = ReadBrake(b);
      b.Finish();
    }
    corner.Finish();
  }
  corners.Finish();
  y.Finish();
  return out;
}

void ApplyParameterOverrides(const ParameterOverrides& o, vehicle::Car& car) {
  for (Corner c : kAllCorners) {
    const int i = CornerIndex(c);
    tyre::TyreThermalParams<double>& t = car.tyres[i].params;
    const TyreOverrides& to = o.tyres[i];
    Set(t.p1, to.p1);
    Set(t.p2, to.p2);
    Set(t.p3, to.p3);
    Set(t.p4, to.p4);
    Set(t.p5, to.p5);
    Set(t.wear_coeff, to.wear_coeff);
    Set(t.wear_exponent, to.wear_exponent);
    Set(t.contact_length_coeff, to.contact_length_coeff);
    Set(t.contact_length_exponent, to.contact_length_exponent);
    brake::BrakeThermalParams<double>& b = car.brakes[i].params;
    const BrakeOverrides& bo = o.brakes[i];
    Set(b.heat_partition, bo.heat_partition);
    Set(b.mass_participation, bo.mass_participation);
    ApplyCholesky(bo.disc_convection, b.disc_convection);
    ApplyCholesky(bo.calliper_convection, b.calliper_convection);
  }
}

}  // namespace hotlap::sim
