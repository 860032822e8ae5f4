#include "hotlap/brake/brake_thermal_fields.h"

#include <array>
#include <utility>

#include "hotlap/common/field_table.h"

namespace hotlap::brake {

namespace {

using P = BrakeThermalParams<double>;
using L = ConvectionPolynomial<double>;

constexpr std::string_view kDisc = "disc_convection_cholesky_sqrtW_per_K";
constexpr std::string_view kCalliper = "calliper_convection_cholesky_sqrtW_per_K";
constexpr std::string_view kBulk = "disc_bulk";

// How the log fit bounds and shows the parameters it frees (ident/brake_thermal_fit.cc).
constexpr FitHint kGammaFit{"gamma", "", 0.0, 1.0, 0.1};
constexpr FitHint kXiFit{"xi", "", 0.005, 1.0, 0.01};
// Cholesky entries: the diagonal ones are kept non-negative so that (L, P) is a unique pair; the
// off-diagonal ones may have either sign. Any such L gives a positive semi-definite P.
constexpr FitHint Diagonal(std::string_view label) {
  return {label, "\u221a(W/K)", 0.0, 100.0, 0.3};
}
constexpr FitHint OffDiagonal(std::string_view label) {
  return {label, "\u221a(W/K)", -100.0, 100.0, 0.3};
}
constexpr FitHint kDiscFit[6] = {Diagonal("disc l11"),    OffDiagonal("disc l21"),
                                 Diagonal("disc l22"),    OffDiagonal("disc l31"),
                                 OffDiagonal("disc l32"), Diagonal("disc l33")};
constexpr FitHint kCalliperFit[6] = {Diagonal("cal l11"),    OffDiagonal("cal l21"),
                                     Diagonal("cal l22"),    OffDiagonal("cal l31"),
                                     OffDiagonal("cal l32"), Diagonal("cal l33")};

double SquareMillimetres(double v) { return 1e-6 * v; }
double Millimetres(double v) { return 1e-3 * v; }
double SquareCentimetres(double v) { return 1e-4 * v; }

BrakeThermalField Top(std::string_view key, double P::*member, Range range,
                      double (*to_si)(double) = nullptr, const FitHint* fit = nullptr) {
  return {.section = "",
          .key = key,
          .member = member,
          .range = std::move(range),
          .to_si = to_si,
          .fit = fit};
}

// A number in a section of its own.
BrakeThermalField In(std::string_view section, std::string_view key, double P::*member,
                     Range range) {
  return {.section = section, .key = key, .member = member, .range = std::move(range)};
}

// A Cholesky entry; its file range follows its fit hint's (non-negative on the diagonal).
BrakeThermalField Entry(std::string_view section, std::string_view key, L P::*polynomial,
                        double L::*entry, const FitHint& fit) {
  const bool diagonal = fit.lower == 0.0;
  return {.section = section,
          .key = key,
          .polynomial = polynomial,
          .entry = entry,
          .range = diagonal ? Range::NonNegative("sqrt(W/K)") : Range::Any("sqrt(W/K)"),
          .fit = &fit};
}

std::span<const BrakeThermalField> Table() {
  // clang-format off
  static const auto table = std::to_array<BrakeThermalField>({
      Top("heat_partition", &P::heat_partition, Range::Closed(0.0, 1.0, ""), nullptr, &kGammaFit),
      Top("mass_participation", &P::mass_participation, Range::OpenClosed(0.0, 1.0, ""), nullptr, &kXiFit),
      Top("disc_mass_kg", &P::disc_mass, Range::Positive("kg")),
      Top("disc_heat_capacity_J_per_kgK", &P::disc_heat_capacity, Range::Positive("J/(kg K)")),
      Top("calliper_mass_kg", &P::calliper_mass, Range::Positive("kg")),
      Top("calliper_heat_capacity_J_per_kgK", &P::calliper_heat_capacity, Range::Positive("J/(kg K)")),
      Top("pad_conductivity_W_per_mK", &P::pad_conductivity, Range::NonNegative("W/(m K)")),
      Top("pad_area_mm2", &P::pad_area, Range::Positive("mm^2"), &SquareMillimetres),
      Top("pad_thickness_mm", &P::pad_thickness, Range::Positive("mm"), &Millimetres),
      Top("disc_emissivity", &P::disc_emissivity, Range::Closed(0.0, 1.0, "")),
      Top("calliper_emissivity", &P::calliper_emissivity, Range::Closed(0.0, 1.0, "")),
      Top("disc_radiating_area_m2", &P::disc_radiating_area, Range::NonNegative("m^2")),
      Top("calliper_radiating_area_cm2", &P::calliper_radiating_area, Range::NonNegative("cm^2"), &SquareCentimetres),
      Entry(kDisc, "l11", &P::disc_convection, &L::l11, kDiscFit[0]),
      Entry(kDisc, "l21", &P::disc_convection, &L::l21, kDiscFit[1]),
      Entry(kDisc, "l22", &P::disc_convection, &L::l22, kDiscFit[2]),
      Entry(kDisc, "l31", &P::disc_convection, &L::l31, kDiscFit[3]),
      Entry(kDisc, "l32", &P::disc_convection, &L::l32, kDiscFit[4]),
      Entry(kDisc, "l33", &P::disc_convection, &L::l33, kDiscFit[5]),
      Entry(kCalliper, "l11", &P::calliper_convection, &L::l11, kCalliperFit[0]),
      Entry(kCalliper, "l21", &P::calliper_convection, &L::l21, kCalliperFit[1]),
      Entry(kCalliper, "l22", &P::calliper_convection, &L::l22, kCalliperFit[2]),
      Entry(kCalliper, "l31", &P::calliper_convection, &L::l31, kCalliperFit[3]),
      Entry(kCalliper, "l32", &P::calliper_convection, &L::l32, kCalliperFit[4]),
      Entry(kCalliper, "l33", &P::calliper_convection, &L::l33, kCalliperFit[5]),
      In(kBulk, "surface_bulk_conductance_W_per_K", &P::bulk_conductance, Range::Positive("W/K")),
      In(kBulk, "vane_convection_W_per_K", &P::bulk_convection, Range::NonNegative("W/K")),
      In(kBulk, "still_air_fraction", &P::bulk_still_air_fraction, Range::Closed(0.0, 1.0, "")),
      In(kBulk, "hub_conductance_W_per_K", &P::hub_conductance, Range::NonNegative("W/K")),
      In(kBulk, "rim_view_fraction", &P::rim_view_fraction, Range::Closed(0.0, 1.0, "")),
  });
  // clang-format on
  return table;
}

constexpr std::array<std::string_view, 4> kSections = {"", kDisc, kCalliper, kBulk};

}  // namespace

std::string BrakeThermalField::Path() const {
  if (section.empty()) return std::string(key);
  return std::string(section) + "." + std::string(key);
}

std::span<const BrakeThermalField> BrakeThermalFields() { return Table(); }

std::span<const std::string_view> BrakeThermalSections() { return kSections; }

std::vector<const BrakeThermalField*> BrakeThermalFieldsIn(std::string_view section) {
  return FieldsIn(Table(), section);
}

std::vector<const BrakeThermalField*> FittedBrakeThermalFields() { return FittedFields(Table()); }

const BrakeThermalField* FindBrakeThermalField(std::string_view path) {
  return FindField(Table(), path);
}

}  // namespace hotlap::brake
