#pragma once
/// @file
/// The finite-element tyre's part of the `hotlap fe --json` summary (docs/fe-tyre.md): the mesh
/// and time step, and each step's figures with the energies at its end; and the warning for a
/// cord stretched beyond what the stable step allows for.

#include <string>

#include <nlohmann/json.hpp>

#include "hotlap/fe/tyre_steps.h"

namespace hotlap::fe {

/// The mesh's size, the time step (and the unscaled stable one) and what mass scaling added.
nlohmann::json FeMeshJson(const TyreRun& run);

/// The energies' JSON (J, and the hourglass over the internal energy).
nlohmann::json FeEnergiesJson(const Energies& energies);

/// Each step's JSON, with the energies at its end.
nlohmann::json InflateJson(const InflateResult& r, const Energies& energies);
nlohmann::json FootprintJson(const FootprintResult& r, const Energies& energies);
nlohmann::json RollJson(const RollResult& r, const Energies& energies);

/// A cord strain as the JSON holds it (four significant digits).
double CordStrainJson(double strain);

/// The warning for a cord strain above kCordStrainAllowance in `step` ("fe STEP: warning: ...",
/// no newline); "" where the strain is within it.
std::string CordStrainWarning(const std::string& step, double strain);

}  // namespace hotlap::fe
