// The GLFW window context (GL 4.3 core). The app reaches the GLFWwindow for input and ImGui.
#pragma once

#include <glm/glm.hpp>
#include <memory>
#include <string>

#include "gl/context.h"

struct GLFWwindow;

namespace tidepool::gl {

struct WindowOptions {
  int width = 1280, height = 720;
  std::string title = "tidepool";
  bool debug = false;
  bool vsync = true;
  bool visible = true;
};

class WindowContext final : public Context {
 public:
  explicit WindowContext(const WindowOptions& options);  // throws Error when no display / no GL 4.3
  ~WindowContext() override;
  WindowContext(const WindowContext&) = delete;
  WindowContext& operator=(const WindowContext&) = delete;

  std::string description() const override { return "window"; }
  void makeCurrent() override;
  GLFWwindow* window() const { return m_window; }
  bool shouldClose() const;
  void swapBuffers();
  void framebufferSize(int& width, int& height) const;
  // Fullscreen on the monitor under the window's centre (its current video mode); back to windowed
  // restores the size and position the window had. False when there is no monitor to fill.
  bool setFullscreen(bool on);
  bool fullscreen() const;

 private:
  GLFWwindow* m_window = nullptr;
  bool m_vsync = true;
  glm::ivec2 m_windowedPos{0}, m_windowedSize{0};  // before going fullscreen, screen coordinates
};

// True when GLFW can reach a display (checked without opening a window).
bool displayAvailable();

}  // namespace tidepool::gl
