#include "hotlap/common/atomic_file.h"

#include <fstream>
#include <random>
#include <string>
#include <system_error>

#include "hotlap/common/error.h"

namespace hotlap {

void WriteFileAtomically(const std::filesystem::path& path,
                         const std::function<void(std::ostream&)>& write) {
  namespace fs = std::filesystem;
  const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) {
    throw InputError("cannot write '" + path.string() + "': folder '" + folder.string() +
                     "' does not exist");
  }
  std::random_device rd;
  const fs::path temp =
      folder / ("." + path.filename().string() + ".tmp" + std::to_string(rd() % 1000000));
  try {
    {
      std::ofstream out(temp, std::ios::binary | std::ios::trunc);
      if (!out)
        throw InputError("cannot write '" + path.string() + "': cannot create a file there");
      write(out);
      out.flush();
      if (!out) throw InputError("cannot write '" + path.string() + "': write failed (disk full?)");
    }
    fs::rename(temp, path, ec);
    if (ec) {
      throw InputError("cannot write '" + path.string() + "': " + ec.message());
    }
  } catch (...) {
    fs::remove(temp, ec);
    throw;
  }
}

}  // namespace hotlap
