#include "hotlap/fe/tyre_mesh.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include <Eigen/Geometry>

#include "hotlap/common/error.h"

namespace hotlap::fe {

namespace {

using Eigen::Vector2d;  // (y, r)
using Eigen::Vector3d;

double SmoothStep(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3.0 - 2.0 * x);
}

// The outer half-profile from the crown centre (y = 0) to the bead seat, densely sampled.
std::vector<Vector2d> OuterProfile(const TyreSize& size, const TyreMeshOptions& o) {
  const double ro = 0.5 * size.OverallDiameter();
  const double a = 0.5 * size.section_width_m;
  const double rm = 0.5 * size.rim_diameter_m + o.widest_point_fraction * size.SectionHeight();
  const double rb = 0.5 * size.rim_diameter_m + o.flange_height_m;
  const double yb = 0.5 * o.rim_width_m;
  const double e = 2.0 / o.profile_exponent;
  const int n = 4000;
  std::vector<Vector2d> p;
  for (int i = 0; i <= n; ++i) {  // crown to the widest point
    const double phi = 0.5 * std::numbers::pi * i / n;
    p.emplace_back(a * std::pow(std::sin(phi), e), rm + (ro - rm) * std::pow(std::cos(phi), e));
  }
  for (int i = 1; i <= n; ++i) {  // widest point to the bead
    const double psi = 0.5 * std::numbers::pi * i / n;
    p.emplace_back(yb + (a - yb) * std::pow(std::cos(psi), e),
                   rm - (rm - rb) * std::pow(std::sin(psi), e));
  }
  return p;
}

void Require(bool ok, const std::string& what) {
  if (!ok) throw InputError("fe tyre mesh: " + what);
}

void CheckOptions(const TyreSize& size, const TyreMeshOptions& o,
                  const std::vector<RebarMaterial>& rebars) {
  Require(o.thickness_elements >= 3, "thickness_elements must be at least 3");
  Require(o.tread_layers >= 1 && o.tread_layers <= o.thickness_elements - 2,
          "tread_layers must be in [1, thickness_elements - 2]");
  Require(o.meridional_elements_half >= 4, "meridional_elements_half must be at least 4");
  Require(o.circumferential_elements_contact >= 1 && o.circumferential_elements_rest >= 3,
          "circumferential element counts too small");
  Require(0.5 * o.rim_width_m < 0.5 * size.section_width_m,
          "rim width must be below the section width");
  Require(o.belt_plies == 1 || o.belt_plies == 2, "belt_plies must be 1 or 2");
  Require(rebars.size() == 4, "four cord materials expected (bead, ply, belt, chafer)");
}

// The section's nodes in (y, r): half[m][k] is station m from the crown centre (0) to the bead
// (nm), layer k inner -> outer; the full section runs I = 0 (bead at -y) .. 2 nm (bead at +y).
struct Section {
  std::vector<std::vector<Vector2d>> half;
  int nm = 0, nt = 0, ni = 0;
  Vector2d yr(int I, int k) const {
    const int m = std::abs(I - nm);
    Vector2d p = half[m][k];
    if (I < nm) p.x() = -p.x();
    return p;
  }
};

// Meridional stations, evenly spaced in arc length along the outer profile, each with the wall
// thickness of its place.
Section MakeSection(const TyreSize& size, const TyreMeshOptions& o) {
  const std::vector<Vector2d> prof = OuterProfile(size, o);
  std::vector<double> s(prof.size(), 0.0);
  for (size_t i = 1; i < prof.size(); ++i) s[i] = s[i - 1] + (prof[i] - prof[i - 1]).norm();
  const double length = s.back();
  Section sec;
  sec.nm = o.meridional_elements_half;
  sec.nt = o.thickness_elements;
  sec.ni = 2 * sec.nm + 1;
  const int nm = sec.nm, nt = sec.nt;
  sec.half.assign(nm + 1, std::vector<Vector2d>(nt + 1));
  for (int m = 0; m <= nm; ++m) {
    const double target = length * m / nm;
    const size_t i =
        std::min<size_t>(std::lower_bound(s.begin(), s.end(), target) - s.begin(), prof.size() - 1);
    const size_t i0 = i == 0 ? 0 : i - 1, i1 = i == 0 ? 1 : i;
    const double w =
        (s[i1] > s[i0]) ? std::clamp((target - s[i0]) / (s[i1] - s[i0]), 0.0, 1.0) : 0.0;
    const Vector2d outer = (1 - w) * prof[i0] + w * prof[i1];
    const Vector2d tangent = (prof[i1] - prof[i0]).normalized();
    const Vector2d inward(tangent.y(), -tangent.x());  // (y, r): crown tangent (1, 0) -> (0, -1)
    // Wall thickness: crown, blending to the flank past the tread edge, then to the bead.
    const double tw = o.tread_half_width_m;
    double t =
        o.sidewall_thickness_m + (o.crown_thickness_m - o.sidewall_thickness_m) *
                                     (1.0 - SmoothStep((outer.x() - 0.85 * tw) / (0.3 * tw)));
    t += (o.bead_thickness_m - t) * SmoothStep((target / length - 0.7) / 0.3);
    const Vector2d inner = outer + t * inward;
    for (int k = 0; k <= nt; ++k) sec.half[m][k] = inner + (double(k) / nt) * (outer - inner);
    if (m == 0) {
      for (int k = 0; k <= nt; ++k) sec.half[m][k].x() = 0.0;  // on the centre plane, exactly
    }
  }
  Require(sec.half[nm][0].x() > 0.0, "the bead's inner corner crosses the centre plane");
  return sec;
}

// Sections around the circle: a finer sector about theta = 0 (-z, the contact patch).
std::vector<double> SectionAngles(const TyreMeshOptions& o) {
  const double tc = o.contact_sector_half_angle_deg * std::numbers::pi / 180.0;
  const int nc1 = o.circumferential_elements_contact, nc2 = o.circumferential_elements_rest;
  std::vector<double> theta;
  for (int j = 0; j < nc1; ++j) theta.push_back(-tc + 2.0 * tc * j / nc1);
  for (int j = 0; j < nc2; ++j) theta.push_back(tc + (2.0 * std::numbers::pi - 2.0 * tc) * j / nc2);
  return theta;
}

// The mesh being built: its section, the node numbering round the circle, and the output.
class MeshBuilder {
 public:
  MeshBuilder(const TyreSize& size, const TyreMeshOptions& o,
              const std::vector<RebarMaterial>& rebars)
      : size_(size), o_(o), rebars_(rebars), sec_(MakeSection(size, o)) {
    const std::vector<double> theta = SectionAngles(o);
    nc_ = static_cast<int>(theta.size());
    out_.outer_radius_m = sec_.half[0][sec_.nt].y();
    out_.section_nodes = sec_.ni * (sec_.nt + 1);
    out_.sections = nc_;
    out_.section_angle_rad = theta;
  }
  TyreMesh Build() {
    AddNodes();
    AddElements();
    AddRimAndContactNodes();
    return std::move(out_);
  }

