// Every command that can run for minutes says so on stderr as it goes: render and run say what
// runs (particles or cells) and, after the first frame that steps, about how long the whole run
// takes; sweep, validate and soak report their progress. Off a terminal (as here) the lines come
// a few per run, never a redraw per frame. The lines' form is checked, never their times.
#include <gtest/gtest.h>

#include <regex>

#include "support/gl_test.h"
#include "support/run_process.h"

using namespace tidepool;
using test::runTidepool;

namespace {

bool has(const std::string& text, const std::string& pattern) { return std::regex_search(text, std::regex(pattern)); }

constexpr const char* kCount = R"([0-9]{1,3}(,[0-9]{3})*)";  // 4,776
constexpr const char* kTime = R"([0-9]+(\.[0-9])? s|[0-9]+ min [0-9]+ s|[0-9]+ h [0-9]+ min)";

}  // namespace

TEST(ProgressCli, RenderSaysTheParticleCountAndEstimatesTheRun) {
  test::TempDir dir;
  const auto r =
      runTidepool({"render", "dam-break", "--frames", "2", "--size", "32x18", "--out", (dir / "o").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(has(r.err, std::string("Dam break: ") + kCount + " particles, 2 frames at 32x18\n")) << r.err;
  EXPECT_TRUE(has(r.err, std::string("Dam break: first frame (") + kTime + "), about (" + kTime + ") for 2 frames\n"))
      << r.err;
  EXPECT_LT(r.err.find("particles, 2 frames"), r.err.find("first frame")) << r.err;
  EXPECT_EQ(r.out.find("particles"), std::string::npos) << r.out;  // stdout stays clean
}

TEST(ProgressCli, GridModelsCountCells) {
  test::TempDir dir;
  const auto r = runTidepool({"render", "ripples", "--frames", "2", "--size", "32x18", "--out", (dir / "o").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(has(r.err, std::string(": ") + kCount + " cells, 2 frames at 32x18\n")) << r.err;
}

TEST(ProgressCli, QuietRenderSaysNeitherCountNorEstimate) {
  test::TempDir dir;
  const auto r = runTidepool(
      {"render", "dam-break", "--frames", "2", "--size", "32x18", "--out", (dir / "o").string(), "--quiet"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.err.find("particles,"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("first frame"), std::string::npos) << r.err;
}

TEST(ProgressCli, SweepAnnouncesItsStudyAndEachRow) {
  test::TempDir dir;
  const auto r = runTidepool({"sweep", "swarm-orbit", "--quick", "--no-chart", "--csv-dir", dir.path().string()});
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_NE(r.err.find("sweep swarm-orbit 1/1: "), std::string::npos) << r.err;
  EXPECT_TRUE(has(r.err, std::string("sweep swarm-orbit: .* ms per simulated s \\((") + kTime + ") so far\\)\n"))
      << r.err;
  EXPECT_TRUE(has(r.err, std::string("sweep swarm-orbit: 1 study in (") + kTime + ")\n")) << r.err;
}

TEST(ProgressCli, ValidateSaysTheCountAndReportsProgress) {
  test::TempDir dir;
  const auto r =
      runTidepool({"validate", "dam-break", "--every", "10", "--until", "0.02", "--csv", (dir / "p.csv").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(has(r.err, std::string("Dam break: ") + kCount + " particles, until t = 0.02 s")) << r.err;
  EXPECT_NE(r.err.find("validate Dam break 100% (20/20, "), std::string::npos) << r.err;
}

TEST(ProgressCli, SoakReportsProgressATenthAtATime) {
  const auto r = runTidepool({"soak", std::string(TIDEPOOL_TEST_DATA) + "/soak/swarm.json", "--steps", "40", "--every",
                              "10", "--rss-tolerance", "100000"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(has(r.err, "soak .* 50% \\(20/40, ")) << r.err;
  EXPECT_TRUE(has(r.err, "soak .* 100% \\(40/40, ")) << r.err;
  EXPECT_EQ(r.out.find("% ("), std::string::npos) << r.out;  // stdout: the samples alone
}
