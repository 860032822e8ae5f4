// The layer rule of docs/architecture.md, checked on the source tree: a file under
// src/hotlap/<area>/ includes only headers of its own area and of the areas its layer may use.
// A new area must be given a layer here (and in docs/architecture.md) before it can pass.

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "test_util.h"

namespace hotlap {
namespace {

namespace fs = std::filesystem;

// One area of src/hotlap/: its level, and, where narrower than "every lower level", the only
// areas it may include.
struct Area {
  int level = 0;
  std::optional<std::set<std::string>> only;
};

// docs/architecture.md's table. Imports point down only: an area includes its own headers and
// those of areas on a lower level; areas on the same level do not include each other.
const std::map<std::string, Area>& Layers() {
  static const std::map<std::string, Area> layers = {
      {"common", {0, {}}},
      {"tyre", {1, {}}},
      {"brake", {1, {}}},
      {"report", {1, std::set<std::string>{"common"}}},
      {"logs", {1, std::set<std::string>{"common"}}},
      {"vehicle", {2, {}}},
      {"track", {2, {}}},
      {"fe", {2, std::set<std::string>{"common", "tyre"}}},
      {"sim", {3, {}}},
      {"abs", {3, std::set<std::string>{"common", "tyre", "brake", "report", "fe"}}},
      {"ident", {4, {}}},
      {"ocp", {4, {}}},
      {"race", {4, {}}},
      {"observe", {4, {}}},
      {"runs", {5, {}}},
  };
  return layers;
}

bool MayInclude(const std::string& from, const std::string& to) {
  if (from == to) return true;
  const auto a = Layers().find(from);
  const auto b = Layers().find(to);
  if (a == Layers().end() || b == Layers().end()) return false;
  if (a->second.only) return a->second.only->count(to) > 0;
  return b->second.level < a->second.level;
}

// Every include of a hotlap header that breaks the rule, as "FILE:LINE: includes HEADER (AREA
// level A may not use AREA level B)", and every area folder the table does not place.
std::vector<std::string> LayerViolations(const fs::path& src_root) {
  static const std::regex kInclude(R"(^\s*#\s*include\s*[<"]hotlap/([A-Za-z0-9_]+)/([^>"]+)[>"])");
  std::vector<std::string> out;
  for (const fs::directory_entry& dir : fs::directory_iterator(src_root)) {
    if (!dir.is_directory()) continue;
    const std::string area = dir.path().filename().string();
    if (!Layers().count(area)) {
      out.push_back(dir.path().string() + ": area '" + area +
                    "' has no layer (add it to docs/architecture.md and this test)");
      continue;
    }
    for (const fs::directory_entry& f : fs::recursive_directory_iterator(dir.path())) {
      const std::string ext = f.path().extension().string();
      if (!f.is_regular_file() || (ext != ".h" && ext != ".cc")) continue;
      std::ifstream in(f.path());
      std::string line;
      for (int n = 1; std::getline(in, line); ++n) {
        std::smatch m;
        if (!std::regex_search(line, m, kInclude)) continue;
        const std::string to = m[1].str();
        if (MayInclude(area, to)) continue;
        const auto level = [](const std::string& a) {
          const auto it = Layers().find(a);
          return it == Layers().end() ? std::string("?") : std::to_string(it->second.level);
        };
        out.push_back(f.path().string() + ":" + std::to_string(n) + ": includes hotlap/" + to +
                      "/" + m[2].str() + " (" + area + ", level " + level(area) + ", may not use " +
                      to + ", level " + level(to) + ")");
      }
    }
  }
  return out;
}

// The headers CMakeLists.txt keeps to the library (HOTLAP_INTERNAL_HEADERS, not installed), as
// "area/file.h".
std::set<std::string> InternalHeaders(const fs::path& cmake_lists) {
  std::ifstream in(cmake_lists);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::set<std::string> out;
  const size_t start = text.find("set(HOTLAP_INTERNAL_HEADERS");
  if (start == std::string::npos) return out;
  const std::string list = text.substr(start, text.find(')', start) - start);
  static const std::regex kHeader(R"(([A-Za-z0-9_]+/[A-Za-z0-9_]+\.h))");
  for (std::sregex_iterator it(list.begin(), list.end(), kHeader), end; it != end; ++it) {
    out.insert((*it)[1].str());
  }
  return out;
}

// Every include of a binding file (python/src) that is neither an area's public header
// ("hotlap/<area>/<file>.h" that exists and is not internal) nor one of the bindings' own files,
// as "FILE:LINE: includes HEADER (why)". The bindings reach the library only through the runs
// layer and the areas' public headers, as any other user of the installed package would.
std::vector<std::string> BindingViolations(const fs::path& binding_root, const fs::path& src_root,
                                           const std::set<std::string>& internal) {
  static const std::regex kAnyInclude(R"(^\s*#\s*include\s*([<"])([^>"]+)[>"])");
  static const std::regex kHotlap(R"(hotlap/([A-Za-z0-9_]+)/([^/]+))");
  std::vector<std::string> out;
  for (const fs::directory_entry& f : fs::recursive_directory_iterator(binding_root)) {
    const std::string ext = f.path().extension().string();
    if (!f.is_regular_file() || (ext != ".h" && ext != ".cc")) continue;
    std::ifstream in(f.path());
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
      std::smatch m;
      if (!std::regex_search(line, m, kAnyInclude)) continue;
      const std::string header = m[2].str();
      const std::string where =
          f.path().string() + ":" + std::to_string(n) + ": includes " + header;
      std::smatch h;
      if (std::regex_match(header, h, kHotlap)) {
        const std::string area = h[1].str(), relative = area + "/" + h[2].str();
        if (!Layers().count(area)) {
          out.push_back(where + " (no area '" + area + "')");
        } else if (internal.count(relative)) {
          out.push_back(where + " (internal to the library: HOTLAP_INTERNAL_HEADERS)");
        } else if (!fs::exists(src_root / relative)) {
          out.push_back(where + " (no such header in src/hotlap)");
        }
      } else if (m[1].str() == "\"" && !fs::exists(f.path().parent_path() / header)) {
        out.push_back(where + " (neither an area's header nor one of the bindings' own)");
      }
    }
  }
  return out;
}

