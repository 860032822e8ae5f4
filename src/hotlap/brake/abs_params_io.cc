#include "hotlap/brake/abs_params_io.h"

#include <fmt/format.h>

#include "hotlap/brake/abs_params_fields.h"
#include "hotlap/common/units.h"

namespace hotlap::brake {

AbsControllerParams ReadAbsControllerParams(YamlReader& c) {
  AbsControllerParams p;
  for (const AbsControllerField& f : AbsControllerFields()) {
    p.*f.member = f.ToSi(c.Number(f.key, f.RangeGiven(p.period_s)));
  }
  if (!(p.high_accel_threshold_mps2 > p.accel_threshold_mps2)) {
    c.Fail("high_accel_threshold_g",
           fmt::format("{:g} must be above accel_threshold_g ({:g})",
                       p.high_accel_threshold_mps2 / kGravity, p.accel_threshold_mps2 / kGravity));
  }
  c.Finish();
  return p;
}

BrakeHydraulicsParams<double> ReadBrakeHydraulicsParams(YamlReader& h) {
  BrakeHydraulicsParams<double> p;
  for (const BrakeHydraulicsField& f : BrakeHydraulicsFields()) {
    p.*f.member = f.ToSi(h.Number(f.key, f.range));
  }
  h.Finish();
  return p;
}

}  // namespace hotlap::brake
