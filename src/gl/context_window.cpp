#include "gl/context_window.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdlib>

#include "gl/debug.h"

namespace tidepool::gl {
namespace {
std::string g_lastGlfwError;
void onGlfwError(int, const char* description) { g_lastGlfwError = description; }

void initGlfw() {
  glfwSetErrorCallback(onGlfwError);
  if (!glfwInit())
    throw Error("cannot open a window: " +
                (g_lastGlfwError.empty() ? std::string("glfwInit failed") : g_lastGlfwError));
}
}  // namespace

bool displayAvailable() {
  const char* x = std::getenv("DISPLAY");
  const char* wl = std::getenv("WAYLAND_DISPLAY");
  return (x && *x) || (wl && *wl);
}

WindowContext::WindowContext(const WindowOptions& o) {
  initGlfw();
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, o.debug ? GLFW_TRUE : GLFW_FALSE);
  glfwWindowHint(GLFW_VISIBLE, o.visible ? GLFW_TRUE : GLFW_FALSE);
  m_window = glfwCreateWindow(o.width, o.height, o.title.c_str(), nullptr, nullptr);
  if (!m_window) {
    glfwTerminate();
    throw Error("cannot open an OpenGL 4.3 core window: " + g_lastGlfwError +
                " (headless: 'tidepool render', or run under xvfb-run)");
  }
  glfwMakeContextCurrent(m_window);
  if (!gladLoadGL(glfwGetProcAddress)) throw Error("window: could not load OpenGL functions");
  requireGl43("window");
  glfwSwapInterval(o.vsync ? 1 : 0);
  if (o.debug) enableDebugOutput();
}

WindowContext::~WindowContext() {
  if (m_window) glfwDestroyWindow(m_window);
  glfwTerminate();
}

void WindowContext::makeCurrent() { glfwMakeContextCurrent(m_window); }
bool WindowContext::shouldClose() const { return glfwWindowShouldClose(m_window); }
void WindowContext::swapBuffers() { glfwSwapBuffers(m_window); }
void WindowContext::framebufferSize(int& w, int& h) const { glfwGetFramebufferSize(m_window, &w, &h); }

}  // namespace tidepool::gl
