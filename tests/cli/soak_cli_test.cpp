// `tidepool soak`: a short run of a small scene holds and prints its table; a run that blows up,
// or a scene without a model, ends in one line saying so. (The soak of each model: the Soak.*
// tests of tests/CMakeLists.txt, label soak.)
#include <gtest/gtest.h>

#include "support/gl_test.h"
#include "support/one_line_error.h"

using namespace tidepool;
using test::runTidepool;

namespace {
const std::string kSoakScenes = std::string(TIDEPOOL_TEST_DATA) + "/soak/";
}

TEST(SoakCli, ShortRunHoldsAndPrintsARowPerSample) {
  // RSS is not judged here (Soak.<model> does): under ASan it measures the quarantine.
  const auto r =
      runTidepool({"soak", kSoakScenes + "swarm.json", "--steps", "40", "--every", "10", "--rss-tolerance", "100000"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("rss_MiB"), std::string::npos) << r.out;
  int rows = 0;
  for (const char* step : {"\n        0 ", "\n       10 ", "\n       20 ", "\n       30 ", "\n       40 "})
    rows += r.out.find(step) != std::string::npos;
  EXPECT_EQ(rows, 5) << r.out;
  EXPECT_NE(r.out.find("soak: held for 40 steps"), std::string::npos) << r.out;
}

TEST(SoakCli, BlowUpEndsInOneLine) {
  test::TempDir dir;  // Courant number 1.5 * (1/30) / 0.01 = 5, far past the 2D limit 0.71
  dir.write("unstable.json",
            R"({"name": "unstable", "model": "ripples", "params": {"width": 32, "height": 32, "cell_size": 0.01,
      "wave_speed": 1.5, "auto_substeps": false, "substeps": 1,
      "drops": [{"time": 0, "x": 0.5, "y": 0.5, "radius": 0.1, "depth": -0.05}]}})");
  const auto r = runTidepool({"soak", (dir / "unstable.json").string(), "--steps", "400"});
  EXPECT_FALSE(r.signaled) << r.err;
  EXPECT_EQ(r.exitCode, 1) << r.err;
  const std::vector<std::string> lines = r.errLines();  // the model's Courant warning, then the verdict
  ASSERT_FALSE(lines.empty());
  EXPECT_NE(lines.back().find("tidepool: error: soak: unstable at step "), std::string::npos) << r.err;
  EXPECT_NE(lines.back().find("ripples diverged by t = "), std::string::npos) << r.err;
}

TEST(SoakCli, SceneWithoutModelIsRefused) {
  test::expectOneLineError({"soak", "blank", "--steps", "10"}, "'Blank' is a blank scene, which has no model to soak",
                           1);
}
