#include "hotlap/tyre/tyre_thermal_fields.h"

#include <array>
#include <vector>

#include "hotlap/common/field_table.h"
#include "hotlap/common/units.h"

namespace hotlap::tyre {

namespace {

using P = TyreThermalParams<double>;

// How the log fits bound and show the parameters they free (tyre_thermal_fit.cc,
// contact_length_fit.cc).
constexpr FitHint kP1Fit{"p1", "", 0.0, 1.0, 0.05};
constexpr FitHint kP2Fit{"p2", "J/(kg N)", 0.0, 0.1, 1e-5};
constexpr FitHint kP3Fit{"p3", "J/(kg N)", 0.0, 0.1, 1e-5};
constexpr FitHint kP4Fit{"p4", "J/(kg N)", 0.0, 0.1, 1e-5};
constexpr FitHint kP5Fit{"p5", "W/(m\u00b2 K)", 0.0, 1e4, 10.0};
constexpr FitHint kWp1Fit{"wp1", "mm/s", 0.0, 1.0, 1e-8};
constexpr FitHint kWp2Fit{"wp2", "", 0.0, 5.0, 0.5};
constexpr FitHint kPcp1Fit{"p_cp1", "m/N^p_cp2", 1e-8, 1.0, 1e-6};
constexpr FitHint kPcp2Fit{"p_cp2", "", 0.0, 2.0, 0.1};
// The gas path's conductances the tyre fit's gas stage frees (TPMS channels; docs/fitting.md).
constexpr FitHint kCarcassGasFit{"G_cg", "W/K", 0.1, 1000.0, 1.0};
constexpr FitHint kGasRimFit{"G_gr", "W/K", 0.1, 1000.0, 1.0};
constexpr FitHint kRimAirFit{"G_ra", "W/K", 0.0, 1000.0, 1.0};

double DegreesToSi(double deg) { return DegToRad(deg); }
double CelsiusToSi(double c) { return CelsiusToKelvin(c); }

std::span<const TyreThermalField> Table() {
  // clang-format off
  static const auto table = std::to_array<TyreThermalField>({
      {"heat_generation", "p1", &P::p1, Range::Closed(0.0, 1.0, ""), nullptr, &kP1Fit},
      {"heat_generation", "p2_J_per_kgN", &P::p2, Range::NonNegative("J/(kg N)"), nullptr, &kP2Fit},
      {"heat_generation", "p3_J_per_kgN", &P::p3, Range::NonNegative("J/(kg N)"), nullptr, &kP3Fit},
      {"heat_generation", "p4_J_per_kgN", &P::p4, Range::NonNegative("J/(kg N)"), nullptr, &kP4Fit},
      {"heat_generation", "p5_W_per_m2K", &P::p5, Range::NonNegative("W/(m^2 K)"), nullptr, &kP5Fit},
      {"wear", "wp1_mm_per_s", &P::wear_coeff, Range::NonNegative("mm/s"), nullptr, &kWp1Fit},
      {"wear", "wp2", &P::wear_exponent, Range::Closed(0.0, 10.0, ""), nullptr, &kWp2Fit},
      {"contact_length", "p_cp1", &P::contact_length_coeff, Range::Positive("m/N^p_cp2"), nullptr, &kPcp1Fit},
      {"contact_length", "p_cp2", &P::contact_length_exponent, Range::Closed(0.0, 2.0, ""), nullptr, &kPcp2Fit},
      {"construction", "tread_mass_kg", &P::tread_mass, Range::Positive("kg")},
      {"construction", "carcass_mass_kg", &P::carcass_mass, Range::Positive("kg")},
      {"construction", "tread_heat_capacity_J_per_kgK", &P::tread_heat_capacity, Range::Positive("J/(kg K)")},
      {"construction", "carcass_heat_capacity_J_per_kgK", &P::carcass_heat_capacity, Range::Positive("J/(kg K)")},
      {"construction", "track_conductance_W_per_m2K", &P::track_conductance, Range::NonNegative("W/(m^2 K)")},
      {"construction", "contact_width_m", &P::contact_width, Range::Positive("m")},
      {"construction", "reference_slip_angle_deg", &P::reference_slip_angle, Range::OpenClosed(0.0, 90.0, "deg"), &DegreesToSi},
      {"construction", "non_sliding_fraction_low", &P::non_sliding_fraction_low, Range::Closed(0.0, 1.0, "")},
      {"construction", "non_sliding_fraction_high", &P::non_sliding_fraction_high, Range::Closed(0.0, 1.0, "")},
      {"construction", "unloaded_radius_m", &P::unloaded_radius, Range::Positive("m")},
      {"construction", "rim_radius_m", &P::rim_radius, Range::Positive("m")},
      {"construction", "diameter_m", &P::diameter, Range::Positive("m")},
      {"construction", "width_m", &P::width, Range::Positive("m")},
      {"construction", "emissivity", &P::emissivity, Range::Closed(0.0, 1.0, "")},
      {"hysteresis", "carcass_slip_share", &P::carcass_slip_share, Range::Closed(0.0, 1.0, "")},
      {"hysteresis", "rolling_resistance_coefficient", &P::rolling_resistance, Range::Closed(0.0, 0.1, "")},
      {"hysteresis", "reference_carcass_temp_C", &P::rolling_reference_temp, Range::Closed(-50.0, 300.0, "degC"), &CelsiusToSi},
      {"hysteresis", "reference_pressure_kPa", &P::rolling_reference_pressure, Range::Closed(20.0, 1000.0, "kPa"), &KilopascalsToPascals},
      {"hysteresis", "temp_coefficient_per_K", &P::rolling_temp_coefficient, Range::Closed(0.0, 0.1, "1/K")},
      {"hysteresis", "temp_floor", &P::rolling_temp_floor, Range::Closed(0.0, 1.0, "")},
      {"hysteresis", "pressure_exponent", &P::rolling_pressure_exponent, Range::Closed(0.0, 2.0, "")},
      {"gas", "cold_set_temp_C", &P::cold_set_temp, Range::Closed(-40.0, 80.0, "degC"), &CelsiusToSi},
      {"gas", "liner_pressure_above_tyre_kPa", &P::liner_pressure_offset, Range::Closed(0.0, 1000.0, "kPa"), &KilopascalsToPascals},
      {"gas", "carcass_gas_W_per_K", &P::carcass_gas_conductance, Range::Positive("W/K"), nullptr, &kCarcassGasFit},
      {"gas", "gas_rim_W_per_K", &P::gas_rim_conductance, Range::Positive("W/K"), nullptr, &kGasRimFit},
      {"gas", "gas_liner_W_per_K", &P::gas_liner_conductance, Range::NonNegative("W/K")},
      {"gas", "liner_rim_W_per_K", &P::liner_rim_conductance, Range::NonNegative("W/K")},
      {"gas", "contact_length_pressure_exponent", &P::contact_length_pressure_exponent, Range::Closed(0.0, 2.0, "")},
      {"rim", "rim_mass_kg", &P::rim_mass, Range::Positive("kg")},
      {"rim", "rim_heat_capacity_J_per_kgK", &P::rim_heat_capacity, Range::Positive("J/(kg K)")},
      {"rim", "rim_air_W_per_K", &P::rim_air_conductance, Range::NonNegative("W/K"), nullptr, &kRimAirFit},
      {"rim", "sidewall_air_W_per_K", &P::sidewall_air_conductance, Range::NonNegative("W/K")},
      {"rim", "still_air_fraction", &P::still_air_fraction, Range::Closed(0.0, 1.0, "")},
  });
  // clang-format on
  return table;
}

constexpr std::array<std::string_view, 7> kSections = {
    "heat_generation", "wear", "contact_length", "construction", "hysteresis", "gas", "rim"};

}  // namespace

std::string TyreThermalField::Path() const { return std::string(section) + "." + std::string(key); }

std::span<const TyreThermalField> TyreThermalFields() { return Table(); }

std::span<const std::string_view> TyreThermalSections() { return kSections; }

bool IsGasRimSection(std::string_view section) {
  return section == "hysteresis" || section == "gas" || section == "rim";
}

std::vector<const TyreThermalField*> TyreThermalFieldsIn(std::string_view section) {
  return FieldsIn(Table(), section);
}

std::vector<const TyreThermalField*> FittedTyreThermalFields(std::string_view section) {
  if (section.empty()) return FittedFields(Table());
  return FittedFields(Table(), section);
}

const TyreThermalField* FindTyreThermalField(std::string_view path) {
  return FindField(Table(), path);
}

}  // namespace hotlap::tyre