TEST(Layers, SourceTreeKeepsTheLayerRule) {
  const std::vector<std::string> violations = LayerViolations(test::SourcePath("src/hotlap"));
  std::string all;
  for (const std::string& v : violations) all += v + "\n";
  EXPECT_TRUE(violations.empty()) << all;
}

TEST(Layers, UpwardAndSidewaysIncludesAreFound) {
  test::TempDir dir;
  const fs::path root = dir.path() / "src/hotlap";
  test::WriteTextFile(root / "tyre/ok.cc", "#include \"hotlap/tyre/ok.h\"\n#include <vector>\n");
  test::WriteTextFile(root / "tyre/up.cc", "// x\n#include \"hotlap/vehicle/car.h\"\n");
  test::WriteTextFile(root / "tyre/side.h", "#include <hotlap/brake/brake_thermal.h>\n");
  test::WriteTextFile(root / "fe/mesh.cc",
                      "#include \"hotlap/tyre/rubber.h\"\n#  include \"hotlap/brake/x.h\"\n");
  test::WriteTextFile(root / "ocp/lap.cc", "#include \"hotlap/sim/qss_lap.h\"\n");
  test::WriteTextFile(root / "sim/run.cc", "#include \"hotlap/ident/fit_log.h\"\n");
  test::WriteTextFile(root / "gui/window.cc", "\n");
  const std::vector<std::string> v = LayerViolations(root);
  std::string all;
  for (const std::string& s : v) all += s + "\n";
  ASSERT_EQ(v.size(), 5u) << all;
  EXPECT_TRUE(test::Contains(all,
                             "up.cc:2: includes hotlap/vehicle/car.h (tyre, level 1, may "
                             "not use vehicle, level 2)"));
  EXPECT_TRUE(test::Contains(all, "side.h:1: includes hotlap/brake/brake_thermal.h"));
  EXPECT_TRUE(test::Contains(all, "mesh.cc:2: includes hotlap/brake/x.h (fe"));
  EXPECT_TRUE(test::Contains(all, "run.cc:1: includes hotlap/ident/fit_log.h (sim, level 3"));
  EXPECT_TRUE(test::Contains(all, "area 'gui' has no layer"));
}

TEST(Layers, PythonBindingsIncludeOnlyTheRunsAndTheAreasPublicHeaders) {
  const std::set<std::string> internal = InternalHeaders(test::SourcePath("CMakeLists.txt"));
  ASSERT_TRUE(internal.count("ident/channel_fit_internal.h"));  // the list was found
  const std::vector<std::string> violations =
      BindingViolations(test::SourcePath("python/src"), test::SourcePath("src/hotlap"), internal);
  std::string all;
  for (const std::string& v : violations) all += v + "\n";
  EXPECT_TRUE(violations.empty()) << all;
}

TEST(Layers, BindingIncludesOfInternalOrUnknownHeadersAreFound) {
  test::TempDir dir;
  const fs::path src = dir.path() / "src/hotlap", py = dir.path() / "python/src";
  test::WriteTextFile(src / "runs/lap_run.h", "\n");
  test::WriteTextFile(src / "ident/fit_internal.h", "\n");
  test::WriteTextFile(py / "own.h", "\n");
  test::WriteTextFile(py / "py_ok.cc",
                      "#include <pybind11/pybind11.h>\n#include \"hotlap/runs/lap_run.h\"\n"
                      "#include \"own.h\"\n");
  test::WriteTextFile(
      py / "py_bad.cc",
      "#include \"hotlap/ident/fit_internal.h\"\n#include \"hotlap/gui/w.h\"\n"
      "#include \"hotlap/runs/missing.h\"\n#include \"../../apps/hotlap/commands.h\"\n");
  const std::vector<std::string> v = BindingViolations(py, src, {"ident/fit_internal.h"});
  std::string all;
  for (const std::string& s : v) all += s + "\n";
  ASSERT_EQ(v.size(), 4u) << all;
  EXPECT_TRUE(test::Contains(all, "py_bad.cc:1: includes hotlap/ident/fit_internal.h (internal"));
  EXPECT_TRUE(test::Contains(all, "py_bad.cc:2: includes hotlap/gui/w.h (no area 'gui')"));
  EXPECT_TRUE(test::Contains(all, "py_bad.cc:3: includes hotlap/runs/missing.h (no such header"));
  EXPECT_TRUE(test::Contains(all, "py_bad.cc:4: includes ../../apps/hotlap/commands.h (neither"));
}

}  // namespace
}  // namespace hotlap
