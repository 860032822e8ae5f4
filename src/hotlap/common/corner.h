#pragma once
/// @file
/// The four corners of a car. Order is fixed: fl, fr, rl, rr.

#include <array>
#include <optional>
#include <string_view>

namespace hotlap {

enum class Corner { kFrontLeft = 0, kFrontRight = 1, kRearLeft = 2, kRearRight = 3 };

inline constexpr std::array<Corner, 4> kAllCorners = {Corner::kFrontLeft, Corner::kFrontRight,
                                                      Corner::kRearLeft, Corner::kRearRight};

/// Short lower-case name used in files and column names: "fl", "fr", "rl", "rr".
constexpr std::string_view CornerName(Corner c) {
  constexpr std::array<std::string_view, 4> kNames = {"fl", "fr", "rl", "rr"};
  return kNames[static_cast<int>(c)];
}

constexpr int CornerIndex(Corner c) { return static_cast<int>(c); }

constexpr bool IsFront(Corner c) { return c == Corner::kFrontLeft || c == Corner::kFrontRight; }

/// Parses "fl", "fr", "rl" or "rr"; nullopt for anything else.
constexpr std::optional<Corner> ParseCorner(std::string_view name) {
  for (Corner c : kAllCorners) {
    if (CornerName(c) == name) return c;
  }
  return std::nullopt;
}

}  // namespace hotlap
