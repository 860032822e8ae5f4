#pragma once
/// @file
/// Deformed shapes as VTK unstructured grids (.vtu, ASCII) for ParaView: the current node
/// positions, the hexahedra, per-node displacement and velocity, per-element region, pressure
/// (-tr(sigma)/3) and von Mises stress.

#include <filesystem>

#include "hotlap/fe/explicit_solver.h"

namespace hotlap::fe {

/// Writes the solver's current state to `path` (atomically). Throws InputError if it cannot.
void WriteVtu(const std::filesystem::path& path, const ExplicitSolver& solver);

}  // namespace hotlap::fe
