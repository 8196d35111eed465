// Messages a new user reads: the list of known scenes is sorted, an option error points at the
// help page of the command it belongs to, every benchmark's help lists the options all of them
// take, and the progress lines give each line's own share.
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

#include "support/gl_test.h"
#include "support/one_line_error.h"

using namespace tidepool;
using test::runTidepool;

TEST(CliMessages, KnownScenesAreListedInOrder) {
  const test::ProcessResult r = test::expectOneLineError({"render", "nosuchscene", "--out", "/tmp/x"}, "(known: ", 1);
  const std::size_t from = r.err.find("(known: ") + 8, to = r.err.find(')', from);
  ASSERT_NE(to, std::string::npos) << r.err;
  std::vector<std::string> names;
  std::stringstream list(r.err.substr(from, to - from));
  for (std::string name; std::getline(list, name, ',');) names.push_back(name.substr(name[0] == ' ' ? 1 : 0));
  EXPECT_GE(names.size(), 30u);
  EXPECT_TRUE(std::is_sorted(names.begin(), names.end())) << r.err;
}

TEST(CliMessages, AnOptionErrorPointsAtItsCommandsHelp) {
  test::expectOneLineError({"render", "blank", "--every", "5", "--out", "/tmp/x"}, "(see 'tidepool render --help')", 2);
  test::expectOneLineError({"bench", "balls", "--no-such-option"}, "(see 'tidepool bench balls --help')", 2);
  test::expectOneLineError({"--no-such-option"}, "(see 'tidepool --help')", 2);
}

TEST(CliMessages, EveryBenchmarksHelpListsTheSharedOptions) {
  for (const char* name : {"balls", "fluid", "render"}) {
    const test::ProcessResult r = runTidepool({"bench", name, "--help"});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    for (const char* option : {"--csv FILE", "--repeats N", "--warmup N"})
      EXPECT_NE(r.out.find(option), std::string::npos) << name << ": " << option << " in\n" << r.out;
  }
}

TEST(CliMessages, ProgressLinesGiveTheirOwnShare) {
  test::TempDir dir;
  const test::ProcessResult r =
      runTidepool({"render", "blank", "--frames", "3", "--size", "16x16", "--out", (dir / "o").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find(" 33% (1/3,"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(" 66% (2/3,"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("100% (3/3,"), std::string::npos) << r.err;
}
