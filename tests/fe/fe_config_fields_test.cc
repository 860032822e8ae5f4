// The FE tyre file's field tables (fe/fe_config_fields.h): they list every number and count of
// the configuration once, each key reads back from the shipped file into its member in SI (the
// rubber regions and cords too), and a value outside a row's range is refused naming the file,
// field and range.

#include "hotlap/fe/fe_config_fields.h"

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "field_table_checks.h"
#include "hotlap/common/error.h"
#include "test_util.h"

namespace hotlap::fe {
namespace {

const std::filesystem::path kShipped = test::SourcePath("data/fe/paper_235_75r15.yaml");

// The file's value of `field` (a dotted path), read as the readers read numbers.
double FileValue(const std::string& field) {
  for (const YamlScalarField& s : ListYamlScalars(kShipped)) {
    if (s.field == field) return *ParseYamlNumber(s.text);
  }
  ADD_FAILURE() << field << " is not in " << kShipped;
  return 0.0;
}

// Every number and count of FeConfig a file sets (not the solver's and road's run-time members,
// which the steps set), each once.
std::vector<double> FileMemberValues(const FeConfig& c) {
  const TyreMeshOptions& m = c.mesh;
  return {c.size.section_width_m,
          c.size.aspect_ratio,
          c.size.rim_diameter_m,
          m.rim_width_m,
          m.flange_height_m,
          m.tread_half_width_m,
          m.crown_thickness_m,
          m.sidewall_thickness_m,
          m.bead_thickness_m,
          m.widest_point_fraction,
          m.profile_exponent,
          double(m.meridional_elements_half),
          double(m.thickness_elements),
          double(m.tread_layers),
          double(m.circumferential_elements_contact),
          double(m.circumferential_elements_rest),
          m.contact_sector_half_angle_deg,
          m.bead_volume_fraction,
          double(m.belt_plies),
          c.bulk_to_shear_ratio,
          c.solver.time_step_safety,
          c.solver.bulk_viscosity_linear,
          c.solver.bulk_viscosity_quadratic,
          c.solver.hourglass_stiffness,
          c.solver.hourglass_viscous,
          c.solver.mass_scaling_min_step_s,
          c.road.penalty_factor,
          c.road.tangential_penalty_factor,
          c.road.friction.static_coefficient,
          c.road.friction.kinetic_coefficient,
          c.road.friction.decay_s_per_m,
          c.rim_mass_kg,
          c.rim_inertia_kgm2,
          c.inflation_pressure_Pa,
          c.inflate.ramp_s,
          c.inflate.hold_s,
          c.inflate.damping_per_s,
          c.vertical_load_N,
          c.footprint.ramp_s,
          c.footprint.hold_s,
          c.footprint.damping_per_s,
          c.roll_speed_mps,
          c.roll_duration_s,
          c.abs_duration_s,
          c.history_interval_s,
          double(c.vtu_frames)};
}

TEST(FeConfigFields, EveryNumberAndCountIsListedOnce) {
  // A distinct value through each row; the members read back hold each value once (a member no
  // row names stays 0, one two rows name keeps only the later value).
  const std::span<const FeConfigField> fields = FeConfigFields();
  ASSERT_EQ(fields.size(), FileMemberValues(FeConfig{}).size());
  FeConfig c;  // a member no row names keeps its default, not one of the values set
  std::vector<double> expected;
  std::set<std::string> paths;
  for (size_t i = 0; i < fields.size(); ++i) {
    const double v = 1.0 + static_cast<double>(i);
    if (fields[i].IsCount()) {
      fields[i].count(c) = static_cast<int>(v);
    } else {
      fields[i].number(c) = v;
    }
    EXPECT_EQ(fields[i].Of(c), v) << fields[i].Path();
    expected.push_back(v);
    EXPECT_TRUE(paths.insert(fields[i].Path()).second) << fields[i].Path();
  }
  std::vector<double> got = FileMemberValues(c);
  std::sort(got.begin(), got.end());
  EXPECT_EQ(got, expected);
  // The rubber rows cover every file number of a Yeoh material; the cords' every number of a
  // rebar (the bulk modulus is derived, the name and response are not numbers).
  EXPECT_EQ((FeRubberFields().size() + 1) * sizeof(double), sizeof(YeohMaterial));
  const std::span<const FeCordField> cords = FeCordFields();
  ASSERT_EQ(cords.size(), 5u);  // modulus, density, area, spacing, angle
  for (size_t i = 0; i < cords.size(); ++i) {
    for (size_t k = i + 1; k < cords.size(); ++k) EXPECT_NE(cords[i].member, cords[k].member);
  }
  EXPECT_EQ(FeRubberRegions().size(), 6u);  // TyreRegion's six (002 Table 1)
  EXPECT_EQ(FeCordNames().size(), 4u);      // TyreCord's four (002 Tables 2-3)
}

TEST(FeConfigFields, EachKeyReadsBackFromTheShippedFileInSi) {
  const FeConfig c = LoadFeConfig(kShipped);
  for (const FeConfigField& f : FeConfigFields()) {
    EXPECT_EQ(f.Of(c), f.to_si * FileValue(f.Path())) << f.Path();
  }
  ASSERT_EQ(c.rubber.size(), FeRubberRegions().size());
  for (size_t r = 0; r < c.rubber.size(); ++r) {
    for (const FeRubberField& f : FeRubberFields()) {
      const std::string path =
          "rubber." + std::string(FeRubberRegions()[r]) + "." + std::string(f.key);
      EXPECT_EQ(c.rubber[r].*f.member, FileValue(path)) << path;
    }
    // The bulk modulus: bulk_to_shear_ratio (20) times the initial shear modulus 2 C10.
    EXPECT_DOUBLE_EQ(c.rubber[r].bulk_modulus_Pa, 20.0 * 2.0 * c.rubber[r].c10_Pa);
  }
  ASSERT_EQ(c.cords.size(), FeCordNames().size());
  for (size_t k = 0; k < c.cords.size(); ++k) {
    EXPECT_EQ(c.cords[k].name, FeCordNames()[k]);
    EXPECT_EQ(c.cords[k].response, FibreResponse::kTensionOnly);
    for (const FeCordField& f : FeCordFields()) {
      if (!f.bead_has_it && c.cords[k].name == "bead") continue;
      const std::string path = "cords." + c.cords[k].name + "." + std::string(f.key);
      EXPECT_EQ(c.cords[k].*f.member, FileValue(path)) << path;
    }
  }
  // The conversions by hand: 235 mm, 15 in, 220 kPa.
  EXPECT_DOUBLE_EQ(c.size.section_width_m, 0.235);
  EXPECT_DOUBLE_EQ(c.size.rim_diameter_m, 0.381);
  EXPECT_DOUBLE_EQ(c.inflation_pressure_Pa, 220e3);
  EXPECT_EQ(c.mesh.belt_plies, 2);
}

TEST(FeConfigFields, AValueOutsideItsRangeIsRefusedNamingFileFieldAndRange) {
  test::TempDir dir;
  // The ABS files named by absolute paths, so the copy in `dir` finds them.
  const auto set = [](YAML::Node& root, const FeConfigField& f, double value) {
    root["abs"]["config_file"] = test::SourcePath("data/abs/fe_tyre.yaml").string();
    root["abs"]["lumped_config_file"] = test::SourcePath("data/abs/paper.yaml").string();
    if (f.section.empty()) {
      root[std::string(f.key)] = value;
    } else {
      root[std::string(f.section)][std::string(f.key)] = value;
    }
  };
  const int checked = test::ExpectReaderErrorsNameFileFieldAndRange(
      FeConfigFields(), kShipped, dir, "bad.yaml", set,
      [](const std::filesystem::path& p) { LoadFeConfig(p); });
  EXPECT_EQ(checked, static_cast<int>(FeConfigFields().size()));  // every row has a finite bound
}

TEST(FeConfigFields, ACountThatIsNotWholeAndAnUnknownResponseAreRefused) {
  test::TempDir dir;
  std::string y = test::ReadTextFile(kShipped);
  y = test::ReplaceOnce(y, "config_file: ../abs/fe_tyre.yaml",
                        "config_file: " + test::SourcePath("data/abs/fe_tyre.yaml").string());
  const std::string half = test::ReplaceOnce(y, "tread_layers: 1 ", "tread_layers: 1.5 ");
  const std::string fractional =
      test::InputErrorOf([&] { LoadFeConfig(dir.Write("half.yaml", half)); });
  EXPECT_TRUE(test::Contains(fractional, "field 'mesh.tread_layers'")) << fractional;
  EXPECT_TRUE(test::Contains(fractional, "must be a whole number")) << fractional;
  const std::string stiff = test::ReplaceOnce(y, "response: tension_only, ", "response: stiff, ");
  const std::string unknown =
      test::InputErrorOf([&] { LoadFeConfig(dir.Write("stiff.yaml", stiff)); });
  EXPECT_TRUE(test::Contains(unknown, "cords.ply.response")) << unknown;
  EXPECT_TRUE(test::Contains(unknown, "linear")) << unknown;
}

}  // namespace
}  // namespace hotlap::fe
