#pragma once
/// @file
/// The JSON summary of `hotlap tyre eval --json` (docs/json-output.md): the model, the operating
/// point, and either its forces or, with a sweep, the grid's size and peaks.

#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "hotlap/tyre/tyre_grid.h"

namespace hotlap::tyre {

/// fx_N, fy_N, mz_Nm, mx_Nm, my_Nm.
nlohmann::json TyreForcesJson(const TyreForces<double>& f);

/// command, model (its kind), params, grip_factor and inputs (each operating-point input by its
/// column name, `values` ordered as OperatingPointInputs()).
nlohmann::json TyreEvalJson(std::string_view model_kind, const std::string& params, double grip,
                            const std::vector<double>& values);

/// The grid's out (the CSV written), points and peak_abs_fx_N, peak_abs_fy_N, peak_abs_mz_Nm added
/// to `summary`.
void AddTyreGridJson(nlohmann::json& summary, const TyreGrid& grid, const std::string& out);

}  // namespace hotlap::tyre
