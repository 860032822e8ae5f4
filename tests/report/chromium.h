#pragma once
/// @file
/// Test helper: load an HTML report in headless Chromium and read back what the page says about
/// itself (#hotlap-status: charts expected, charts drawn, script errors; see html_report.h).
///
/// Chromium is a test dependency (Debian package `chromium`, installed by
/// `bash scripts/install-deps.sh --test`, which scripts/test.sh runs). Without it the tests that
/// use this helper FAIL with a message saying so; they are never skipped silently.

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "test_util.h"

namespace hotlap::test {

/// What the page's status element said after loading.
struct PageStatus {
  int expected = -1;  ///< charts the page has
  int rendered = -1;  ///< charts drawn
  int errors = -1;    ///< script errors seen
  std::string text;   ///< the element's text (lists the errors)
  std::string dom;    ///< the whole page as Chromium serialised it after loading
};

/// $HOTLAP_CHROMIUM if set, else /usr/bin/chromium, else `chromium` or `chromium-browser` on the
/// PATH; nullopt if there is none.
inline std::optional<std::filesystem::path> FindChromium() {
  namespace fs = std::filesystem;
  if (const char* env = std::getenv("HOTLAP_CHROMIUM"); env != nullptr && *env != '\0') {
    return fs::path(env);
  }
  if (::access("/usr/bin/chromium", X_OK) == 0) return fs::path("/usr/bin/chromium");
  if (const char* path = std::getenv("PATH")) {
    std::string dirs = path;
    for (size_t start = 0; start <= dirs.size();) {
      const size_t end = std::min(dirs.find(':', start), dirs.size());
      for (const char* name : {"chromium", "chromium-browser"}) {
        const fs::path candidate = fs::path(dirs.substr(start, end - start)) / name;
        if (::access(candidate.c_str(), X_OK) == 0) return candidate;
      }
      start = end + 1;
    }
  }
  return std::nullopt;
}

/// Parses #hotlap-status out of a DOM dump; nullopt if the element is not there.
inline std::optional<PageStatus> ParsePageStatus(const std::string& dom) {
  // Plain string search: the dump holds all of Chart.js, too long for std::regex.
  const size_t id = dom.find("id=\"hotlap-status\"");
  if (id == std::string::npos) return std::nullopt;
  const size_t open = dom.rfind('<', id), close = dom.find('>', id);
  const size_t end = dom.find("</p>", close);
  if (open == std::string::npos || close == std::string::npos || end == std::string::npos) {
    return std::nullopt;
  }
  const std::string tag = dom.substr(open, close - open);
  PageStatus status;
  const auto read = [&](const char* name, int& value) {
    std::smatch m;
    if (std::regex_search(tag, m, std::regex(std::string(name) + "=\"([0-9]+)\""))) {
      value = std::stoi(m.str(1));
    }
  };
  read("data-expected", status.expected);
  read("data-rendered", status.rendered);
  read("data-errors", status.errors);
  status.text = dom.substr(close + 1, end - close - 1);
  return status;
}

/// Loads `html` in headless Chromium (fresh profile in `scratch`, no network, killed with all its
/// children after `timeout`) and returns the page's status. Adds a test failure and returns
/// nullopt if Chromium is missing, hangs, exits with an error or the page has no status element.
inline std::optional<PageStatus> RenderUrlInChromium(
    const std::string& url, const std::filesystem::path& scratch,
    std::chrono::seconds timeout = std::chrono::seconds(90));

inline std::optional<PageStatus> RenderInChromium(
    const std::filesystem::path& html, const std::filesystem::path& scratch,
    std::chrono::seconds timeout = std::chrono::seconds(90)) {
  return RenderUrlInChromium("file://" + std::filesystem::absolute(html).string(), scratch,
                             timeout);
}

/// The same for any URL (e.g. a page a test's own server serves on 127.0.0.1).
inline std::optional<PageStatus> RenderUrlInChromium(const std::string& url,
                                                     const std::filesystem::path& scratch,
                                                     std::chrono::seconds timeout) {
  namespace fs = std::filesystem;
  const std::string html = url;
  const std::optional<fs::path> chromium = FindChromium();
  if (!chromium || ::access(chromium->c_str(), X_OK) != 0) {
    ADD_FAILURE() << "headless Chromium is needed to check that HTML reports render, and "
                  << (chromium ? chromium->string() + " (from HOTLAP_CHROMIUM) is not executable"
                               : std::string("it is not installed (no /usr/bin/chromium)"))
                  << ". Run `bash scripts/install-deps.sh --test` (installs Debian's chromium "
                     "package), or set HOTLAP_CHROMIUM to a Chromium binary.";
    return std::nullopt;
  }
  const fs::path profile = scratch / "chromium-profile";
  const fs::path dom_file = scratch / "dom.html", log_file = scratch / "chromium.log";
  fs::create_directories(profile);
  std::vector<std::string> args = {chromium->string(),
                                   "--headless",
                                   "--no-sandbox",  // needed as root
                                   "--disable-gpu",
                                   "--disable-quic",
                                   "--no-first-run",
                                   "--disable-background-networking",
                                   "--disable-component-update",
                                   "--disable-sync",
                                   "--disable-dev-shm-usage",
                                   "--user-data-dir=" + profile.string(),
                                   "--virtual-time-budget=10000",
                                   "--dump-dom",
                                   url};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);

