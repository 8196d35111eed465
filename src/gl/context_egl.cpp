// Headless EGL context: EGL_EXT_platform_device first (finds NVIDIA GPUs without a display;
// hardware devices before Mesa's software device), then EGL_MESA_platform_surfaceless.
#include <glad/egl.h>

#include <cstdlib>
#include <cstring>
#include <vector>

#include "gl/context.h"
#include "gl/debug.h"

namespace tidepool::gl {
namespace {

bool hasExtension(const char* list, const char* name) {
  if (!list) return false;
  const std::size_t n = std::strlen(name);
  for (const char* p = std::strstr(list, name); p; p = std::strstr(p + 1, name))
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  return false;
}

class EglContext final : public Context {
 public:
  EglContext(EGLDisplay display, EGLContext context, std::string description)
      : m_display(display), m_context(context), m_description(std::move(description)) {}
  ~EglContext() override {
    eglMakeCurrent(m_display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(m_display, m_context);
    eglTerminate(m_display);
  }
  std::string description() const override { return m_description; }
  void makeCurrent() override { eglMakeCurrent(m_display, EGL_NO_SURFACE, EGL_NO_SURFACE, m_context); }

 private:
  EGLDisplay m_display;
  EGLContext m_context;
  std::string m_description;
};

struct Candidate {
  EGLDisplay display;
  std::string description;
};

std::vector<Candidate> candidates() {
  std::vector<Candidate> out;
  if (GLAD_EGL_EXT_device_enumeration && GLAD_EGL_EXT_platform_device) {
    EGLint count = 0;
    eglQueryDevicesEXT(0, nullptr, &count);
    std::vector<EGLDeviceEXT> devices(std::size_t(std::max(count, 0)));
    if (count > 0) eglQueryDevicesEXT(count, devices.data(), &count);
    const char* pick = std::getenv("TIDEPOOL_EGL_DEVICE");  // index into the device list
    std::vector<Candidate> software;
    for (EGLint i = 0; i < count; ++i) {
      if (pick && std::atoi(pick) != i) continue;
      const char* ext = GLAD_EGL_EXT_device_query ? eglQueryDeviceStringEXT(devices[i], EGL_EXTENSIONS) : nullptr;
      EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
      if (d == EGL_NO_DISPLAY) continue;
      const std::string desc = "egl-device #" + std::to_string(i) + " of " + std::to_string(count);
      (hasExtension(ext, "EGL_MESA_device_software") ? software : out).push_back({d, desc});
    }
    out.insert(out.end(), software.begin(), software.end());
  }
  if (GLAD_EGL_MESA_platform_surfaceless) {
    EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (d != EGL_NO_DISPLAY) out.push_back({d, "egl-surfaceless"});
  }
  return out;
}

EGLContext makeContext(EGLDisplay display, bool debug, bool versioned) {
  EGLConfig config = nullptr;
  const EGLint configAttribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLint n = 0;
  if (!eglChooseConfig(display, configAttribs, &config, 1, &n) || n == 0) {
    if (!GLAD_EGL_KHR_no_config_context) return EGL_NO_CONTEXT;
    config = EGL_NO_CONFIG_KHR;
  }
  const EGLint versionedAttribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                     4,
                                     EGL_CONTEXT_MINOR_VERSION,
                                     3,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                     EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                     EGL_CONTEXT_OPENGL_DEBUG,
                                     debug ? EGL_TRUE : EGL_FALSE,
                                     EGL_NONE};
  const EGLint plainAttribs[] = {EGL_NONE};
  return eglCreateContext(display, config, EGL_NO_CONTEXT, versioned ? versionedAttribs : plainAttribs);
}

}  // namespace

std::unique_ptr<Context> createEglContext(const ContextOptions& options) {
  if (!gladLoaderLoadEGL(EGL_NO_DISPLAY)) throw Error("EGL: libEGL.so.1 could not be loaded (install libegl1)");
  std::string tried;
  for (const Candidate& c : candidates()) {
    EGLint major = 0, minor = 0;
    if (!eglInitialize(c.display, &major, &minor)) {
      tried += " " + c.description + ": eglInitialize failed;";
      continue;
    }
    gladLoaderLoadEGL(c.display);  // display extensions
    if (!eglBindAPI(EGL_OPENGL_API)) {
      tried += " " + c.description + ": no desktop OpenGL;";
      eglTerminate(c.display);
      continue;
    }
    EGLContext ctx = makeContext(c.display, options.debug, true);
    const bool versioned = ctx != EGL_NO_CONTEXT;
    if (!versioned) ctx = makeContext(c.display, false, false);  // to report what the driver has
    if (ctx == EGL_NO_CONTEXT || !eglMakeCurrent(c.display, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) {
      tried += " " + c.description + ": no OpenGL context;";
      if (ctx != EGL_NO_CONTEXT) eglDestroyContext(c.display, ctx);
      eglTerminate(c.display);
      continue;
    }
    auto context = std::make_unique<EglContext>(c.display, ctx, c.description);
    if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(eglGetProcAddress)))
      throw Error("EGL: " + c.description + ": could not load OpenGL functions");
    requireGl43(c.description);
    if (options.debug) enableDebugOutput();
    return context;
  }
  throw Error("EGL found no usable display (" +
              (tried.empty() ? std::string(" no device or surfaceless platform") : tried) + ")");
}

}  // namespace tidepool::gl
