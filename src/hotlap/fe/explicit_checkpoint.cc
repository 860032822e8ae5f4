#include "hotlap/fe/explicit_checkpoint.h"

#include <string>
#include <utility>

#include "hotlap/fe/field_io.h"

namespace hotlap::fe {

void SaveExplicitState(const ExplicitModel& model, const ExplicitState& state, BinaryWriter& out) {
  out.PutTag("SOLV");
  out.PutDouble(model.time_step_s);
  PutFields(out, state);
}

void LoadExplicitState(const ExplicitModel& model, BinaryReader& in, ExplicitState& state) {
  in.ExpectTag("SOLV");
  const double dt = in.GetDouble();
  if (dt != model.time_step_s) {
    in.Damaged("its time step " + std::to_string(dt) + " s is not this model's " +
               std::to_string(model.time_step_s) + " s");
  }
  // Read into a copy (its arrays give the sizes); only a state read whole replaces `state`.
  ExplicitState read = state;
  GetFields(in, read);
  state = std::move(read);
}

}  // namespace hotlap::fe
