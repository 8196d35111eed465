// Linked GL programs: compute (one .comp) or graphics (.vert + .frag [+ .geom]).
// Built by the ShaderLibrary, which can swap a new GL program in on hot reload; uniform
// locations are cached by name and dropped on swap. Compute kernels with typed uniforms wrap a
// Program in gl::Kernel (gl/kernel.h).
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <unordered_map>

#include "gl/handle.h"

namespace tidepool::gl {

class Program {
 public:
  Program() = default;
  Program(Handle<Kind::Program> handle, std::string label);

  GLuint id() const { return m_handle.get(); }
  const std::string& label() const { return m_label; }  // e.g. "grid/scan.comp [WG=256]"
  void use() const { glUseProgram(id()); }
  void swap(Program& other) noexcept;                        // hot reload: take the other's GL program
  std::uint64_t generation() const { return m_generation; }  // new on every swap: cached locations go stale

  GLint uniform(const char* name) const;  // -1 when absent or optimised out
  void set(const char* name, float v) const;
  void set(const char* name, int v) const;
  void set(const char* name, unsigned v) const;
  void set(const char* name, const glm::vec2& v) const;
  void set(const char* name, const glm::vec3& v) const;
  void set(const char* name, const glm::vec4& v) const;
  void set(const char* name, const glm::ivec2& v) const;
  void set(const char* name, const glm::uvec3& v) const;
  void set(const char* name, const glm::mat4& v) const;

  // Compute only: local work-group size declared in the shader.
  glm::uvec3 localSize() const;
  // Compute only: runs at least `threads` invocations along x (the program must be in use).
  // Group counts beyond GL_MAX_COMPUTE_WORK_GROUP_COUNT[0] spill into y; shaders get their
  // linear index from common/index.glsl's globalIndex().
  void dispatchThreads(std::size_t threads) const;
  void dispatch(glm::uvec3 groups) const;

 private:
  Handle<Kind::Program> m_handle;
  std::string m_label;
  mutable std::unordered_map<std::string, GLint> m_locations;
  std::uint64_t m_generation = nextGeneration();
  static std::uint64_t nextGeneration();
};

}  // namespace tidepool::gl
