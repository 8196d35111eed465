// Strings from files and the command line quoted in an error are escaped and cut: a newline, an
// ANSI escape or a NUL in a name, or a name of 100,000 characters, still gives one short line.
// Numbers are refused when they are not finite, and the limits a range error names are compact.
#include <gtest/gtest.h>

#include "io/json.h"
#include "support/gl_test.h"
#include "support/one_line_error.h"

using namespace tidepool;
using test::expectOneLineError;

namespace {

// One line (expectOneLineError), no raw control bytes, at most `maxLength` characters (the list
// of known scenes alone takes ~600).
void expectEchoed(const std::vector<std::string>& args, const std::string& expected, int code = 1,
                  std::size_t maxLength = 1000, const std::vector<std::string>& env = {}) {
  const test::ProcessResult r = expectOneLineError(args, expected, code, env);
  std::string line = r.err;
  if (!line.empty() && line.back() == '\n') line.pop_back();
  for (const char c : line)
    EXPECT_FALSE(static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
        << "raw control byte " << int(c) << " in: " << io::printable(line, 400);
  EXPECT_LE(line.size(), maxLength) << io::printable(line, 400);
}

// An argument cannot hold a NUL (the file test has one): a newline, an ANSI colour, a tab, length.
std::string control() { return "a\nb\x1b[31mc\td" + std::string(100000, 'x'); }

}  // namespace

TEST(Echo, SceneNameFromTheCommandLine) {
  expectEchoed({"render", "no\nsuch\x1b[2Jscene" + std::string(100000, 'x'), "--out", "/tmp/x"},
               "scene 'no\\x0asuch\\x1b[2Jscene");
  expectEchoed({"render", "/nonexistent/a\nb\x1b[2J" + std::string(5000, 'x') + ".json", "--out", "/tmp/x"},
               "file not found: '/nonexistent/a\\x0ab\\x1b[2J");
}

TEST(Echo, MeshNameFromASceneFile) {
  test::TempDir dir;
  // The name as JSON: "\n", "\u001b", "\u0000" escaped in the file, raw bytes once read.
  dir.write("s.json", R"({"model": "balls", "params": {"particles": {"fill": "none"},
    "obstacles": [{"shape": "mesh", "mesh": "a\nb\u001b[31mc\u0000d)" +
                          std::string(100000, 'x') + R"("}]}})");
  expectEchoed({"render", (dir / "s.json").string(), "--frames", "1", "--out", (dir / "o").string()},
               "mesh 'a\\x0ab\\x1b[31mc\\x00dxxx");
}

TEST(Echo, SizeAndSetFromTheCommandLine) {
  expectEchoed({"render", "blank", "--size", control(), "--out", "/tmp/x"}, "--size 'a\\x0ab\\x1b[31mc\\x09dxxx");
  expectEchoed({"render", "blank", "--set", control(), "--out", "/tmp/x"}, "--set 'a\\x0ab\\x1b[31mc");
}

TEST(Echo, NonFiniteNumbersAreRefused) {
  for (const char* option : {"--resolution", "--checkpoint-every", "--budget"})
    for (const char* value : {"nan", "inf", "-inf"})
      expectEchoed({"render", "dam-break", option, value, "--out", "/tmp/x"},
                   std::string(option) + ": " + value + " is not a finite number", 2);
  expectEchoed({"render", "dam-break", "--export", "surface", "--surface-iso", "nan", "--out", "/tmp/x"},
               "--surface-iso: nan is not a finite number", 2);
  expectEchoed({"validate", "dam-break", "--until", "nan"}, "--until: nan is not a finite number", 2);
  expectEchoed({"soak", "balls", "--warmup", "nan"}, "--warmup: nan is not a finite number", 2);
}

