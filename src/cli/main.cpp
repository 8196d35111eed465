// tidepool: GPU particle and water simulations with OpenGL 4.3 compute shaders.
// Every failure ends in one clear line on stderr and a non-zero exit: 2 for usage, 1 otherwise.
// The line is escaped and cut once more here (kMaxMessage): a message that quotes input raw, from
// CLI11 or a site that forgot, still cannot break the line, reach the terminal or run on.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>

#include "base/error.h"
#include "cli/commands.h"
#include "io/json.h"

namespace {
constexpr std::size_t kMaxMessage = 2000;  // characters; the longest lists (known scenes) take ~700
}  // namespace

int main(int argc, char** argv) {
  using namespace tidepool;
  const auto shown = [](const char* message) { return io::printable(message, kMaxMessage); };
  CLI::App app{"tidepool: GPU particle and water simulations (OpenGL 4.3 compute shaders)", "tidepool"};
  app.set_version_flag("--version", "tidepool 0.1.0");
  app.require_subcommand(1);
  const cli::Command commands[] = {cli::addRun(app),   cli::addRender(app),     cli::addInfo(app),
                                   cli::addBench(app), cli::addSweep(app),      cli::addValidate(app),
                                   cli::addSoak(app),  cli::addCheckResume(app)};
  if (argc > 1 && argv[1][0] != '-') {
    bool known = false;
    for (const cli::Command& c : commands) known |= c.sub->get_name() == argv[1];
    if (!known) {
      std::fprintf(stderr,
                   "tidepool: unknown subcommand '%s' (expected run, render, info, bench, sweep, validate, soak or "
                   "check-resume; see "
                   "'tidepool --help')\n",
                   io::printable(argv[1]).c_str());
      return 2;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --version
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // The help page of the (sub)command the options belong to: `tidepool bench balls --help`.
    std::string page = "tidepool";
    const CLI::App* level = &app;
    for (int i = 1; i < argc; ++i) {
      const auto subs = level->get_subcommands([&](const CLI::App* s) { return s->get_name() == argv[i]; });
      if (subs.empty()) break;
      level = subs.front();
      page += " " + level->get_name();
    }
    std::fprintf(stderr, "tidepool: %s (see '%s --help')\n", shown(e.what()).c_str(), page.c_str());
    return 2;
  }
  try {
    for (const cli::Command& c : commands)
      if (c.sub->parsed()) return c.action();
    return 2;
  } catch (const Error& e) {
    std::fprintf(stderr, "tidepool: error: %s\n", shown(e.what()).c_str());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tidepool: internal error: %s\n", shown(e.what()).c_str());
    return 1;
  }
}
