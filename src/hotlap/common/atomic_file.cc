#include "hotlap/common/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <fstream>
#include <random>
#include <string>
#include <system_error>

#include "hotlap/common/error.h"

namespace hotlap {
namespace {

// "write failed: No space left on device", or without the reason when the system gave none.
std::string WriteError(int error) {
  if (error == 0) return "write failed (disk full?)";
  return "write failed: " + std::generic_category().message(error);
}

}  // namespace

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
      errno = 0;
      write(out);
      out.flush();
      if (out) out.close();
      if (out.fail())
        throw InputError("cannot write '" + path.string() + "': " + WriteError(errno));
    }
    // On disk before it replaces the previous file, so that a crash of the machine right after
    // the rename cannot leave an empty file under the final name.
    if (const int fd = ::open(temp.c_str(), O_RDONLY); fd >= 0) {
      const int synced = ::fsync(fd);
      const int error = errno;
      ::close(fd);
      if (synced != 0) {
        throw InputError("cannot write '" + path.string() + "': " + WriteError(error));
      }
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
