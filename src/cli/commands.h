// Subcommands of the tidepool executable, each registered on the CLI11 app by one function.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

namespace tidepool::cli {

// Each adds its subcommand; the action runs after parsing when that subcommand was chosen.
struct Command {
  CLI::App* sub;
  std::function<int()> action;  // returns the exit code; throws tidepool::Error
};
Command addInfo(CLI::App& app);
Command addRender(CLI::App& app);
Command addRun(CLI::App& app);
Command addBench(CLI::App& app);
Command addSweep(CLI::App& app);
Command addValidate(CLI::App& app);
Command addSoak(CLI::App& app);
Command addCheckResume(CLI::App& app);

// "1280x720" -> width, height (throws Error otherwise).
void parseSize(const std::string& text, int& width, int& height);

// Checks of floating-point options: a finite number (NaN and infinities refused) in [min, max],
// or above zero; the bounds written compactly ("[0.05, 64]", "1e+06").
CLI::Validator finiteRange(double min, double max);
CLI::Validator finitePositive();

}  // namespace tidepool::cli
