#include "gl/program.h"

#include <atomic>
#include <glm/gtc/type_ptr.hpp>

namespace tidepool::gl {

Program::Program(Handle<Kind::Program> handle, std::string label)
    : m_handle(std::move(handle)), m_label(std::move(label)) {}

void Program::swap(Program& other) noexcept {
  std::swap(m_handle, other.m_handle);
  m_locations.clear();
  other.m_locations.clear();
  m_generation = nextGeneration();
  other.m_generation = nextGeneration();
}

std::uint64_t Program::nextGeneration() {
  static std::atomic<std::uint64_t> next{0};
  return next++;
}

GLint Program::uniform(const char* name) const {
  auto it = m_locations.find(name);
  if (it != m_locations.end()) return it->second;
  const GLint loc = glGetUniformLocation(id(), name);
  m_locations.emplace(name, loc);
  return loc;
}

void Program::set(const char* n, float v) const { glProgramUniform1f(id(), uniform(n), v); }
void Program::set(const char* n, int v) const { glProgramUniform1i(id(), uniform(n), v); }
void Program::set(const char* n, unsigned v) const { glProgramUniform1ui(id(), uniform(n), v); }
void Program::set(const char* n, const glm::vec2& v) const {
  glProgramUniform2fv(id(), uniform(n), 1, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::vec3& v) const {
  glProgramUniform3fv(id(), uniform(n), 1, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::vec4& v) const {
  glProgramUniform4fv(id(), uniform(n), 1, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::ivec2& v) const {
  glProgramUniform2iv(id(), uniform(n), 1, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::uvec3& v) const {
  glProgramUniform3uiv(id(), uniform(n), 1, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::mat4& v) const {
  glProgramUniformMatrix4fv(id(), uniform(n), 1, GL_FALSE, glm::value_ptr(v));
}

glm::uvec3 Program::localSize() const {
  GLint size[3] = {0, 0, 0};
  glGetProgramiv(id(), GL_COMPUTE_WORK_GROUP_SIZE, size);
  return {GLuint(size[0]), GLuint(size[1]), GLuint(size[2])};
}

void Program::dispatchThreads(std::size_t threads) const {
  if (threads == 0) return;
  const std::size_t local = localSize().x;
  std::size_t groups = (threads + local - 1) / local;
  static const GLint maxX = [] {  // one GL query per process, not per dispatch
    GLint v = 0;
    glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, 0, &v);
    return v;
  }();
  const std::size_t x = std::min<std::size_t>(groups, std::size_t(maxX));
  const std::size_t y = (groups + x - 1) / x;
  glDispatchCompute(GLuint(x), GLuint(y), 1u);
}

void Program::dispatch(glm::uvec3 groups) const { glDispatchCompute(groups.x, groups.y, groups.z); }

}  // namespace tidepool::gl
