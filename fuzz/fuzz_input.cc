#include "fuzz_input.h"

#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace hotlap::fuzz {

namespace fs = std::filesystem;

namespace {

fs::path MakeWorkDir() {
  std::string pattern = (fs::temp_directory_path() / "hotlap-fuzz-XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
  return pattern;
}

}  // namespace

const fs::path& WorkDir() {
  static const fs::path dir = MakeWorkDir();
  // Registered once `dir` exists, so that it runs before dir's destructor (exit runs handlers in
  // the reverse order of their registration). Registered inside dir's initialiser, as it was
  // until 2026-11-27, it ran after it: remove_all read a destroyed path (a use after free that
  // ASan does not see inside libstdc++) and every run left its folder behind.
  static const bool remove_at_exit = [] {
    std::atexit([] {
      std::error_code ec;
      fs::remove_all(WorkDir(), ec);
    });
    return true;
  }();
  (void)remove_at_exit;
  return dir;
}

fs::path CopyOfData(std::string_view data_relative, std::string_view name) {
  const fs::path to = WorkDir() / name;
  if (!fs::exists(to)) {
    fs::copy(fs::path(HOTLAP_SOURCE_DIR) / data_relative, to, fs::copy_options::recursive);
  }
  return to;
}

const fs::path& WriteInput(const fs::path& path, const std::uint8_t* data, std::size_t size) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) throw std::runtime_error("cannot write " + path.string());
  if (size > 0 && std::fwrite(data, 1, size, f) != size) throw std::runtime_error("short write");
  std::fclose(f);
  return path;
}

}  // namespace hotlap::fuzz
