// --resolution, --fit-gpu and --set from the command line (render; run shares the options).
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "io/png.h"
#include "support/gl_test.h"
#include "support/one_line_error.h"

using namespace tidepool;
using test::runTidepool;

namespace {

const char* kSmallDam = R"({"model": "balls", "params": {
    "particles": {"radius": 0.02, "domain_max": [0.4, 0.2, 0.3], "fill": "block", "fill_max": [0.1, 0.2, 0.2]},
    "engine": {"dt": 0.0005, "substeps": 2, "contact_time": 0.005}},
    "clip": {"frames": 2, "width": 64, "height": 36}})";

}  // namespace

TEST(ResolutionCli, ResolutionAndSetReachTheScene) {
  test::TempDir dir;
  dir.write("dam.json", kSmallDam);
  // --set view.mode=water: the water look, a colour the balls' look does not have at the tank's floor.
  auto r = runTidepool({"render", (dir / "dam.json").string(), "--resolution", "2", "--set", "view.mode=water", "--set",
                        "engine.damping=1", "--frames", "1", "--out", (dir / "f").string(), "--quiet", "--checkpoint",
                        (dir / "c.ckpt").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "f/frame_00000.png"));
  // The checkpoint holds the parameters as run: refined twice, the mode and the damping as set.
  const std::string text = [&] {
    std::ifstream in(dir / "c.ckpt", std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }();
  EXPECT_NE(text.find("\"resolution\":2.0"), std::string::npos);
  EXPECT_NE(text.find("\"radius\":0.00999999"), std::string::npos);  // 0.02 / 2 in float
  EXPECT_NE(text.find("\"mode\":\"water\""), std::string::npos);
  EXPECT_NE(text.find("\"damping\":1.0"), std::string::npos);
}

TEST(ResolutionCli, FitGpuPrintsItsTrialsAndRenders) {
  test::TempDir dir;
  dir.write("dam.json", kSmallDam);
  auto r = runTidepool({"render", (dir / "dam.json").string(), "--fit-gpu", "--budget", "60", "--frames", "1", "--out",
                        (dir / "f").string(), "--quiet"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("resolution  particles   ms/frame  fits"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("yes"), std::string::npos) << r.err;
}

TEST(ResolutionCli, BadValuesGetOneLine) {
  test::TempDir dir;
  dir.write("dam.json", kSmallDam);
  const std::string scene = (dir / "dam.json").string(), out = (dir / "f").string();
  test::expectOneLineError({"render", scene, "--set", "view.mode", "--out", out}, "is not KEY=VALUE");
  test::expectOneLineError({"render", scene, "--set", "particles.radius=big", "--out", out}, "radius");
  test::expectOneLineError({"render", scene, "--set", "particles.nonsense=1", "--out", out}, "unknown key");
  test::expectOneLineError({"render", scene, "--resolution", "100", "--out", out}, "--resolution", 2);  // usage
  test::expectOneLineError({"render", scene, "--set", "engine.substeps=50", "--resolution", "40", "--out", out},
                           "substeps per frame");
  test::expectOneLineError({"render", "life", "--resolution", "2", "--out", out}, "unknown key");
  test::expectOneLineError({"render", "life", "--fit-gpu", "--out", out}, "--fit-gpu refines water");
  // No trial fits: the trials as usual, then one line of error, the last.
  const auto r = runTidepool({"render", scene, "--fit-gpu", "--budget", "0.1", "--out", out, "--quiet"});
  EXPECT_FALSE(r.signaled);
  EXPECT_EQ(r.exitCode, 1) << r.err;
  ASSERT_FALSE(r.errLines().empty());
  EXPECT_NE(r.errLines().back().find("over the budget of 0.1 ms"), std::string::npos) << r.err;
}
