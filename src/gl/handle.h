// Move-only ownership of one GL object name. Each GL object type gets its own Handle type, so
// passing a texture where a buffer is expected does not compile, and every name is released
// exactly once (live counts per kind are kept so tests and the UI can see leaks).
#pragma once

#include <array>
#include <cstdint>
#include <utility>

#include "gl/gl.h"

namespace tidepool::gl {

enum class Kind : int { Buffer, Texture, Framebuffer, VertexArray, Query, Program, Shader, Count };

// Number of live GL objects of a kind created through src/gl (for leak checks).
int liveCount(Kind kind);

namespace detail {
void noteCreated(Kind kind);
void noteReleased(Kind kind);
GLuint generate(Kind kind);            // glGen* for the kind (Buffer to Query)
void release(Kind kind, GLuint name);  // glDelete* for the kind
}  // namespace detail

template <Kind K>
class Handle {
 public:
  Handle() = default;
  explicit Handle(GLuint name) : m_name(name) {
    if (m_name) detail::noteCreated(K);
  }
  // A new name from glGen*; programs and shaders come from glCreate*, which their owners call.
  static Handle generate() {
    static_assert(K < Kind::Program, "programs and shaders are made by glCreateProgram / glCreateShader");
    return Handle(detail::generate(K));
  }
  ~Handle() { reset(); }
  Handle(Handle&& o) noexcept : m_name(std::exchange(o.m_name, 0)) {}
  Handle& operator=(Handle&& o) noexcept {
    if (this != &o) {
      reset();
      m_name = std::exchange(o.m_name, 0);
    }
    return *this;
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;

  GLuint get() const { return m_name; }
  explicit operator bool() const { return m_name != 0; }
  void reset() {
    if (m_name) {
      detail::release(K, m_name);
      detail::noteReleased(K);
      m_name = 0;
    }
  }

 private:
  GLuint m_name = 0;
};

}  // namespace tidepool::gl
