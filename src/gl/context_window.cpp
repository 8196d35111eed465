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
  m_vsync = o.vsync;
  glfwSwapInterval(o.vsync ? 1 : 0);
  if (o.debug) enableDebugOutput();
}

namespace {
// The monitor whose area holds the window's centre; the primary one when none does.
GLFWmonitor* monitorUnder(GLFWwindow* window) {
  int x = 0, y = 0, w = 0, h = 0, count = 0;
  glfwGetWindowPos(window, &x, &y);
  glfwGetWindowSize(window, &w, &h);
  GLFWmonitor** monitors = glfwGetMonitors(&count);
  for (int i = 0; i < count; ++i) {
    int mx = 0, my = 0;
    glfwGetMonitorPos(monitors[i], &mx, &my);
    const GLFWvidmode* mode = glfwGetVideoMode(monitors[i]);
    const int cx = x + w / 2, cy = y + h / 2;
    if (mode && cx >= mx && cx < mx + mode->width && cy >= my && cy < my + mode->height) return monitors[i];
  }
  return glfwGetPrimaryMonitor();
}
}  // namespace

bool WindowContext::fullscreen() const { return glfwGetWindowMonitor(m_window) != nullptr; }

bool WindowContext::setFullscreen(bool on) {
  if (on == fullscreen()) return true;
  if (on) {
    GLFWmonitor* monitor = monitorUnder(m_window);
    const GLFWvidmode* mode = monitor ? glfwGetVideoMode(monitor) : nullptr;
    if (!mode) return false;
    glfwGetWindowPos(m_window, &m_windowedPos.x, &m_windowedPos.y);
    glfwGetWindowSize(m_window, &m_windowedSize.x, &m_windowedSize.y);
    glfwSetWindowMonitor(m_window, monitor, 0, 0, mode->width, mode->height, mode->refreshRate);
  } else {
    glfwSetWindowMonitor(m_window, nullptr, m_windowedPos.x, m_windowedPos.y, m_windowedSize.x, m_windowedSize.y,
                         GLFW_DONT_CARE);
  }
  glfwSwapInterval(m_vsync ? 1 : 0);  // some platforms drop it with the switch
  return true;
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
