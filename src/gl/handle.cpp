#include "gl/handle.h"

#include <atomic>

namespace tidepool::gl {
namespace {
std::array<std::atomic<int>, static_cast<int>(Kind::Count)> g_live{};
}

int liveCount(Kind kind) { return g_live[static_cast<int>(kind)].load(); }

namespace detail {
void noteCreated(Kind kind) { ++g_live[static_cast<int>(kind)]; }
void noteReleased(Kind kind) { --g_live[static_cast<int>(kind)]; }

GLuint generate(Kind kind) {
  GLuint name = 0;
  switch (kind) {
    case Kind::Buffer: glGenBuffers(1, &name); break;
    case Kind::Texture: glGenTextures(1, &name); break;
    case Kind::Framebuffer: glGenFramebuffers(1, &name); break;
    case Kind::VertexArray: glGenVertexArrays(1, &name); break;
    case Kind::Query: glGenQueries(1, &name); break;
    case Kind::Program:
    case Kind::Shader:
    case Kind::Count: break;  // Handle::generate() does not compile for these
  }
  return name;
}

void release(Kind kind, GLuint name) {
  switch (kind) {
    case Kind::Buffer: glDeleteBuffers(1, &name); break;
    case Kind::Texture: glDeleteTextures(1, &name); break;
    case Kind::Framebuffer: glDeleteFramebuffers(1, &name); break;
    case Kind::VertexArray: glDeleteVertexArrays(1, &name); break;
    case Kind::Query: glDeleteQueries(1, &name); break;
    case Kind::Program: glDeleteProgram(name); break;
    case Kind::Shader: glDeleteShader(name); break;
    case Kind::Count: break;
  }
}
}  // namespace detail
}  // namespace tidepool::gl