TEST(Echo, RangeErrorsPrintCompactLimits) {
  expectEchoed({"render", "dam-break", "--checkpoint-every", "-1", "--out", "/tmp/x"}, "-1 is not above 0", 2, 120);
  expectEchoed({"render", "dam-break", "--budget", "1e7", "--out", "/tmp/x"}, "1e+07 is out of range [0.1, 1e+06]", 2,
               120);
  expectEchoed({"render", "dam-break", "--resolution", "0.049", "--out", "/tmp/x"}, "0.049 is out of range [0.05, 64]",
               2, 120);
  expectEchoed({"render", "dam-break", "--export", "surface", "--surface-iso", "1e30", "--out", "/tmp/x"},
               "1e+30 is out of range [0, 1]", 2, 120);
}

TEST(Echo, ResolutionBoundsAreInclusive) {
  test::TempDir dir;
  const test::ProcessResult r = test::runTidepool({"render", "dam-break", "--resolution", "0.05", "--frames", "1",
                                                   "--size", "16x16", "--quiet", "--out", (dir / "o").string()});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  dir.write("s.json", R"({"model": "balls", "params": {"particles": {"resolution": 0.05}}})");
  const test::ProcessResult s = test::runTidepool({"render", (dir / "s.json").string(), "--frames", "1", "--size",
                                                   "16x16", "--quiet", "--out", (dir / "o").string()});
  EXPECT_EQ(s.exitCode, 0) << s.err;
}

TEST(Echo, SceneWithoutAModelIsRefused) {
  test::TempDir dir;
  dir.write("s.json", R"({"name": "no model", "params": {"color": [1, 0, 0]}})");
  expectEchoed({"render", (dir / "s.json").string(), "--out", (dir / "o").string()},
               (dir / "s.json").string() + ": scene.model is missing: give one of blank, ");
}

TEST(Echo, InvertedFillIsRefused) {
  test::TempDir dir;
  for (const char* model : {"balls", "fluid"}) {
    dir.write("s.json", std::string(R"({"model": ")") + model + R"(", "params": {"particles": {"fill": "block",
              "fill_min": [0.5, 0, 0], "fill_max": [0.25, 1, 0.5]}}})");
    expectEchoed(
        {"render", (dir / "s.json").string(), "--frames", "1", "--out", (dir / "o").string()},
        std::string(model) + ": particles.fill_max = [0.25, 1, 0.5] must exceed fill_min = [0.5, 0, 0] on every axis");
  }
}

TEST(Echo, DuplicateJsonKeysAreRefused) {
  test::TempDir dir;
  dir.write("s.json", "{\"model\": \"blank\",\n  \"params\": {\"color\": [1, 0, 0], \"color\": [0, 1, 0]}}");
  expectEchoed({"render", (dir / "s.json").string(), "--out", (dir / "o").string()},
               (dir / "s.json").string() + ":2:34: key \"color\" given twice in one object");
  dir.write("t.json", "{\"model\": \"blank\", \"a\\u000ab\": 1, \"a\\nb\": 2}");
  expectEchoed({"render", (dir / "t.json").string(), "--out", (dir / "o").string()},
               (dir / "t.json").string() + ":1:35: key \"a\\x0ab\" given twice in one object");
}

TEST(Echo, BenchTokensAndCheckpointPaths) {
  expectEchoed({"bench", "balls", "--n", control()}, "size 'a\\x0ab\\x1b[31mc\\x09dxxx", 1, 200);
  expectEchoed({"bench", "balls", "--n", "1M", "--steps", control()}, "--steps 'a\\x0ab\\x1b[31mc\\x09dxxx", 1, 200);
  expectEchoed({"render", "blank", "--resume", "/nonexistent/" + control(), "--out", "/tmp/x"},
               "checkpoint '/nonexistent/a\\x0ab\\x1b[31mc\\x09dxxx", 1, 400);
}

TEST(Echo, SceneNamesAreShownEscapedAndCut) {
  test::TempDir dir;
  dir.write("s.json", R"({"model": "blank", "name": "a\nb\u001b[31mc\u0000d)" + std::string(100000, 'x') + R"("})");
  expectEchoed({"soak", (dir / "s.json").string()}, "soak: 'a\\x0ab\\x1b[31mc\\x00dxxx", 1, 200);
}
