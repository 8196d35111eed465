#include "app/key_queue.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <utility>

namespace tidepool {

void KeyQueue::onKey(int key, int action, bool uiHasKeyboard) {
  if (action != GLFW_PRESS || key == GLFW_KEY_UNKNOWN || uiHasKeyboard) return;
  if (m_pressed.size() < kMaxQueued) m_pressed.push_back(key);
}

std::vector<int> KeyQueue::take() { return std::exchange(m_pressed, {}); }

void installKeyQueue(GLFWwindow* window, KeyQueue& queue) {
  glfwSetWindowUserPointer(window, &queue);
  glfwSetKeyCallback(window, keyQueueCallback);
}

void keyQueueCallback(GLFWwindow* window, int key, int /*scancode*/, int action, int /*mods*/) {
  auto* queue = static_cast<KeyQueue*>(glfwGetWindowUserPointer(window));
  if (!queue) return;
  // ImGui's flag is as the last frame left it, which is the state the user pressed the key in.
  const bool uiHasKeyboard = ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureKeyboard;
  queue->onKey(key, action, uiHasKeyboard);
}

}  // namespace tidepool
