#pragma once
/// @file
/// The finite-element tyre's configuration file (data/fe/*.yaml; docs/fe-tyre.md): the size and
/// profile, the mesh density, the paper's rubber and cord data, the solver settings, the road,
/// the rim and the settings of each step (inflate, footprint, roll, abs). Loaded strictly: every
/// key is required, unknown keys are errors, and every message names the file, field, value and
/// allowed range.

#include <filesystem>
#include <string>
#include <vector>

#include "hotlap/fe/explicit_model.h"
#include "hotlap/fe/rebar.h"
#include "hotlap/fe/road_contact.h"
#include "hotlap/fe/tyre_mesh.h"
#include "hotlap/fe/yeoh.h"

namespace hotlap::fe {

/// Dynamic relaxation to a static state: the load is ramped, then held, with mass damping.
struct QuasiStaticStep {
  double ramp_s = 0.0;
  double hold_s = 0.0;
  double damping_per_s = 0.0;  ///< alpha of the mass-proportional damping, 1/s
};

/// Everything in one configuration file. SI units.
struct FeConfig {
  std::filesystem::path file;
  std::string name;
  TyreSize size;
  TyreMeshOptions mesh;
  /// Each rubber's bulk modulus over its initial shear modulus, 1 (sets YeohMaterial's bulk).
  double bulk_to_shear_ratio = 0.0;
  std::vector<YeohMaterial> rubber;  ///< TyreRegion order (002 Table 1)
  std::vector<RebarMaterial> cords;  ///< TyreCord order (002 Tables 2-3)
  SolverOptions solver;
  RoadContact road;  ///< enabled by the steps that need it
  double rim_mass_kg = 0.0;
  double rim_inertia_kgm2 = 0.0;

  double inflation_pressure_Pa = 0.0;
  QuasiStaticStep inflate;
  double vertical_load_N = 0.0;
  QuasiStaticStep footprint;
  double roll_speed_mps = 0.0;
  double roll_duration_s = 0.0;
  std::filesystem::path abs_config;  ///< the ABS controller and hydraulics (data/abs/*.yaml)
  /// Optional: the lumped quarter car's own ABS tuning (data/abs/*.yaml), whose `hotlap abs`
  /// run is reported beside the FE stop with the run of `abs_config`; empty if not given.
  std::filesystem::path abs_lumped_config;
  double abs_duration_s = 0.0;
  double history_interval_s = 0.0;
  int vtu_frames = 0;  ///< deformed shapes written per step (>= 1: at least the last)
};

/// Reads and validates `path` (its numbers and counts as fe_config_fields.h lists them). Throws
/// InputError naming the file, field, value and range.
FeConfig LoadFeConfig(const std::filesystem::path& path);

}  // namespace hotlap::fe
