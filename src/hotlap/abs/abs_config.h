#pragma once
/// @file
/// The ABS configuration file (`model: abs_quarter_car`; docs/abs.md, data/abs/paper.yaml): the
/// braking event, the driver, the wheel and its tyre file, the brake thermal file, the
/// hydraulics, the controller, the friction laws and surfaces, and the scenario settings.
/// Loaded strictly: an unknown or missing key is an InputError naming the file and the field.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "hotlap/abs/abs_plant.h"
#include "hotlap/abs/abs_surface.h"
#include "hotlap/brake/abs_controller.h"
#include "hotlap/brake/brake_params_io.h"
#include "hotlap/brake/wheel_speed_filter.h"
#include "hotlap/common/yaml_reader.h"

namespace hotlap::sim {

/// Whether the ABS controls the brake, or the driver's pressure goes straight to the hydraulics.
enum class AbsControl { kAbs, kDriverOnly };

/// The driver's brake application: from t = 0 the master-cylinder pressure rises at a constant
/// rate to a level and stays there.
struct AbsDriver {
  double pressure_rate_Pa_per_s = 0.0;  ///< Pa/s (> 0)
  double pressure_Pa = 0.0;             ///< Pa (> 0)

  /// Master-cylinder pressure at time t (s), Pa.
  double PressureAt(double t) const {
    if (t <= 0.0) return 0.0;
    const double p = pressure_rate_Pa_per_s * t;
    return p < pressure_Pa ? p : pressure_Pa;
  }
};

/// One braking event (the `event:` section), with what the command line may change.
struct AbsEvent {
  double initial_speed_mps = 0.0;  ///< Vx at t = 0; the wheel free-rolling, m/s
  double duration_s = 0.0;         ///< longest time simulated, s
  double stop_speed_mps = 0.0;     ///< the vehicle counts as stopped below this, m/s
  AbsVehicleMode vehicle = AbsVehicleMode::kFree;
  std::string surface;                   ///< name of a friction law or surface
  double ambient_temp_K = 0.0;           ///< cooling-air temperature, K
  double initial_disc_temp_K = 0.0;      ///< K
  double initial_calliper_temp_K = 0.0;  ///< K
  int steps_per_period = 0;              ///< integration steps per controller period (>= 1)
  AbsControl control = AbsControl::kAbs;
};

/// The `scenarios:` section: comparisons and the series of stops.
struct AbsScenarioSettings {
  double max_duration_s = 0.0;          ///< comparison stops run to standstill, at most this long
  int stop_series_count = 0;            ///< stops in the heating series
  double stop_series_interval_s = 0.0;  ///< driving at the initial speed between stops, s
  std::string stop_series_surface;      ///< the surface of the series
};

/// A named friction law of the `friction_laws:` list.
struct NamedFrictionLaw {
  std::string name;
  FrictionLaw<double> law;
};

/// Everything one ABS configuration file holds.
struct AbsConfig {
  std::string name;
  std::filesystem::path path;
  /// The numbers of the file replaced on loading (LoadAbsConfig's `overrides`), in order.
  std::vector<YamlOverride> overrides;
  AbsPlantModel<double> plant;  ///< wheel, tyre (from `wheel.tyre_file`), hydraulics
  brake::AbsControllerParams controller;
  /// The wheel-speed filter before the controller (`wheel_speed_filter`; absent: none).
  brake::WheelSpeedFilterParams wheel_speed_filter;
  brake::BrakeFile brake;  ///< the disc/calliper thermal model (from `brake_file`)
  AbsDriver driver;
  AbsEvent event;
  std::vector<NamedFrictionLaw> friction_laws;
  /// Every friction law as a one-segment surface of the same name, then the `surfaces:` list.
  std::vector<Surface> surfaces;
  AbsScenarioSettings scenarios;

  /// The surface called `name`; InputError listing the names there are.
  const Surface& SurfaceNamed(std::string_view name) const;
  /// The hydraulic delay in controller periods (a whole number, checked on loading).
  int DelayTicks() const;
};

/// Loads and checks an ABS configuration file; InputError naming the file, field, value and range.
/// `overrides` (`--set KEY=VALUE`, ParseAbsOverrides) replace numbers of the file itself (e.g.
/// `controller.reapply_fraction`), checked as the file's own; not of the tyre and brake files it
/// names.
AbsConfig LoadAbsConfig(const std::filesystem::path& path,
                        const std::vector<YamlOverride>& overrides = {});

/// Each of `texts` ("KEY=VALUE") as an override of an ABS file's number (ParseYamlOverride).
std::vector<YamlOverride> ParseAbsOverrides(const std::vector<std::string>& texts);

/// The summaries' record of the overrides: {key: value}, {} when there are none.
nlohmann::json AbsOverridesJson(const std::vector<YamlOverride>& overrides);

/// The shipped default, the FE/ABS paper's case: DataDir()/abs/paper.yaml.
std::filesystem::path DefaultAbsConfigPath();

}  // namespace hotlap::sim
