// README commands shrunk to a few frames and a small size, so that all of them run on llvmpipe in
// a few minutes, with the files each one promises. The rules, one per option of each subcommand
// the README uses (readme_shrink.cpp lists them):
//   render, run: --frames -> 2 and --size -> 64x48 (both added when absent); --every -> 1, so the
//   last of the 2 frames is exported as `--frames 76 --every 75` means; --checkpoint-every ->
//   0.001 s, under any scene's frame, so the 2 frames save on the way and at the end;
//   --resolution -> 1.5, refining as the README's examples do; a scene too big for llvmpipe gets
//   the --resolution that makes it small; --fit-gpu gets --budget 100 (llvmpipe meets 33 ms only
//   at tiny sizes and by luck of load).
//   bench: --repeats 1, --warmup 0, --n one small count, --steps 1:3, and each bench's own
//   smallest (render 64x48 after 1 settling step, export 1 frame, surface 4096 particles on 16
//   cells); validate: --until 0.02 s, --every 5 steps; check-resume: 1 frame at 32x18.
// An option, subcommand or bench without a rule is an error: a new form gets a rule before it runs.
#pragma once

#include <string>
#include <vector>

#include "support/readme_commands.h"

namespace tidepool::test {

struct ShrunkCommand {
  ReadmeCommand source;
  std::vector<std::string> args;   // what runs, after the program
  int folder = 0;                  // working folder: a --resume runs where its checkpoint was written
  std::vector<std::string> files;  // relative to the folder: must exist, not empty, after the run
  bool printsTable = false;        // standard output must not be empty (info, bench, validate to stdout)
  bool needsFfmpeg = false;        // --video
};

struct ShrunkCommands {
  std::vector<ShrunkCommand> commands;  // in README order
  std::vector<std::string> errors;      // "README.md:L: ..." for each form without a rule
};

ShrunkCommands shrinkReadmeCommands(const std::vector<ReadmeCommand>& commands);

}  // namespace tidepool::test
