#include "gl/context.h"

#include "gl/debug.h"

namespace tidepool::gl {

Backend parseBackend(std::string_view name) {
  if (name == "auto") return Backend::Auto;
  if (name == "egl") return Backend::Egl;
  if (name == "osmesa") return Backend::OsMesa;
  if (name == "window") return Backend::Window;
  throw Error("unknown backend '" + std::string(name) + "': expected auto, egl, osmesa or window");
}

std::unique_ptr<Context> createHeadlessContext(const ContextOptions& options) {
  switch (options.backend) {
    case Backend::Egl: return createEglContext(options);
    case Backend::OsMesa: return createOsMesaContext(options);
    case Backend::Window: throw Error("the window backend is not headless: use 'tidepool run' for a window");
    case Backend::Auto: break;
  }
  try {
    return createEglContext(options);
  } catch (const Error& eglError) {
    try {
      return createOsMesaContext(options);
    } catch (const Error& osmesaError) {
      throw Error(std::string("no headless OpenGL 4.3 context: ") + eglError.what() + "; " + osmesaError.what());
    }
  }
}

void requireGl43(const std::string& backend) {
  GLint major = 0, minor = 0, invocations = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  if (major > 4 || (major == 4 && minor >= 3)) glGetIntegerv(GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS, &invocations);
  if (invocations > 0) return;
  auto str = [](GLenum e) {
    const GLubyte* s = glGetString(e);
    return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
  };
  throw Error("OpenGL 4.3 with compute shaders is required, but the " + backend + " backend found vendor '" +
              str(GL_VENDOR) + "', renderer '" + str(GL_RENDERER) + "', version '" + str(GL_VERSION) +
              "'; to run on the CPU with Mesa llvmpipe: LIBGL_ALWAYS_SOFTWARE=1 tidepool ... --backend egl");
}

}  // namespace tidepool::gl
