// Key presses queued as GLFW reports them, until the frame reads them. Polling the key state once
// a frame loses a tap whose press and release both fall between two polls (at 1 frame/s, most
// taps); the callback sees every press. Each press counts once, in the order made; a held key does
// not repeat. A press made while ImGui has the keyboard (a text field) is ImGui's, not queued.
#pragma once

#include <cstddef>
#include <vector>

struct GLFWwindow;

namespace tidepool {

class KeyQueue {
 public:
  static constexpr std::size_t kMaxQueued = 256;  // presses kept between two take()s; later ones dropped

  void onKey(int key, int action, bool uiHasKeyboard);  // one GLFW key event (GLFW_PRESS, _RELEASE, _REPEAT)
  std::vector<int> take();                              // GLFW key codes pressed since the last take, in order

 private:
  std::vector<int> m_pressed;
};

// Makes GLFW report `window`'s keys to `queue` (through the window's user pointer). Call it before
// ImGui_ImplGlfw_InitForOpenGL(window, true): ImGui's key callback then calls this one first (it
// chains to the callback it replaced), and ImGui_ImplGlfw_Shutdown puts this one back.
void installKeyQueue(GLFWwindow* window, KeyQueue& queue);
void keyQueueCallback(GLFWwindow* window, int key, int scancode, int action, int mods);  // the one GLFW calls

}  // namespace tidepool
