#include "gl/debug.h"

#include <string>

#include "base/log.h"
#include "gl/gl.h"

namespace tidepool::gl {
namespace {
void GLAPIENTRY onMessage(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei, const GLchar* message,
                          const void*) {
  (void)source;
  if (severity == GL_DEBUG_SEVERITY_NOTIFICATION) return;
  const std::string text = "GL [" + std::to_string(id) + "] " + message;
  if (type == GL_DEBUG_TYPE_ERROR)
    log::error(text);
  else if (severity == GL_DEBUG_SEVERITY_HIGH)
    log::warn(text);
  else
    log::debug(text);
}
}  // namespace

void enableDebugOutput() {
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDebugMessageCallback(onMessage, nullptr);
}

}  // namespace tidepool::gl
