#pragma once
/// @file
/// The explicit solver's state in a checkpoint (checkpoint.h): the model's time step, then every
/// field of ExplicitState as its VisitFields lists it (explicit_state.h), each behind its name,
/// doubles as their bytes. Nothing is listed by hand here, so the checkpoint holds the state
/// whole and a restart continues bit for bit.
///
///   fe::BinaryWriter w;
///   fe::SaveExplicitState(model, state, w);
///   ...
///   fe::BinaryReader r(w.bytes(), "name");
///   fe::LoadExplicitState(model, r, state);   // state: one of the same model
///   r.ExpectEnd();

#include "hotlap/fe/checkpoint.h"
#include "hotlap/fe/explicit_model.h"
#include "hotlap/fe/explicit_state.h"

namespace hotlap::fe {

/// Writes the model's time step and the whole state.
void SaveExplicitState(const ExplicitModel& model, const ExplicitState& state, BinaryWriter& out);

/// Reads what SaveExplicitState wrote into `state`, a state of the same model (its arrays give
/// the sizes expected). Throws InputError (via the reader: "checkpoint '<name>' is damaged:
/// ...", naming the field) if the time step is not the model's, a field's name, size or value
/// is wrong (non-finite doubles, flags and enums out of range, a negative step count), or the
/// data ends early; `state` is then unchanged.
void LoadExplicitState(const ExplicitModel& model, BinaryReader& in, ExplicitState& state);

}  // namespace hotlap::fe
