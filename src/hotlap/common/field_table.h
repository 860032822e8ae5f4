#pragma once
/// @file
/// Look-ups over a parameter set's field table (tyre/tyre_thermal_fields.h,
/// brake/brake_thermal_fields.h): a table is a span of entries, each with a `section`, a `key`,
/// a `Path()`, an optional `fit` hint and an optional `to_si` conversion of the file's value.

#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace hotlap {

/// The entries of `table` in `section`, in table order.
template <class Field>
std::vector<const Field*> FieldsIn(std::span<const Field> table, std::string_view section) {
  std::vector<const Field*> out;
  for (const Field& f : table) {
    if (f.section == section) out.push_back(&f);
  }
  return out;
}

/// The entries of `table` with a fit hint, in table order; with `section` given, only those in it.
template <class Field>
std::vector<const Field*> FittedFields(std::span<const Field> table,
                                       std::optional<std::string_view> section = std::nullopt) {
  std::vector<const Field*> out;
  for (const Field& f : table) {
    if (f.fit && (!section || f.section == *section)) out.push_back(&f);
  }
  return out;
}

/// The entry of `table` whose Path() is `path`, or nullptr.
template <class Field>
const Field* FindField(std::span<const Field> table, std::string_view path) {
  for (const Field& f : table) {
    if (f.Path() == path) return &f;
  }
  return nullptr;
}

/// The SI value of `field` for the value `file_value` written in its file.
template <class Field>
double FieldToSi(const Field& field, double file_value) {
  return field.to_si ? field.to_si(file_value) : file_value;
}

}  // namespace hotlap
