#pragma once
/// @file
/// A hexahedral tyre generated from its size designation (002 §2.1.1, Figure 1; spec section 9).
///
/// The half cross-section (bead to centre plane) is built in the (axial y, radial r) plane:
/// its outer profile is two quarter super-ellipses meeting at the section's widest point
/// (section width at mid-height), from the crown (outer radius D / 2 at y = 0) to the bead seat
/// (rim radius plus the flange height, at half the rim width). The wall is offset inwards by a
/// thickness that is the crown thickness under the tread, the sidewall thickness on the flank
/// and grows to the bead thickness at the bead. The half section is mirrored about y = 0 and
/// revolved about the axle (+y); the circumferential elements are finer in a sector around the
/// contact patch (the bottom, -z).
///
/// Rubber regions (002 Table 1, six Yeoh materials), by position in the wall:
///   ply:       the innermost element layer (the carcass and the inner liner), bead to bead;
///   tread:     the outermost layer(s) over the crown (|y| below the tread half-width);
///   belt:      the layer between the ply and the tread over the crown;
///   sidewall:  the outer layers of the flank;
///   filler:    the middle and outer layers near the bead (the apex), except:
///   rim strip: the outermost layer nearest the bead, where the rim flange bears.
/// Cord layers (002 Tables 2-3): ply cords in the ply layer bead to bead (-2.28 deg from the
/// meridional direction: a radial ply), belt cords in the belt layer (-66.7 deg), chafer cords in
/// the rim-strip layer (44.6 deg), bead wire circumferential in the elements at the bead; with
/// belt_plies 2 the belt layer holds a second ply at the opposite angle (crossed belts). The
/// paper gives no bead area or spacing (Table 3 has no bead row): the bead's volume fraction is
/// a configuration value. The bead face nodes are tied to the rigid rim.
///
/// Coordinates: axle along +y, the tyre centre at the origin, the contact patch towards -z;
/// circumferential angle theta from -z towards +x.

#include <cstdint>

#include "hotlap/fe/mesh.h"

namespace hotlap::fe {

/// Indices of the rubber regions, in 002 Table 1's order (the materials vector follows it).
enum TyreRegion : std::uint8_t {
  kTread = 0,
  kSidewall = 1,
  kRimStrip = 2,
  kBelt = 3,
  kPly = 4,
  kFiller = 5,
  kTyreRegionCount = 6
};

/// Indices of the cord materials, in 002 Table 2's order (the rebar vector follows it).
enum TyreCord : std::uint8_t { kBeadCord = 0, kPlyCord = 1, kBeltCord = 2, kChaferCord = 3 };

/// The size designation, e.g. 235/75R15.
struct TyreSize {
  double section_width_m = 0.0;  ///< 0.235
  double aspect_ratio = 0.0;     ///< section height over width, 0.75
  double rim_diameter_m = 0.0;   ///< 15 in = 0.381 m

  double SectionHeight() const { return section_width_m * aspect_ratio; }
  /// Overall (unloaded) diameter, m: rim + 2 section heights (733.5 mm for 235/75R15).
  double OverallDiameter() const { return rim_diameter_m + 2.0 * SectionHeight(); }
};

/// Profile and mesh density. Lengths in metres.
struct TyreMeshOptions {
  double rim_width_m = 0.0;            ///< bead-to-bead width at the seat
  double flange_height_m = 0.0;        ///< bead seat above the rim diameter
  double tread_half_width_m = 0.0;     ///< crown region |y| < this
  double crown_thickness_m = 0.0;      ///< wall thickness under the tread
  double sidewall_thickness_m = 0.0;   ///< flank thickness
  double bead_thickness_m = 0.0;       ///< wall thickness at the bead
  double widest_point_fraction = 0.0;  ///< height of the widest point over the section height
  double profile_exponent = 0.0;       ///< super-ellipse exponent (2: ellipse; larger: squarer)
  int meridional_elements_half = 0;    ///< elements from the bead to the centre plane
  int thickness_elements = 0;          ///< element layers through the wall (>= 3)
  int tread_layers = 0;                ///< of which in the tread (>= 1)
  int circumferential_elements_contact = 0;    ///< elements in the contact sector
  int circumferential_elements_rest = 0;       ///< elements in the rest of the circle
  double contact_sector_half_angle_deg = 0.0;  ///< the finer sector, each side of -z
  double bead_volume_fraction = 0.0;           ///< bead wire in the bead elements (assumed), 1
  /// Belt plies: 1 (002 Table 3's single row) or 2 (crossed at +-angle, the usual construction).
  int belt_plies = 0;
};

/// The generated tyre: the mesh and what the steps need to know about it.
struct TyreMesh {
  Mesh mesh;
  double outer_radius_m = 0.0;                  ///< unloaded outer radius at the centre plane
  int section_nodes = 0;                        ///< nodes in one cross-section
  int sections = 0;                             ///< cross-sections around the circle
  std::vector<int> crown_centre_nodes;          ///< outer node on y = 0 in each section
  std::vector<double> section_angle_rad;        ///< theta of each section
  std::vector<std::array<int, 4>> outer_faces;  ///< the tread and sidewall outer surface
};

/// Generates the tyre. `rebars` (002 Tables 2-3 order) give the cord sheet thicknesses A / s.
/// Throws InputError when the options cannot make a valid mesh.
TyreMesh MakeTyreMesh(const TyreSize& size, const TyreMeshOptions& options,
                      const std::vector<RebarMaterial>& rebars);

}  // namespace hotlap::fe
