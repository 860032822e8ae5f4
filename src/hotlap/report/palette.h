#pragma once
/// @file
/// Colours for report charts. Each corner has one fixed colour, so fl is the same blue in every
/// chart of every report; other series take the palette in order (Tableau 10: distinct, readable
/// on white, kind to the common forms of colour blindness).

#include <array>
#include <cstddef>
#include <string_view>

#include "hotlap/common/corner.h"

namespace hotlap::report {

/// The default series colours, CSS hex, in the order they are handed out.
inline constexpr std::array<std::string_view, 10> kPalette = {
    "#4e79a7", "#f28e2b", "#e15759", "#76b7b2", "#59a14f",
    "#edc948", "#b07aa1", "#ff9da7", "#9c755f", "#bab0ac"};

/// The fixed colour of a corner: fl blue, fr red, rl green, rr orange.
constexpr std::string_view CornerColour(Corner c) {
  constexpr std::array<std::string_view, 4> kCorners = {"#4e79a7", "#e15759", "#59a14f", "#f28e2b"};
  return kCorners[static_cast<size_t>(CornerIndex(c))];
}

/// The i-th default colour, wrapping around after the last.
constexpr std::string_view PaletteColour(size_t i) { return kPalette[i % kPalette.size()]; }

}  // namespace hotlap::report
