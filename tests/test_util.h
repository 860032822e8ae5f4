#pragma once
/// @file
/// Small helpers shared by the tests: the repository's data folder, a fresh temporary folder per
/// test, text files in and out, a substring assertion for error messages, and central differences
/// to check automatic derivatives against.

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "hotlap/common/scalar.h"

namespace hotlap::test {

/// Every scalar the models are instantiated for (HOTLAP_FOR_EACH_SCALAR), for typed tests.
using AllScalarTypes = ::testing::Types<double, Jet2, Jet5, Jet7, Jet14>;

/// A path inside the source tree, e.g. SourcePath("data/cars/gen7/car.yaml"). Uses the compile
/// definition HOTLAP_SOURCE_DIR, never the working directory.
inline std::filesystem::path SourcePath(const std::string& relative) {
  return std::filesystem::path(HOTLAP_SOURCE_DIR) / relative;
}

/// The shipped gen7 car folder.
inline std::filesystem::path Gen7Dir() { return SourcePath("data/cars/gen7"); }

/// Whole file as a string; throws if it cannot be read.
inline std::string ReadTextFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("test: cannot read " + path.string());
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Writes `text` byte for byte to `path` (creating its folder) and returns the path.
inline std::filesystem::path WriteTextFile(const std::filesystem::path& path,
                                           const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

/// `text` with the first occurrence of `from` replaced by `to`; throws if `from` is absent, so a
/// test that edits a shipped file notices when that file changes under it.
inline std::string ReplaceOnce(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  if (at == std::string::npos) throw std::runtime_error("test: '" + from + "' not found");
  text.replace(at, from.size(), to);
  return text;
}

/// Passes when `text` contains `part`; prints both otherwise.
inline ::testing::AssertionResult Contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "'" << text << "' does not contain '" << part << "'";
}

/// The message of the InputError that `f()` throws; "" and a test failure if it throws none.
template <typename F>
std::string InputErrorOf(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError";
  return "";
}

/// Central difference of `f` with respect to the double that `select(x)` refers to, with a relative
/// step h = 1e-6 |value|: (f(x + h) - f(x - h)) / (2 h). `f` returns a double, or a std::array of
/// doubles that is differenced element by element.
template <class X, class Select, class F>
auto CentralDifference(const X& x, Select select, F f) {
  X up = x, down = x;
  const double h = 1e-6 * std::abs(select(up));
  select(up) += h;
  select(down) -= h;
  const auto fu = f(static_cast<const X&>(up));
  const auto fdn = f(static_cast<const X&>(down));
  if constexpr (std::is_floating_point_v<std::remove_cv_t<decltype(fu)>>) {
    return (fu - fdn) / (2 * h);
  } else {
    auto d = fu;
    for (std::size_t k = 0; k < d.size(); ++k) d[k] = (fu[k] - fdn[k]) / (2 * h);
    return d;
  }
}

/// Checks an automatic derivative `ad` against a central difference `fd` (CentralDifference).
/// With the relative step 1e-6 the truncation error is ~1e-12 relative and the rounding error
/// ~1e-16 / 1e-6 times (largest term / derivative); 1e-5 relative covers both, with an absolute
/// floor of 1e-9 of the quantity's `scale` for derivatives that are (near) zero.
inline void ExpectNearDerivative(double ad, double fd, double scale, const std::string& what) {
  EXPECT_NEAR(ad, fd, 1e-5 * std::max(std::abs(ad), std::abs(fd)) + 1e-9 * scale) << what;
}

/// A fresh folder under the system temp folder named after the running test (and the process),
/// removed with everything in it when the object goes away.
class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = info == nullptr ? std::string("no_test")
                                       : std::string(info->test_suite_name()) + "_" + info->name();
    std::replace_if(
        name.begin(), name.end(), [](unsigned char c) { return !std::isalnum(c) && c != '_'; },
        '_');
    path_ = std::filesystem::temp_directory_path() /
            ("hotlap_test_" + std::to_string(::getpid()) + "_" + name);
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  /// Writes `text` to `relative` inside the folder and returns the full path.
  std::filesystem::path Write(const std::string& relative, const std::string& text) const {
    return WriteTextFile(path_ / relative, text);
  }

 private:
  std::filesystem::path path_;
};

/// The inputs the fuzzers found that once crashed, hung or leaked in a reader (fuzz/,
/// docs/reliability.md): every file of tests/data/fuzz_regressions/TARGET, sorted. Each reader's
/// test replays its target's files and expects an InputError from each.
inline std::vector<std::filesystem::path> FuzzRegressions(const std::string& target) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry :
       std::filesystem::directory_iterator(SourcePath("tests/data/fuzz_regressions/" + target))) {
    files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace hotlap::test
