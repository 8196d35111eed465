// OpenGL 4.3 core contexts behind one small interface: a GLFW window, headless EGL (device
// platform first: that is what finds an NVIDIA GPU without a display; then Mesa's surfaceless
// platform) and OSMesa as the last fallback. Nothing above src/gl can tell which one it runs on.
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "gl/gl.h"

namespace tidepool::gl {

enum class Backend { Auto, Egl, OsMesa, Window };
Backend parseBackend(std::string_view name);  // "auto" | "egl" | "osmesa" | "window"; throws Error

class Context {
 public:
  virtual ~Context() = default;
  virtual std::string description() const = 0;  // "egl-device #0 (NVIDIA)", "osmesa", "window"...
  virtual void makeCurrent() = 0;
};

struct ContextOptions {
  Backend backend = Backend::Auto;
  bool debug = false;  // debug context + KHR_debug messages to the log
};

// Headless context (no default framebuffer: render into Framebuffers). Backend::Auto tries EGL
// then OSMesa; Backend::Window is refused. Throws Error saying what each attempt found.
std::unique_ptr<Context> createHeadlessContext(const ContextOptions& options = {});

// Internal to src/gl: the individual backends, and the check that every backend ends with.
std::unique_ptr<Context> createEglContext(const ContextOptions& options);
std::unique_ptr<Context> createOsMesaContext(const ContextOptions& options);

// Throws when the current context is older than 4.3 or has no compute shaders, naming the
// vendor, renderer and version found and how to run on Mesa llvmpipe instead.
void requireGl43(const std::string& backend);

}  // namespace tidepool::gl
