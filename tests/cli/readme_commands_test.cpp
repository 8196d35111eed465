// Every command README.md shows runs as written, shrunk to a few frames and a small size
// (support/readme_shrink.h states the rules): exit status 0 and the files it promises. Each runs
// in a folder of its own (so `out/<scene>` lands there), a `--resume` in the folder of the command
// that wrote its checkpoint, in README order, without a display (`run` then renders headless).
// TIDEPOOL_README names another file to check instead (how a broken copy is seen to fail).
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

#include "io/video.h"
#include "support/gl_test.h"
#include "support/readme_commands.h"
#include "support/readme_shrink.h"
#include "support/run_process.h"

using namespace tidepool::test;

namespace {

std::filesystem::path readmePath() {
  if (const char* other = std::getenv("TIDEPOOL_README")) return other;
  return std::filesystem::path(TIDEPOOL_SOURCE_DIR) / "README.md";
}

std::string readText(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string joined(const std::vector<std::string>& words) {
  std::string s;
  for (const std::string& w : words) s += (s.empty() ? "" : " ") + w;
  return s;
}

// The README's commands, shrunk; every form neither recognised nor given a rule is a failure.
ShrunkCommands readmeCommands() {
  const std::string text = readText(readmePath());
  EXPECT_FALSE(text.empty()) << readmePath() << " is empty or missing";
  const ReadmeCommands read = readReadmeCommands(text, readmeRules());
  ShrunkCommands shrunk = shrinkReadmeCommands(read.runnable);
  for (const std::string& e : read.errors) ADD_FAILURE() << e;
  for (const std::string& e : shrunk.errors) ADD_FAILURE() << e;
  return shrunk;
}

}  // namespace

TEST(ReadmeCommands, EveryCommandFormIsRecognisedAndHasShrinkRules) {
  const ShrunkCommands shrunk = readmeCommands();
  EXPECT_GE(shrunk.commands.size(), 25u) << "the README shows fewer commands than it did: is the reader lost?";
  for (const ShrunkCommand& c : shrunk.commands)
    std::cout << "README.md:" << c.source.line << ": " << c.source.text << "\n    runs: tidepool " << joined(c.args)
              << "\n    in folder " << c.folder << ", promises: " << joined(c.files) << "\n";
}

// The reader and the shrink rules refuse what they do not know, and say where.
TEST(ReadmeCommands, AnUnknownFormFailsInsteadOfBeingSkipped) {
  const std::map<std::string, std::string> cases = {
      {"run `tidepool frobnicate cup` now\n", "no shrink rules for `frobnicate`"},
      {"```sh\ntidepool render cup --wobble 3   # a new option\n```\n", "no shrink rule for `--wobble`"},
      {"```sh\nmake install\n```\n", "neither a tidepool command nor in readmeRules().otherTools"},
      {"as `tidepool soak <scene> --steps N` does\n", "is not a synopsis readmeRules() lists"},
      {"then `tidepool render cup --resume old.ckpt`\n", "which no README command before it writes"},
      {"or `tidepool render cup --out \"my clips\"`\n", "needs a shell"},
      {"```sh\ntidepool bench life --n 1M\n```\n", "no shrink rules for `bench life`"},
  };
  ReadmeRules rules = readmeRules();
  rules.synopses.clear();
  for (const auto& [markdown, why] : cases) {
    const ReadmeCommands read = readReadmeCommands(markdown, rules);
    const ShrunkCommands shrunk = shrinkReadmeCommands(read.runnable);
    std::string errors;
    for (const std::string& e : read.errors) errors += e + "\n";
    for (const std::string& e : shrunk.errors) errors += e + "\n";
    EXPECT_NE(errors.find(why), std::string::npos) << markdown << "gave: " << errors;
    EXPECT_EQ(errors.find("README.md:0"), std::string::npos) << errors;
  }
  const ReadmeCommands stale = readReadmeCommands("nothing here\n", readmeRules());
  EXPECT_EQ(stale.errors.size(), readmeRules().synopses.size()) << "a listed synopsis gone from the README";
}

TEST(ReadmeCommands, EveryCommandRunsAsWritten) {
  const ShrunkCommands shrunk = readmeCommands();
  ASSERT_FALSE(shrunk.commands.empty());
  std::map<int, TempDir> folders;
  for (const ShrunkCommand& c : shrunk.commands) {
    const std::string name = "README.md:" + std::to_string(c.source.line) + ": `" + c.source.text + "`";
    std::cout << name << "\n    $ tidepool " << joined(c.args) << std::endl;
    if (c.needsFfmpeg && !tidepool::io::ffmpegAvailable()) {
      ADD_FAILURE() << name << " needs ffmpeg: scripts/install-deps.sh installs it, as CI does";
      continue;
    }
    const TempDir& dir = folders[c.folder];
    std::vector<std::string> argv = {"sh", "-c", "cd \"$0\" && exec \"$@\"", dir.path().string(), TIDEPOOL_EXE};
    argv.insert(argv.end(), c.args.begin(), c.args.end());
    std::vector<std::string> env = {"DISPLAY=", "WAYLAND_DISPLAY="};
    env.insert(env.end(), c.source.env.begin(), c.source.env.end());
    const auto start = std::chrono::steady_clock::now();
    const ProcessResult r = runProcess(argv, env);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << "    exit " << r.exitCode << " in " << std::fixed << std::setprecision(1) << seconds << " s"
              << std::endl;
    if (r.exitCode != 0 || r.signaled) {
      ADD_FAILURE() << name << " failed (exit " << r.exitCode << (r.signaled ? ", a signal" : "") << "):\n" << r.err;
      continue;
    }
    for (const std::string& file : c.files) {
      std::error_code ec;
      const auto bytes = std::filesystem::file_size(dir / file, ec);  // (uintmax_t)-1 on an error
      EXPECT_TRUE(!ec && bytes > 0) << name << " promised " << file
                                    << " (in its working folder), which is missing or empty\n"
                                    << r.err;
    }
    if (c.printsTable) EXPECT_FALSE(r.out.empty()) << name << " printed nothing\n" << r.err;
  }
}
