// `hotlap sweep`: set-up sweeps on dask.distributed or as Slurm shards. The engine is the Python
// package's hotlap.sweep (dask is a Python library); this command finds the package beside the
// program (the build tree's python/, or the install prefix's) and hands it every argument.

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.h"
#include "hotlap/common/error.h"

namespace hotlap::app {

namespace {

namespace fs = std::filesystem;

int RunSweep(const std::vector<std::string>& args) {
#if defined(HOTLAP_PYTHON) && defined(HOTLAP_PYTHON_INSTALL_DIR)
  std::error_code ec;
  const fs::path exe_dir = fs::read_symlink("/proc/self/exe", ec).parent_path();
  // The package built beside this program (build/python), else the installed one.
  std::string path;
  for (const fs::path& dir : {exe_dir / "python", exe_dir / ".." / HOTLAP_PYTHON_INSTALL_DIR}) {
    if (fs::is_regular_file(dir / "hotlap" / "sweep.py", ec)) {
      path = fs::weakly_canonical(dir, ec).string();
      break;
    }
  }
  if (path.empty()) {
    throw InputError(
        "hotlap sweep: the Python package hotlap is not beside this program (build it with the "
        "default -DHOTLAP_BUILD_PYTHON=ON; docs/sweeps.md)");
  }
  if (const char* old = std::getenv("PYTHONPATH"); old != nullptr && *old != '\0') {
    path += std::string(":") + old;
  }
  setenv("PYTHONPATH", path.c_str(), 1);
  std::vector<std::string> argv_text = {HOTLAP_PYTHON, "-m", "hotlap.sweep"};
  argv_text.insert(argv_text.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : argv_text) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::fflush(stdout);
  execv(HOTLAP_PYTHON, argv.data());
  throw InputError(
      fmt::format("hotlap sweep: cannot run {}: {}", HOTLAP_PYTHON, std::strerror(errno)));
#else
  (void)args;
  throw InputError("hotlap sweep: this build has no Python package (-DHOTLAP_BUILD_PYTHON=OFF)");
#endif
}

}  // namespace

CommandRunner RegisterSweepCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand(
      "sweep",
      "Run a case table of laps on dask.distributed or as Slurm shards: sweep --cases FILE --out "
      "DIR [--local-workers N | --scheduler tcp://HOST:PORT | --shard I/N] [--json PATH]; sweep "
      "merge DIR (docs/sweeps.md; `hotlap sweep --help` for the options)");
  // Everything after `sweep` goes to the Python engine as it is, --help included.
  sub->prefix_command();
  sub->set_help_flag();
  sub->allow_extras();
  return [sub] { return RunSweep(sub->remaining()); };
}

}  // namespace hotlap::app
