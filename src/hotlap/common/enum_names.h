#pragma once
/// @file
/// An enum's names as one table, from which its name function and its parser are made, so that
/// each enum lists its names once (rather than a switch for the name and a loop or an if-chain
/// for the parse). Usage:
///
///   constexpr EnumNames<SegmentType, 3> kSegmentTypes{{{SegmentType::kStraight, "straight"},
///                                                     {SegmentType::kArc, "arc"},
///                                                     {SegmentType::kClothoid, "clothoid"}}};
///   const char* SegmentTypeName(SegmentType t) { return kSegmentTypes.Name(t); }

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace hotlap {

template <class E, std::size_t N>
struct EnumNames {
  struct Entry {
    E value;
    const char* name;  ///< a literal: lives for the program
  };
  std::array<Entry, N> entries;

  /// The name of `value`; `unknown` for a value outside the table.
  constexpr const char* Name(E value, const char* unknown = "?") const {
    for (const Entry& e : entries) {
      if (e.value == value) return e.name;
    }
    return unknown;
  }

  /// The value named `name`, if any.
  constexpr std::optional<E> Find(std::string_view name) const {
    for (const Entry& e : entries) {
      if (name == e.name) return e.value;
    }
    return std::nullopt;
  }

  /// The names joined for a message: "a, b, c".
  std::string List(std::string_view separator = ", ") const {
    std::string out;
    for (const Entry& e : entries) {
      if (!out.empty()) out += separator;
      out += e.name;
    }
    return out;
  }
};

}  // namespace hotlap
