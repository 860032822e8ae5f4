#include "hotlap/common/output_folder.h"

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

}  // namespace hotlap
