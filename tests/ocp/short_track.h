#pragma once
// A short closed track for the mesh tests: a stadium whose two half circles (radius 80 m, flat)
// are entered and left by 60 m clothoids, between 100 m straights; 823 m, 12 m wide.

#include <cmath>

#include "hotlap/common/units.h"
#include "hotlap/track/track.h"

namespace hotlap::test {

inline track::Track ShortStadium() {
  using track::CubicHermite;
  const double radius = 80.0, clothoid = 60.0, straight = 100.0, k = 1.0 / radius;
  const auto piece = [](double length, CubicHermite kappa) {
    track::RibbonPiece p;
    p.length_m = length;
    p.curvature = kappa;
    p.bank = p.grade = CubicHermite::Constant(0.0);
    p.width_left = p.width_right = CubicHermite::Constant(6.0);
    return p;
  };
  const CubicHermite zero = CubicHermite::Constant(0.0);
  const CubicHermite in{0.0, k / clothoid, k, k / clothoid};
  const CubicHermite out{k, -k / clothoid, 0.0, -k / clothoid};
  const double arc = kPi * radius - clothoid;  // the clothoids turn clothoid / radius in all
  std::vector<track::RibbonPiece> pieces;
  for (int end = 0; end < 2; ++end) {
    pieces.push_back(piece(straight, zero));
    pieces.push_back(piece(clothoid, in));
    pieces.push_back(piece(arc, CubicHermite::Constant(k)));
    pieces.push_back(piece(clothoid, out));
  }
  return track::Track::FromPieces("short stadium", pieces, track::TrackStart{});
}

}  // namespace hotlap::test
