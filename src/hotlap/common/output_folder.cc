#include "hotlap/common/output_folder.h"

#include <unistd.h>

#include <string>
#include <system_error>

#include "hotlap/common/error.h"

namespace hotlap {

void CheckOutputFolder(const std::filesystem::path& path, const char* option) {
  const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : ".";
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec)) {
    throw InputError(std::string(option) + " '" + path.string() + "': folder '" + folder.string() +
                     "' does not exist");
  }
  if (std::filesystem::is_directory(path, ec)) {
    throw InputError(std::string(option) + " '" + path.string() + "' is a folder, not a file");
  }
}

void CheckOutputDirectory(const std::filesystem::path& path, const char* option) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (fs::exists(status)) {
    if (!fs::is_directory(status)) {
      throw InputError(std::string(option) + " '" + path.string() + "' exists and is not a folder");
    }
    return;
  }
  // The nearest ancestor that exists must be a folder we can create entries in.
  fs::path ancestor = fs::absolute(path, ec).lexically_normal();
  while (ancestor.has_relative_path() && !fs::exists(ancestor, ec)) {
    ancestor = ancestor.parent_path();
  }
  if (!fs::is_directory(ancestor, ec)) {
    throw InputError(std::string(option) + " '" + path.string() + "': '" + ancestor.string() +
                     "' is not a folder");
  }
  if (::access(ancestor.c_str(), W_OK | X_OK) != 0) {
    throw InputError(std::string(option) + " '" + path.string() + "': cannot create it in '" +
                     ancestor.string() + "' (no permission to write there)");
  }
}

void CreateOutputDirectory(const std::filesystem::path& path, const char* option) {
  std::error_code ec;
  std::filesystem::create_directories(path, ec);
  if (!std::filesystem::is_directory(path)) {
    throw InputError(std::string(option) + ": cannot create the folder '" + path.string() + "'" +
                     (ec ? ": " + ec.message() : std::string()));
  }
}

}  // namespace hotlap
