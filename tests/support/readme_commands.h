// The commands README.md shows, as a user copies them: lines of its ```sh blocks that start with
// `tidepool` or `build/tidepool` (less a trailing # comment), and `code spans` in its prose that
// are commands: `tidepool ...`, or the prose's shorthand of a subcommand with options
// (`render cup --frames 60 --out B`). Every other form is sorted by a listed rule (ReadmeRules)
// or reported as an error: a form nobody recognised must fail a test, never be skipped quietly.
//
//   `tidepool render <scene> --size 400x300`  ->  runnable: render dam-break --size 400x300
//   `tidepool soak <scene> --steps N`         ->  synopsis (N is a placeholder), listed, not run
//   `tidepool render`                         ->  a name, not a command
#pragma once

#include <string>
#include <vector>

namespace tidepool::test {

struct ReadmeRules {
  std::string scene;                      // what `<scene>` and `[scene]` become
  std::vector<std::string> placeholders;  // words that stand for a value (N, FILE, WxH, ...)
  std::vector<std::string> names;         // spans that name the program or a subcommand
  std::vector<std::string> synopses;      // spans with placeholders left: each must be in the README
  std::vector<std::string> otherTools;    // prefixes of ```sh lines that run something else
  std::vector<std::string> subcommands;   // first words of the prose's shorthand (`render cup --out B`)
};

// The rules for this repository's README.md, each list with the reason it holds.
ReadmeRules readmeRules();

struct ReadmeCommand {
  int line = 0;                   // README line it starts on
  std::string text;               // as written (a fenced line without its comment)
  std::vector<std::string> env;   // leading NAME=value words
  std::vector<std::string> args;  // the words after the program, <scene> substituted
};

struct ReadmeCommands {
  std::vector<ReadmeCommand> runnable;  // in README order
  std::vector<ReadmeCommand> synopses;  // recognised and listed, not run
  std::vector<std::string> errors;      // "README.md:L: ..." for each form not recognised
};

ReadmeCommands readReadmeCommands(const std::string& markdown, const ReadmeRules& rules);

}  // namespace tidepool::test