  const pid_t pid = ::fork();
  if (pid < 0) {
    ADD_FAILURE() << "cannot start Chromium: fork failed";
    return std::nullopt;
  }
  if (pid == 0) {
    // Child: own process group (so the whole tree can be killed), output to files.
    ::setpgid(0, 0);
    const int out = ::open(dom_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = ::open(log_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (out < 0 || err < 0) ::_exit(126);
    ::dup2(out, STDOUT_FILENO);
    ::dup2(err, STDERR_FILENO);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  ::setpgid(pid, pid);  // also from the parent, so there is no race with the kill below
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  int wait_status = 0;
  bool finished = false;
  while (std::chrono::steady_clock::now() < deadline) {
    const pid_t done = ::waitpid(pid, &wait_status, WNOHANG);
    if (done == pid) {
      finished = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  ::kill(-pid, SIGKILL);  // Chromium's helpers, and Chromium itself if it hung
  if (!finished) ::waitpid(pid, &wait_status, 0);
  const std::string log = fs::exists(log_file) ? ReadTextFile(log_file) : "";
  if (!finished) {
    ADD_FAILURE() << "Chromium did not finish within " << timeout.count() << " s on " << html
                  << "; killed. Its log:\n"
                  << log;
    return std::nullopt;
  }
  if (!WIFEXITED(wait_status) || WEXITSTATUS(wait_status) != 0) {
    ADD_FAILURE() << "Chromium failed on " << html << " (status " << wait_status << "). Its log:\n"
                  << log;
    return std::nullopt;
  }
  const std::string dom = ReadTextFile(dom_file);
  std::optional<PageStatus> status = ParsePageStatus(dom);
  if (status) status->dom = dom;
  if (!status) {
    ADD_FAILURE() << "the page " << html << " has no #hotlap-status element after loading. "
                  << "Chromium's log:\n"
                  << log;
  }
  std::error_code ec;
  fs::remove_all(profile, ec);
  return status;
}

/// Passes when the page drew all its charts (and at least `min_charts`) with no script error.
inline ::testing::AssertionResult RenderedCleanly(const std::optional<PageStatus>& status,
                                                  int min_charts) {
  if (!status) return ::testing::AssertionFailure() << "no page status";
  if (status->expected >= min_charts && status->rendered == status->expected &&
      status->errors == 0) {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure()
         << "expected at least " << min_charts << " charts, all drawn, no script errors; page says "
         << status->expected << " expected, " << status->rendered << " drawn, " << status->errors
         << " errors: " << status->text;
}

}  // namespace hotlap::test