 private:
  int node(int j, int I, int k) const { return ((j % nc_) * sec_.ni + I) * (sec_.nt + 1) + k; }
  // Element (j, I, k): xi along I, eta through the wall, zeta around.
  std::array<int, 8> hex(int j, int I, int k) const {
    return std::array<int, 8>{
        node(j, I, k),     node(j, I + 1, k),     node(j, I + 1, k + 1),     node(j, I, k + 1),
        node(j + 1, I, k), node(j + 1, I + 1, k), node(j + 1, I + 1, k + 1), node(j + 1, I, k + 1)};
  }
  void AddNodes();
  void AddElements();
  // Element (j, I, k) with its cords and its outer and inner (pressure) faces.
  void AddElement(int j, int I, int k, bool flip);
  void AddRimAndContactNodes();

  const TyreSize& size_;
  const TyreMeshOptions& o_;
  const std::vector<RebarMaterial>& rebars_;
  const Section sec_;
  int nc_ = 0;
  TyreMesh out_;
};

void MeshBuilder::AddNodes() {
  const std::vector<double>& theta = out_.section_angle_rad;
  for (int j = 0; j < nc_; ++j) {
    for (int I = 0; I < sec_.ni; ++I) {
      for (int k = 0; k <= sec_.nt; ++k) {
        const Vector2d yr = sec_.yr(I, k);
        out_.mesh.nodes.emplace_back(yr.y() * std::sin(theta[j]), yr.x(),
                                     -yr.y() * std::cos(theta[j]));
      }
    }
    out_.crown_centre_nodes.push_back(node(j, sec_.nm, sec_.nt));
  }
}

void MeshBuilder::AddElements() {
  // Flip every element if the numbering is left-handed.
  const auto& x = out_.mesh.nodes;
  const std::array<int, 8> h = hex(0, 0, 0);
  const bool flip = (x[h[1]] - x[h[0]]).cross(x[h[3]] - x[h[0]]).dot(x[h[4]] - x[h[0]]) < 0.0;
  for (int j = 0; j < nc_; ++j) {
    for (int I = 0; I + 1 < sec_.ni; ++I) {
      for (int k = 0; k < sec_.nt; ++k) AddElement(j, I, k, flip);
    }
  }
}

void MeshBuilder::AddElement(int j, int I, int k, bool flip) {
  Mesh& mesh = out_.mesh;
  const auto& x = mesh.nodes;
  const int nm = sec_.nm, nt = sec_.nt, ni = sec_.ni;
  const double s_frac = std::abs(I + 0.5 - nm) / nm;  // 0 at the crown centre, 1 at the bead
  const double y_outer = 0.5 * std::abs(sec_.yr(I, nt).x() + sec_.yr(I + 1, nt).x());
  const bool crown = y_outer < o_.tread_half_width_m;
  const bool bead_zone = s_frac > 0.8;
  const std::array<int, 8> h = hex(j, I, k);
  int region = kSidewall;
  if (k == 0) {
    region = kPly;
  } else if (crown) {
    region = k >= nt - o_.tread_layers ? kTread : kBelt;
  } else if (bead_zone) {
    region = (k == nt - 1 && s_frac > 0.9) ? kRimStrip : kFiller;
  }
  const int e = static_cast<int>(mesh.elements.size());
  std::array<int, 8> oriented = h;
  if (flip) {
    for (int a = 0; a < 4; ++a) std::swap(oriented[a], oriented[a + 4]);
  }
  mesh.elements.push_back(oriented);
  mesh.element_material.push_back(region);

  // Local directions at the element centre: meridional (increasing I), circumferential,
  // through the wall; the layer thickness for the sheet volume fractions.
  const Vector3d c_in = 0.25 * (x[h[0]] + x[h[1]] + x[h[4]] + x[h[5]]);
  const Vector3d c_out = 0.25 * (x[h[2]] + x[h[3]] + x[h[6]] + x[h[7]]);
  const Vector3d em =
      (0.25 * (x[h[1]] + x[h[2]] + x[h[5]] + x[h[6]] - x[h[0]] - x[h[3]] - x[h[4]] - x[h[7]]))
          .normalized();
  Vector3d ec =
      0.25 * (x[h[4]] + x[h[5]] + x[h[6]] + x[h[7]] - x[h[0]] - x[h[1]] - x[h[2]] - x[h[3]]);
  ec = (ec - ec.dot(em) * em).normalized();
  const double layer = (c_out - c_in).norm();
  const auto add = [&](int cord, const Vector3d& dir, double fraction) {
    Require(fraction < 0.5, "a cord layer fills half of an element: refine less or thicken");
    mesh.fibres.push_back({e, cord, dir, fraction});
  };
  const auto angle_dir = [&](double deg) {
    const double a = deg * std::numbers::pi / 180.0;
    return Vector3d(std::cos(a) * em + std::sin(a) * ec).normalized();
  };
  const auto sheet = [&](int cord) { return rebars_[cord].SheetThickness() / layer; };
  if (region == kPly) {
    add(kPlyCord, angle_dir(rebars_[kPlyCord].angle_deg), sheet(kPlyCord));
  } else if (region == kBelt) {
    add(kBeltCord, angle_dir(rebars_[kBeltCord].angle_deg), sheet(kBeltCord));
    if (o_.belt_plies == 2) {
      add(kBeltCord, angle_dir(-rebars_[kBeltCord].angle_deg), sheet(kBeltCord));
    }
  } else if (region == kRimStrip) {
    add(kChaferCord, angle_dir(rebars_[kChaferCord].angle_deg), sheet(kChaferCord));
  }
  if ((I == 0 || I + 2 == ni) && k > 0 && o_.bead_volume_fraction > 0.0) {
    add(kBeadCord, ec, o_.bead_volume_fraction);
  }
  if (k == nt - 1) {
    out_.outer_faces.push_back(
        {node(j, I, nt), node(j, I + 1, nt), node(j + 1, I + 1, nt), node(j + 1, I, nt)});
  }
  if (k == 0) {
    // Inner face, oriented to point out of the solid (into the cavity).
    std::array<int, 4> f = {node(j, I, 0), node(j, I + 1, 0), node(j + 1, I + 1, 0),
                            node(j + 1, I, 0)};
    const Vector3d area = (x[f[2]] - x[f[0]]).cross(x[f[3]] - x[f[1]]);
    if (area.dot(c_in - c_out) < 0.0) std::swap(f[1], f[3]);
    mesh.pressure_faces.push_back(f);
  }
}

void MeshBuilder::AddRimAndContactNodes() {
  Mesh& mesh = out_.mesh;
  for (int j = 0; j < nc_; ++j) {
    for (int k = 0; k <= sec_.nt; ++k) {
      mesh.rim_nodes.push_back(node(j, 0, k));
      mesh.rim_nodes.push_back(node(j, sec_.ni - 1, k));
    }
    for (int I = 0; I < sec_.ni; ++I) {
      const Vector2d yr = sec_.yr(I, sec_.nt);
      if (std::abs(yr.x()) < 0.5 * size_.section_width_m * 0.999 &&
          yr.y() > 0.5 * size_.rim_diameter_m + 0.5 * size_.SectionHeight()) {
        mesh.contact_nodes.push_back(node(j, I, sec_.nt));
      }
    }
  }
}

}  // namespace

TyreMesh MakeTyreMesh(const TyreSize& size, const TyreMeshOptions& o,
                      const std::vector<RebarMaterial>& rebars) {
  CheckOptions(size, o, rebars);
  return MeshBuilder(size, o, rebars).Build();
}

}  // namespace hotlap::fe
