#pragma once
/// @file
/// One point of a track's ribbon, and the ribbon's local frame there.
///
/// Conventions (spec section 10, ISO 8855 axes: x forward, y left, z up):
/// - `s_m` is the distance along the centre line from the start/finish line.
/// - `heading_rad` is the direction of the centre line's horizontal projection, anticlockwise from
///   the world x axis; continuous along the lap (it ends 2 pi * winding above where it starts).
/// - `curvature_per_m` is the horizontal curvature kappa_h = d heading / ds: positive turning left.
///   An anticlockwise oval has kappa_h > 0 in every turn.
/// - `bank_rad` is the ribbon's cross slope, positive when the left edge is lower than the right
///   edge. On an anticlockwise oval the left is the inside, so positive banking is "outside edge
///   up" as in spec section 10 and as on every oval's turns. (Rotating the ribbon about its
///   forward axis by the ISO 8855 roll angle phi gives bank = -phi.)
/// - `grade_rad` is the centre line's slope, positive uphill in the direction of travel.
/// - Widths are measured in the ribbon plane from the centre line to the left and right edges.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>

namespace hotlap::track {

/// The ribbon at one distance along the centre line. Units in the names; see the file comment.
struct TrackPoint {
  double s_m = 0.0;                    ///< distance from the start/finish line, in [0, length)
  double x_m = 0.0;                    ///< centre line, world frame
  double y_m = 0.0;                    ///< centre line, world frame (y left of x)
  double z_m = 0.0;                    ///< centre line height, world frame
  double heading_rad = 0.0;            ///< anticlockwise from world x, continuous over the lap
  double curvature_per_m = 0.0;        ///< kappa_h = d heading/ds, positive turning left
  double curvature_rate_per_m2 = 0.0;  ///< d kappa_h / ds
  double bank_rad = 0.0;               ///< cross slope, positive = left edge down (outside up)
  double bank_rate_per_m = 0.0;        ///< d bank / ds
  double grade_rad = 0.0;              ///< longitudinal slope, positive uphill
  double width_left_m = 0.0;           ///< centre line to left edge, in the ribbon plane
  double width_right_m = 0.0;          ///< centre line to right edge, in the ribbon plane
};

/// In-plane (geodesic) curvature of the centre line in the banked ribbon, kappa_g = kappa_h
/// cos(bank), 1/m, positive turning left (spec section 10). This is what a car following the
/// centre line must turn by in the road plane: m u^2 kappa_g is the in-plane lateral force.
inline double GeodesicCurvature(const TrackPoint& p) {
  return p.curvature_per_m * std::cos(p.bank_rad);
}

/// Normal curvature of the centre line, kappa_n = kappa_h sin(bank), 1/m (spec section 10).
/// Positive when the turn presses the car into the road (turning left on a ribbon banked left
/// edge down): it adds m u^2 kappa_n to the normal load.
inline double NormalCurvature(const TrackPoint& p) {
  return p.curvature_per_m * std::sin(p.bank_rad);
}

/// Unit tangent of the centre line (direction of travel), world frame.
inline Eigen::Vector3d TangentUnit(const TrackPoint& p) {
  const double cg = std::cos(p.grade_rad);
  return {cg * std::cos(p.heading_rad), cg * std::sin(p.heading_rad), std::sin(p.grade_rad)};
}

/// Unit vector in the ribbon plane, perpendicular to the tangent, pointing to the left edge.
/// With zero grade it is (-sin(heading) cos(bank), cos(heading) cos(bank), -sin(bank)): it dips
/// below horizontal for positive bank (left edge down).
inline Eigen::Vector3d LateralUnit(const TrackPoint& p) {
  const double sh = std::sin(p.heading_rad), ch = std::cos(p.heading_rad);
  const double sg = std::sin(p.grade_rad), cg = std::cos(p.grade_rad);
  const Eigen::Vector3d left_horizontal(-sh, ch, 0.0);
  const Eigen::Vector3d up_unbanked(-sg * ch, -sg * sh, cg);  // tangent x left_horizontal
  return std::cos(p.bank_rad) * left_horizontal - std::sin(p.bank_rad) * up_unbanked;
}

/// Unit normal of the ribbon plane, pointing away from the road (up). Tangent, lateral and
/// normal form a right-handed frame (x forward, y left, z up of ISO 8855).
inline Eigen::Vector3d NormalUnit(const TrackPoint& p) {
  return TangentUnit(p).cross(LateralUnit(p));
}

/// World position of the point at lateral offset `n_m` from the centre line, in the ribbon plane
/// (positive left; `width_left_m` gives the left edge, `-width_right_m` the right edge).
inline Eigen::Vector3d PointAtOffset(const TrackPoint& p, double n_m) {
  return Eigen::Vector3d(p.x_m, p.y_m, p.z_m) + n_m * LateralUnit(p);
}

}  // namespace hotlap::track
