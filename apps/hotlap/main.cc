// hotlap: race-car tyre and brake thermal management. main() parses and dispatches.

#include <csignal>
#include <cstdio>
#include <exception>
#include <map>
#include <string>

#include <CLI/CLI.hpp>

#include "commands.h"
#include "hotlap/common/error.h"

int main(int argc, char** argv) {
  // A file-size limit (ulimit -f) makes a write fail with EFBIG, reported like a full disk, rather
  // than kill the process mid-write.
  std::signal(SIGXFSZ, SIG_IGN);
  CLI::App app{"hotlap " HOTLAP_VERSION
               ": tyre and brake thermal models, fitting and lap simulation for race cars"};
  app.set_version_flag("--version", std::string(HOTLAP_VERSION));
  app.require_subcommand(1);
  std::map<CLI::App*, hotlap::app::CommandRunner> runners;
  const auto add = [&](hotlap::app::CommandRunner (*reg)(CLI::App&)) {
    // Each Register* adds exactly one subcommand; remember which runner belongs to it.
    const size_t before = app.get_subcommands({}).size();
    hotlap::app::CommandRunner run = reg(app);
    runners[app.get_subcommands({}).at(before)] = std::move(run);
  };
  add(&hotlap::app::RegisterReplayCommand);
  add(&hotlap::app::RegisterTyreCommand);
  add(&hotlap::app::RegisterTrackCommand);
  add(&hotlap::app::RegisterLapCommand);
  add(&hotlap::app::RegisterOptimiseCommand);
  add(&hotlap::app::RegisterFitCommand);
  add(&hotlap::app::RegisterSynthCommand);
  add(&hotlap::app::RegisterObserveCommand);
  add(&hotlap::app::RegisterAbsCommand);
  add(&hotlap::app::RegisterFeCommand);
  add(&hotlap::app::RegisterLogCommand);
  add(&hotlap::app::RegisterSweepCommand);
  add(&hotlap::app::RegisterStintCommand);
  add(&hotlap::app::RegisterRaceCommand);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version print and exit 0.
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e);
    // A bad option is bad input like any other: one line on stderr, exit 2.
    std::string where = "hotlap";
    for (CLI::App* sub = &app;;) {
      CLI::App* next = nullptr;
      for (CLI::App* s : sub->get_subcommands({})) {
        if (s->parsed()) next = s;
      }
      if (next == nullptr) break;
      where += " " + next->get_name();
      sub = next;
    }
    std::string what = e.what();
    if (where == "hotlap" && argc > 1 && argv[1][0] != '-') {
      what = "unknown command '" + std::string(argv[1]) + "'";
    }
    for (char& c : what) {
      if (c == '\n') c = ' ';
    }
    std::fprintf(stderr, "hotlap: error: %s (%s --help)\n", what.c_str(), where.c_str());
    return 2;
  }
  try {
    for (auto& [sub, run] : runners) {
      if (sub->parsed()) return run();
    }
    return 1;
  } catch (const hotlap::InputError& e) {
    std::fprintf(stderr, "hotlap: error: %s\n", e.what());
    return 2;
  } catch (const hotlap::NumericalError& e) {
    std::fprintf(stderr, "hotlap: numerical failure: %s\n", e.what());
    return 3;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hotlap: internal error: %s\n", e.what());
    return 4;
  }
}
