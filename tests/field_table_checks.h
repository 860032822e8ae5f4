#pragma once
/// @file
/// Checks shared by the tests of the parameter field tables (tyre/tyre_thermal_fields.h,
/// brake/brake_thermal_fields.h).

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "hotlap/common/error.h"
#include "test_util.h"

namespace hotlap::test {

/// Every member of Params is reached by exactly one row of `fields`: a distinct value is set
/// through each row, and the struct read back (`member_values(params)`, every member once) must
/// hold each value once (a member no row names stays 0; one that two rows name keeps only the
/// later value). The const accessor must read what the other one set.
template <class Params, class Fields, class MemberValues>
void ExpectEveryMemberCoveredOnce(const Fields& fields, MemberValues member_values) {
  ASSERT_EQ(fields.size(), member_values(Params{}).size());
  Params p{};
  std::vector<double> expected;
  for (size_t i = 0; i < fields.size(); ++i) {
    fields[i].Of(p) = 1.0 + static_cast<double>(i);
    expected.push_back(1.0 + static_cast<double>(i));
  }
  std::vector<double> got = member_values(p);
  std::sort(got.begin(), got.end());
  EXPECT_EQ(got, expected);
  const Params& c = p;
  for (size_t i = 0; i < fields.size(); ++i) {
    EXPECT_EQ(fields[i].Of(c), 1.0 + static_cast<double>(i)) << i;
  }
}

/// For every row with a finite bound: the YAML file `source` with that row's value set just
/// outside its range (`set(root, row, value)`), written as `name` in `dir`, must make
/// `load(path)` throw an InputError naming the file, "field 'PATH'" and the range. Returns the
/// rows checked.
template <class Fields, class Set, class Load>
int ExpectReaderErrorsNameFileFieldAndRange(const Fields& fields,
                                            const std::filesystem::path& source, TempDir& dir,
                                            const std::string& name, Set set, Load load) {
  int checked = 0;
  for (const auto& f : fields) {
    const double bad = std::isfinite(f.range.min) ? f.range.min - 1.0 : f.range.max + 1.0;
    if (!std::isfinite(bad)) continue;  // a row that takes any value
    YAML::Node root = YAML::LoadFile(source.string());
    set(root, f, bad);
    YAML::Emitter out;
    out << root;
    const std::filesystem::path path = dir.Write(name, out.c_str());
    std::string message;
    try {
      load(path);
    } catch (const InputError& e) {
      message = e.what();
    }
    EXPECT_TRUE(Contains(message, path.string())) << f.Path() << ": " << message;
    EXPECT_TRUE(Contains(message, "field '" + f.Path() + "'")) << f.Path() << ": " << message;
    EXPECT_TRUE(Contains(message, f.range.Describe())) << f.Path() << ": " << message;
    ++checked;
  }
  return checked;
}

}  // namespace hotlap::test
