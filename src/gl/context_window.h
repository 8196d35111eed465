// The GLFW window context (GL 4.3 core). The app reaches the GLFWwindow for input and ImGui.
#pragma once

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

 private:
  GLFWwindow* m_window = nullptr;
};

// True when GLFW can reach a display (checked without opening a window).
bool displayAvailable();

}  // namespace tidepool::gl
