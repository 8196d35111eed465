#include "gl/info.h"

#include <sstream>

#include "gl/gl.h"

namespace tidepool::gl {
namespace {
std::string str(GLenum e) {
  const GLubyte* s = glGetString(e);
  return s ? reinterpret_cast<const char*>(s) : "?";
}
}  // namespace

GlInfo queryInfo() {
  GlInfo i;
  i.vendor = str(GL_VENDOR);
  i.renderer = str(GL_RENDERER);
  i.version = str(GL_VERSION);
  i.glsl = str(GL_SHADING_LANGUAGE_VERSION);
  glGetIntegerv(GL_MAJOR_VERSION, &i.major);
  glGetIntegerv(GL_MINOR_VERSION, &i.minor);
  for (GLuint d = 0; d < 3; ++d) {
    glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_SIZE, d, &i.maxWorkGroupSize[d]);
    glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, d, &i.maxWorkGroupCount[d]);
  }
  glGetIntegerv(GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS, &i.maxWorkGroupInvocations);
  glGetIntegerv(GL_MAX_COMPUTE_SHARED_MEMORY_SIZE, &i.maxSharedMemoryBytes);
  GLint64 ssbo = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &ssbo);
  i.maxSsboBytes = ssbo;
  glGetIntegerv(GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS, &i.maxSsboBindings);
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &i.maxTextureSize);
  if (GLAD_GL_NVX_gpu_memory_info) {
    GLint total = 0, avail = 0;
    glGetIntegerv(GL_GPU_MEMORY_INFO_TOTAL_AVAILABLE_MEMORY_NVX, &total);
    glGetIntegerv(GL_GPU_MEMORY_INFO_CURRENT_AVAILABLE_VIDMEM_NVX, &avail);
    i.totalMemoryKb = total;
    i.freeMemoryKb = avail;
  } else if (GLAD_GL_ATI_meminfo) {
    GLint vbo[4] = {0, 0, 0, 0};
    glGetIntegerv(GL_VBO_FREE_MEMORY_ATI, vbo);
    i.freeMemoryKb = vbo[0];
  }
  GLint bits = 0;
  glGetQueryiv(GL_TIME_ELAPSED, GL_QUERY_COUNTER_BITS, &bits);
  i.timerQueries = bits > 0;
  glGetError();  // memory-info enums on drivers that only half support them
  return i;
}

std::string formatInfo(const GlInfo& i) {
  std::ostringstream o;
  auto mb = [](std::int64_t kb) { return kb < 0 ? std::string("unknown") : std::to_string(kb / 1024) + " MiB"; };
  o << "GL_VENDOR                 " << i.vendor << "\n"
    << "GL_RENDERER               " << i.renderer << "\n"
    << "GL_VERSION                " << i.version << "\n"
    << "GLSL                      " << i.glsl << "\n"
    << "context version           " << i.major << "." << i.minor << " core\n"
    << "compute work-group size   " << i.maxWorkGroupSize[0] << " x " << i.maxWorkGroupSize[1] << " x "
    << i.maxWorkGroupSize[2] << " (max " << i.maxWorkGroupInvocations << " invocations)\n"
    << "compute work-group count  " << i.maxWorkGroupCount[0] << " x " << i.maxWorkGroupCount[1] << " x "
    << i.maxWorkGroupCount[2] << "\n"
    << "shared memory per group   " << i.maxSharedMemoryBytes << " bytes\n"
    << "max SSBO size             " << i.maxSsboBytes << " bytes (" << i.maxSsboBytes / (1024 * 1024) << " MiB)\n"
    << "SSBO bindings             " << i.maxSsboBindings << "\n"
    << "max texture size          " << i.maxTextureSize << "\n"
    << "GPU memory total / free   " << mb(i.totalMemoryKb) << " / " << mb(i.freeMemoryKb) << "\n"
    << "timer queries             " << (i.timerQueries ? "yes" : "no") << "\n";
  return o.str();
}

}  // namespace tidepool::gl
