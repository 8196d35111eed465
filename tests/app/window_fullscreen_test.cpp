// F11's fullscreen under Xvfb: the window fills the monitor's video mode, and going back restores
// the windowed size and position. Without a display the test runs itself under xvfb-run.
#include <gtest/gtest.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <filesystem>

#include "gl/context_window.h"
#include "support/run_process.h"

using namespace tidepool;

namespace {
void pumpEvents() {  // the X server answers the switch asynchronously
  for (int i = 0; i < 30; ++i) glfwWaitEventsTimeout(0.01);
}
}  // namespace

TEST(WindowFullscreen, FillsTheMonitorAndRestoresTheWindow) {
  if (!gl::displayAvailable()) {
    ASSERT_EQ(test::runProcess({"sh", "-c", "command -v xvfb-run"}).exitCode, 0)
        << "xvfb-run is needed for the window tests (scripts/install-deps.sh installs it)";
    const std::string self = std::filesystem::read_symlink("/proc/self/exe").string();
    auto r = test::runProcess({"xvfb-run", "-a", "-s", "-screen 0 1024x768x24", self,
                               "--gtest_filter=WindowFullscreen.FillsTheMonitorAndRestoresTheWindow"});
    ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("[  PASSED  ] 1 test"), std::string::npos) << r.out;
    return;
  }
  gl::WindowContext context({320, 240, "fullscreen", false, false, true});
  GLFWwindow* window = context.window();
  glfwSetWindowPos(window, 60, 40);
  pumpEvents();
  int x = 0, y = 0, w = 0, h = 0;
  glfwGetWindowPos(window, &x, &y);
  glfwGetWindowSize(window, &w, &h);
  ASSERT_EQ(w, 320);
  ASSERT_EQ(h, 240);
  EXPECT_FALSE(context.fullscreen());

  ASSERT_TRUE(context.setFullscreen(true));
  pumpEvents();
  EXPECT_TRUE(context.fullscreen());
  const GLFWvidmode* mode = glfwGetVideoMode(glfwGetWindowMonitor(window));
  ASSERT_NE(mode, nullptr);
  int fw = 0, fh = 0;
  glfwGetWindowSize(window, &fw, &fh);
  EXPECT_EQ(fw, mode->width);
  EXPECT_EQ(fh, mode->height);
  int fbw = 0, fbh = 0;
  context.framebufferSize(fbw, fbh);
  EXPECT_EQ(fbw, mode->width) << "the frame follows: the next frame renders at the monitor's size";
  EXPECT_TRUE(context.setFullscreen(true)) << "asking again changes nothing";

  ASSERT_TRUE(context.setFullscreen(false));
  pumpEvents();
  EXPECT_FALSE(context.fullscreen());
  int x2 = 0, y2 = 0, w2 = 0, h2 = 0;
  glfwGetWindowPos(window, &x2, &y2);
  glfwGetWindowSize(window, &w2, &h2);
  EXPECT_EQ(w2, 320);
  EXPECT_EQ(h2, 240);
  EXPECT_EQ(x2, x);
  EXPECT_EQ(y2, y);
}
