#include "hotlap/common/data_path.h"

#include <dlfcn.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#include "hotlap/common/error.h"
#include "hotlap/common/string_match.h"

namespace hotlap {

namespace fs = std::filesystem;

namespace {
fs::path ExecutableDir() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : exe.parent_path();
}

// The folder of the shared object that holds this code (the Python module, a shared build of the
// library), or empty where that is the executable (a program linked with the static libraries).
fs::path SharedObjectDir() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<const void*>(&SharedObjectDir), &info) == 0 ||
      info.dli_fname == nullptr) {
    return {};
  }
  std::error_code ec;
  const fs::path object = fs::canonical(info.dli_fname, ec);
  const fs::path exe = fs::canonical("/proc/self/exe", ec);
  return ec || object == exe ? fs::path() : object.parent_path();
}

// " (there is no data folder at ...)" where the data folder is missing, for the messages of names
// that are not built in: an install whose data is not where the library looks.
std::string MissingDataNote(const fs::path& data) {
  std::error_code ec;
  if (fs::is_directory(data, ec)) return "";
  return "; there is no data folder at '" + data.string() +
         "': set HOTLAP_DATA_DIR to the installed share/hotlap/data";
}
}  // namespace

fs::path DataDir() {
  if (const char* env = std::getenv("HOTLAP_DATA_DIR"); env != nullptr && *env != '\0') {
    return env;
  }
  std::error_code ec;
  const fs::path installed = ExecutableDir() / ".." / "share" / "hotlap" / "data";
  if (fs::is_directory(installed, ec)) return installed;
  // The installed Python package (<prefix>/lib/python3/dist-packages/hotlap/_hotlap...so): the
  // prefix's share/hotlap/data four folders up, wherever `cmake --install --prefix` put it.
  fs::path dir = SharedObjectDir();
  for (int up = 0; up < 5 && !dir.empty(); ++up, dir = dir.parent_path()) {
    const fs::path data = dir / "share" / "hotlap" / "data";
    if (fs::is_directory(data, ec)) return data;
    if (dir == dir.root_path()) break;
  }
  // A program of the user's linked against the library: the source tree it was built from, or,
  // once that is gone, the data `cmake --install` put in place.
  const fs::path source = fs::path(HOTLAP_SOURCE_DIR) / "data";
  if (fs::is_directory(source, ec)) return source;
  return fs::path(HOTLAP_INSTALL_DATA_DIR);
}

fs::path ResolveCarFile(std::string_view name_or_path) {
  std::error_code ec;
  const fs::path given(name_or_path);
  if (fs::is_regular_file(given, ec)) return given;
  if (fs::is_directory(given, ec) && fs::is_regular_file(given / "car.yaml", ec)) {
    return given / "car.yaml";
  }
  const fs::path cars = DataDir() / "cars";
  const fs::path builtin = cars / given / "car.yaml";
  if (given.is_relative() && fs::is_regular_file(builtin, ec)) return builtin;
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(cars, ec)) {
    if (fs::is_regular_file(entry.path() / "car.yaml", ec)) {
      names.push_back(entry.path().filename().string());
    }
  }
  throw InputError("no car '" + std::string(name_or_path) +
                   "': not a car.yaml file, and not a built-in car (built-in: " +
                   QuotedList(names) + ")" + MissingDataNote(DataDir()));
}

fs::path ResolveTrackFile(std::string_view name_or_path) {
  std::error_code ec;
  const fs::path given(name_or_path);
  if (fs::is_regular_file(given, ec)) return given;
  const fs::path tracks = DataDir() / "tracks";
  const std::vector<std::string> extensions = {".yaml", ".yml", ".csv", ".xml"};
  if (given.is_relative() && !given.has_parent_path() && !name_or_path.empty()) {
    for (const std::string& ext : extensions) {
      const fs::path builtin = tracks / (std::string(name_or_path) + ext);
      if (fs::is_regular_file(builtin, ec)) return builtin;
    }
  }
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(tracks, ec)) {
    const std::string ext = entry.path().extension().string();
    if (entry.is_regular_file(ec) &&
        std::find(extensions.begin(), extensions.end(), ext) != extensions.end()) {
      names.push_back(entry.path().stem().string());
    }
  }
  std::sort(names.begin(), names.end());
  throw InputError("no track '" + std::string(name_or_path) +
                   "': not a track file (.yaml, .yml, .csv or .xml), and not a built-in track "
                   "(built-in: " +
                   QuotedList(names) + ")" + MissingDataNote(DataDir()));
}

fs::path ResolveTyreFile(std::string_view name_or_path) {
  std::error_code ec;
  const fs::path given(name_or_path);
  // A file name (with its extension) or an absolute path is a path: the loader says if it is not
  // there.
  if (fs::is_regular_file(given, ec) || given.has_extension() || given.is_absolute()) return given;
  // Built-in: DataDir()/tyres/NAME.{yaml,yml,tir}, or CAR/NAME for
  // DataDir()/cars/CAR/tyres/NAME.tir.
  const std::vector<std::string> extensions = {".yaml", ".yml", ".tir"};
  const fs::path data = DataDir();
  if (given.is_relative() && !name_or_path.empty()) {
    for (const std::string& ext : extensions) {
      const fs::path builtin = (data / "tyres" / given).string() + ext;
      if (fs::is_regular_file(builtin, ec)) return builtin;
    }
    // A car's tyres folder also holds its thermal parameter files: only .tir files are models.
    if (given.has_parent_path()) {
      const fs::path builtin =
          (data / "cars" / given.parent_path() / "tyres" / given.filename()).string() + ".tir";
      if (fs::is_regular_file(builtin, ec)) return builtin;
    }
  }
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(data / "tyres", ec)) {
    const std::string ext = entry.path().extension().string();
    if (entry.is_regular_file(ec) &&
        std::find(extensions.begin(), extensions.end(), ext) != extensions.end()) {
      names.push_back(entry.path().stem().string());
    }
  }
  for (const auto& car : fs::directory_iterator(data / "cars", ec)) {
    for (const auto& entry : fs::directory_iterator(car.path() / "tyres", ec)) {
      if (entry.is_regular_file(ec) && entry.path().extension() == ".tir") {
        names.push_back(car.path().filename().string() + "/" + entry.path().stem().string());
      }
    }
  }
  std::sort(names.begin(), names.end());
  throw InputError("no tyre '" + std::string(name_or_path) +
                   "': not a tyre file, and not a built-in tyre (built-in: " + QuotedList(names) +
                   ")" + MissingDataNote(data));
}

}  // namespace hotlap
