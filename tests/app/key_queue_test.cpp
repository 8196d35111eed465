// Keys tapped faster than the frame rate: the queue keeps every press, in order, once. Under Xvfb
// the taps are real X key events (press and release sent together, as a tap within one slow frame
// arrives), read by GLFW with ImGui's backend chained in, and by the window app itself, whose
// title (read back from the X server) follows the water model M switches to. Without a display
// the window tests run themselves under xvfb-run.
#include <gtest/gtest.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <imgui.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <thread>

#include "app/key_bindings.h"
#include "app/key_queue.h"
#include "app/window_app.h"
#include "gl/context_window.h"
#include "support/gl_test.h"
#include "support/run_process.h"

#include <X11/Xlib.h>  // last: its macros (None, Bool, Status) clash with C++ names
#include <X11/keysym.h>

// GLFW's X11 handles, as GLFW/glfw3native.h declares them (it would also want the Xrandr headers).
extern "C" Display* glfwGetX11Display(void);
extern "C" Window glfwGetX11Window(GLFWwindow* window);

using namespace tidepool;

namespace {

// The keys of the README's Controls table: the app's, then the models' letters (water M; life C, N, W).
std::vector<int> controlsKeys() {
  std::vector<int> keys;
  for (const KeyBinding& b : keyBindings()) keys.push_back(b.key);
  for (int k : {GLFW_KEY_M, GLFW_KEY_C, GLFW_KEY_N, GLFW_KEY_W}) keys.push_back(k);
  return keys;
}

KeySym keysymOf(int key) {
  if (key >= GLFW_KEY_A && key <= GLFW_KEY_Z) return XK_a + (key - GLFW_KEY_A);
  if (key >= GLFW_KEY_F1 && key <= GLFW_KEY_F12) return XK_F1 + (key - GLFW_KEY_F1);
  if (key == GLFW_KEY_SPACE) return XK_space;
  if (key == GLFW_KEY_PERIOD) return XK_period;
  if (key == GLFW_KEY_ESCAPE) return XK_Escape;
  ADD_FAILURE() << "no keysym for GLFW key " << key;
  return NoSymbol;
}

// Taps (press, then release) sent to `window` and flushed together. Event times grow by 50 ms: GLFW
// drops a press not later than the key's last one and takes a release followed within 20 ms by a
// press of the same key for auto-repeat.
void sendTaps(Display* display, Window window, const std::vector<int>& keys) {
  static Time time = 1000;
  for (int key : keys)
    for (int type : {KeyPress, KeyRelease}) {
      XEvent e{};
      e.xkey.type = type;
      e.xkey.display = display;
      e.xkey.window = window;
      e.xkey.root = DefaultRootWindow(display);
      e.xkey.time = time += 50;
      e.xkey.keycode = XKeysymToKeycode(display, keysymOf(key));
      e.xkey.same_screen = True;
      XSendEvent(display, window, False, type == KeyPress ? KeyPressMask : KeyReleaseMask, &e);
    }
  XSync(display, False);
}

// Runs this test again under xvfb-run when there is no display; true when it did (the caller returns).
bool ranUnderXvfb(const std::string& test) {
  if (gl::displayAvailable()) return false;
  EXPECT_EQ(test::runProcess({"sh", "-c", "command -v xvfb-run"}).exitCode, 0)
      << "xvfb-run is needed for the window tests (scripts/install-deps.sh installs it)";
  const std::string self = std::filesystem::read_symlink("/proc/self/exe").string();
  auto r = test::runProcess({"xvfb-run", "-a", "-s", "-screen 0 1024x768x24", self, "--gtest_filter=" + test});
  EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("[  PASSED  ] 1 test"), std::string::npos) << r.out;
  return true;
}

std::string nameOf(Display* display, Window window) {
  char* name = nullptr;
  if (!XFetchName(display, window, &name) || !name) return "";
  std::string s(name);
  XFree(name);
  return s;
}

// The top-level window whose title starts with `prefix`, once it exists (0 after `seconds`).
Window findWindow(Display* display, const std::string& prefix, double seconds) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) {
    Window root = 0, parent = 0, *children = nullptr;
    unsigned count = 0;
    if (XQueryTree(display, DefaultRootWindow(display), &root, &parent, &children, &count)) {
      Window found = 0;
      for (unsigned i = 0; i < count && !found; ++i)
        if (nameOf(display, children[i]).rfind(prefix, 0) == 0) found = children[i];
      if (children) XFree(children);
      if (found) return found;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return 0;
}

}  // namespace

TEST(KeyQueue, EveryTapComesOutOnceInOrder) {
  KeyQueue q;
  for (int key : {GLFW_KEY_R, GLFW_KEY_PERIOD, GLFW_KEY_PERIOD, GLFW_KEY_D}) {
    q.onKey(key, GLFW_PRESS, false);
    q.onKey(key, GLFW_RELEASE, false);
  }
  EXPECT_EQ(q.take(), (std::vector<int>{GLFW_KEY_R, GLFW_KEY_PERIOD, GLFW_KEY_PERIOD, GLFW_KEY_D}));
  EXPECT_TRUE(q.take().empty()) << "a press is taken once";
}

