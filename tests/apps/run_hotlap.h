#pragma once
// Running the built `hotlap` program from the command tests: its exit code and what it printed;
// and a fixture with a temporary folder of its own for tests that need nothing more.

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "test_util.h"

namespace hotlap::test {

struct RunResult {
  int exit_code = 0;
  std::string out;  // standard output
  std::string err;  // standard error
};

/// Runs `hotlap ARGS` through the shell (ARGS may hold redirections and quotes), capturing its
/// standard output and error in files in `scratch`; its cache (`hotlap race`'s fall-off) in
/// `scratch`/cache, never the user's.
inline RunResult RunHotlap(const std::string& args, const std::filesystem::path& scratch) {
  const std::filesystem::path out = scratch / "stdout.txt", err = scratch / "stderr.txt";
  const std::string command = "HOTLAP_CACHE_DIR='" + (scratch / "cache").string() + "' " +
                              std::string(HOTLAP_BINARY) + " " + args + " >" + out.string() +
                              " 2>" + err.string();
  const int status = std::system(command.c_str());
  return {WEXITSTATUS(status), ReadTextFile(out), ReadTextFile(err)};
}

/// A fresh temporary folder per test, removed with everything in it at the end.
class CommandTest : public ::testing::Test {
 protected:
  RunResult Run(const std::string& args) { return RunHotlap(args, dir()); }
  nlohmann::json Json(const std::filesystem::path& p) {
    return nlohmann::json::parse(ReadTextFile(p));
  }
  const std::filesystem::path& dir() const { return dir_.path(); }

 private:
  TempDir dir_;
};

}  // namespace hotlap::test
