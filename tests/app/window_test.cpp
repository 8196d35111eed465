// The window path under Xvfb: a real GLFW window (GL from llvmpipe through GLX) opens, draws
// frames with the ImGui panel and saves a screenshot.
#include <gtest/gtest.h>

#include <unistd.h>

#include "io/png.h"
#include "support/gl_test.h"
#include "support/run_process.h"

using namespace tidepool;

namespace {

bool onPath(const std::string& tool) { return test::runProcess({"sh", "-c", "command -v " + tool}).exitCode == 0; }

// The window of a plain green scene at `size` (WxH) on an Xvfb screen of `screen`, its screenshot
// after `frames` frames.
io::Image greenWindow(const std::string& screen, const std::string& size, const std::string& frames) {
  EXPECT_TRUE(onPath("xvfb-run")) << "xvfb-run is needed for the window test (scripts/install-deps.sh installs it)";
  test::TempDir dir;
  dir.write("green.json", R"({"name": "Green", "model": "blank", "params": {"color": [0, 1, 0]}})");
  const std::string shot = (dir / "shot.png").string();
  auto r = test::runProcess({"xvfb-run", "-a", "-s", "-screen 0 " + screen, TIDEPOOL_EXE, "run",
                             (dir / "green.json").string(), "--backend", "window", "--size", size, "--frames", frames,
                             "--screenshot", shot});
  EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
  return r.exitCode == 0 ? io::readPng(shot) : io::Image{};
}

}  // namespace

TEST(Window, OpensDrawsAndTakesAScreenshotUnderXvfb) {
  const io::Image img = greenWindow("800x600x24", "640x480", "3");
  ASSERT_EQ(img.width, 640);
  ASSERT_EQ(img.height, 480);
  // The scene colour fills the window away from the UI panel (bottom-right corner)...
  const uint8_t* corner = &img.rgba[(std::size_t(475) * 640 + 635) * 4];
  EXPECT_EQ(corner[0], 0);
  EXPECT_EQ(corner[1], 255);
  EXPECT_EQ(corner[2], 0);
  // ...and the ImGui panel covers the top-left with other colours.
  int nonGreen = 0;
  for (int y = 10; y < 60; ++y)
    for (int x = 10; x < 200; ++x) {
      const uint8_t* p = &img.rgba[(std::size_t(y) * 640 + x) * 4];
      nonGreen += !(p[0] == 0 && p[1] == 255 && p[2] == 0);
    }
  EXPECT_GT(nonGreen, 1000) << "the UI panel should be drawn over the scene";
}

// At 1280x720 the panel is a sidebar the window's height and the scene is drawn right of it: the
// blank scene's colour fills the columns beside the panel from top to bottom, and the panel's
// column is other colours down to the bottom row (the screenshot waited for its layout).
TEST(Window, TheSidebarPanelLeavesTheSceneUncovered) {
  const io::Image img = greenWindow("1920x1080x24", "1280x720", "1");
  ASSERT_EQ(img.width, 1280);
  ASSERT_EQ(img.height, 720);
  const auto green = [&](int x, int y) {
    const uint8_t* p = &img.rgba[(std::size_t(y) * 1280 + x) * 4];
    return p[0] == 0 && p[1] == 255 && p[2] == 0;
  };
  int panelGreen = 0, sceneGreen = 0;
  for (int y = 0; y < 720; ++y) {
    panelGreen += green(200, y);
    sceneGreen += green(500, y);
  }
  EXPECT_EQ(panelGreen, 0) << "the panel's column is the panel, down to the bottom";
  EXPECT_GT(sceneGreen, 600) << "beside the panel, the scene (the indicators cover the top right only)";
}

TEST(Window, NoDisplayGivesAClearError) {
  auto r =
      test::runTidepool({"run", "blank", "--backend", "window", "--frames", "1"}, {"DISPLAY=", "WAYLAND_DISPLAY="});
  EXPECT_FALSE(r.signaled);
  EXPECT_EQ(r.exitCode, 1);
  ASSERT_EQ(r.errLines().size(), 1u) << r.err;
  EXPECT_NE(r.err.find("cannot open"), std::string::npos) << r.err;
}

// A water scene's probes are plotted live under the other plots: the fluid tank's gauges,
// pressures and forces; a probe the model cannot measure (a force on the balls) is a line in the
// panel, the others are still plotted, and the window keeps running.
TEST(Window, ProbesArePlottedAndOneTheModelCannotMeasureIsALineInThePanel) {
  test::TempDir dir;
  dir.write("balls.json", R"({"model": "balls", "params": {"particles": {"radius": 0.01,
      "domain_max": [0.2, 0.1, 0.2], "fill": "slab", "slab_height": 0.05},
      "probes": [{"kind": "gauge", "at": [0.1, 0.05, 0]}, {"kind": "force", "wall": "-z"}]}})");
  for (const std::string scene : {std::string("fluid-tank"), (dir / "balls.json").string()}) {
    const std::string shot = (dir / "shot.png").string();
    auto r = test::runProcess({"xvfb-run", "-a", "-s", "-screen 0 1920x1080x24", TIDEPOOL_EXE, "run", scene,
                               "--backend", "window", "--size", "1280x720", "--frames", "3", "--screenshot", shot});
    EXPECT_EQ(r.exitCode, 0) << scene << ": " << r.out << r.err;
    EXPECT_EQ(io::readPng(shot).width, 1280) << scene;
  }
}