TEST(KeyQueue, HeldKeysDoNotRepeatAndTheUiKeepsItsKeys) {
  KeyQueue q;
  q.onKey(GLFW_KEY_D, GLFW_PRESS, false);
  for (int i = 0; i < 5; ++i) q.onKey(GLFW_KEY_D, GLFW_REPEAT, false);
  q.onKey(GLFW_KEY_D, GLFW_RELEASE, false);
  q.onKey(GLFW_KEY_R, GLFW_PRESS, true);  // typed into a text field
  q.onKey(GLFW_KEY_UNKNOWN, GLFW_PRESS, false);
  EXPECT_EQ(q.take(), (std::vector<int>{GLFW_KEY_D}));
  for (std::size_t i = 0; i < 2 * KeyQueue::kMaxQueued; ++i) q.onKey(GLFW_KEY_SPACE, GLFW_PRESS, false);
  EXPECT_EQ(q.take().size(), KeyQueue::kMaxQueued) << "bounded while nothing takes them";
}

// GLFW, with ImGui's backend installed after the queue as the window app does: every Controls key
// tapped within one frame arrives, `.` twice, in order; ImGui still sees the keys; a press while
// ImGui wants the keyboard is not queued.
TEST(KeyQueueWindow, EveryControlsKeyTappedWithinOneFrameArrivesInOrder) {
  if (ranUnderXvfb("KeyQueueWindow.EveryControlsKeyTappedWithinOneFrameArrivesInOrder")) return;
  gl::WindowContext context({320, 240, "keys", false, false, true});
  GLFWwindow* window = context.window();
  KeyQueue keys;
  installKeyQueue(window, keys);
  ImGui::CreateContext();
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  Display* display = glfwGetX11Display();
  const Window x11 = glfwGetX11Window(window);

  std::vector<int> taps = controlsKeys();
  taps.push_back(GLFW_KEY_PERIOD);  // the second of two quick `.` taps
  taps.push_back(GLFW_KEY_R);
  sendTaps(display, x11, taps);
  glfwPollEvents();  // one frame's poll sees all of them
  EXPECT_EQ(keys.take(), taps);

  XEvent press{};  // a key held down: ImGui's callback, chained after ours, sees it too
  press.xkey = {KeyPress, 0, False, display, x11, DefaultRootWindow(display),          0,   99999,
                0,        0, 0,     0,       0,   XKeysymToKeycode(display, XK_space), True};
  XSendEvent(display, x11, False, KeyPressMask, &press);
  XSync(display, False);
  glfwPollEvents();
  EXPECT_TRUE(ImGui::GetIO().KeysDown[GLFW_KEY_SPACE]);
  EXPECT_EQ(keys.take(), (std::vector<int>{GLFW_KEY_SPACE}));

  ImGui::GetIO().WantCaptureKeyboard = true;  // as after a frame with a text field active
  sendTaps(display, x11, {GLFW_KEY_R});
  glfwPollEvents();
  EXPECT_TRUE(keys.take().empty()) << "ImGui's key";

  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

// The window app: M tapped within one frame switches the water model and the title follows; F12
// and Esc tapped together take a screenshot and quit, long before the frame limit.
TEST(KeyQueueWindow, TheWindowAppTakesQuickTapsAndItsTitleFollowsTheModel) {
  if (ranUnderXvfb("KeyQueueWindow.TheWindowAppTakesQuickTapsAndItsTitleFollowsTheModel")) return;
  XInitThreads();  // the helper below talks to the X server from a second thread
  test::TempDir dir;
  dir.write("water.json", R"({"name": "Keys", "model": "balls", "params": {"particles": {"radius": 0.02,
      "domain_max": [0.4, 0.2, 0.4], "fill": "block", "fill_max": [0.2, 0.2, 0.2]}}})");
  WindowJob job;
  job.scene = (dir / "water.json").string();
  job.width = 320;
  job.height = 240;
  job.vsync = false;
  job.maxFrames = 1000;                     // a few frames do it; the limit only ends the run when the keys are lost
  job.screenshot = dir / "last_frame.png";  // written only if the frame limit ends the run
  const auto cwd = std::filesystem::current_path();
  std::filesystem::current_path(dir / "");  // F12 saves screenshot_<time>.png here

  std::atomic<bool> foundWindow = false;
  std::string titles;  // as the X server had them: before and after M
  std::thread user([&] {
    Display* display = XOpenDisplay(nullptr);
    if (!display) return;
    XSetErrorHandler([](Display*, XErrorEvent*) { return 0; });  // the window may close while it looks
    if (const Window w = findWindow(display, "tidepool - Keys", 60.0)) {
      foundWindow = true;
      const auto waitFor = [&](const std::string& title) {
        for (int i = 0; i < 3000 && nameOf(display, w) != title; ++i)
          std::this_thread::sleep_for(std::chrono::milliseconds(10));
        titles += nameOf(display, w) + "\n";
      };
      waitFor("tidepool - Keys [balls]");
      sendTaps(display, w, {GLFW_KEY_M});
      waitFor("tidepool - Keys [fluid]");
      sendTaps(display, w, {GLFW_KEY_F12, GLFW_KEY_ESCAPE});
    }
    XCloseDisplay(display);
  });
  const int code = runWindow(job);
  user.join();
  int shots = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir / ""))
    shots += e.path().filename().string().rfind("screenshot_", 0) == 0;
  std::filesystem::current_path(cwd);

  EXPECT_EQ(code, 0);
  ASSERT_TRUE(foundWindow);
  EXPECT_EQ(titles, "tidepool - Keys [balls]\ntidepool - Keys [fluid]\n");
  EXPECT_EQ(shots, 1) << "F12";
  EXPECT_FALSE(std::filesystem::exists(job.screenshot)) << "Esc should have closed the window before the frame limit";
}
