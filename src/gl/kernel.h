// A compute kernel with typed uniforms and declared storage bindings. Its uniforms are one plain
// struct that names each field's GLSL uniform once; its storage blocks are a list of binding
// points. Both are checked against the program when it is built and on every hot reload, so a
// misspelled, missing or mistyped uniform, or a block at an undeclared binding, is a GlError
// naming the kernel file and the uniform instead of a silent no-op (gl/kernel_check.h).
//
//   struct ScanUniforms {
//     GLuint count = 0;  // elements
//     GLuint first = 0;
//     static constexpr auto fields() {
//       return std::tuple{gl::field("uCount", &ScanUniforms::count), gl::field("uFirst", &ScanUniforms::first)};
//     }
//   };
//   gl::Kernel<ScanUniforms> scan(shaders, "grid/scan.comp", {GRID_IN, GRID_OUT}, {{"WG", "256"}});
//   scan.dispatchThreads(n, {.count = n});  // sets every field, then dispatches
//
// A field may be a struct with fields() of its own (gl::field(&Outer::grid), no name): its fields
// are set as if listed in place. Samplers and images take an int field: their unit.
#pragma once

#include <array>
#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <initializer_list>
#include <tuple>
#include <vector>

#include "gl/kernel_check.h"
#include "gl/shader_library.h"

namespace tidepool::gl {

template <class S, class M>
struct Field {
  const char* name;  // GLSL name; nullptr for a nested struct of fields
  M S::*member;
};
template <class S, class M>
constexpr Field<S, M> field(const char* name, M S::*member) {
  return {name, member};
}
template <class S, class M>
constexpr Field<S, M> field(M S::*member) {  // a nested struct with fields() of its own
  return {nullptr, member};
}

template <class T>
concept UniformStruct = requires {
  T::fields();
};

// GL type and setter of each C++ field type.
template <class T>
struct UniformType;
#define TIDEPOOL_UNIFORM_TYPE(T, GLTYPE, CALL)                 \
  template <>                                                  \
  struct UniformType<T> {                                      \
    static constexpr GLenum type = GLTYPE;                     \
    static void set(GLuint p, GLint loc, const T& v) { CALL; } \
  }
TIDEPOOL_UNIFORM_TYPE(float, GL_FLOAT, glProgramUniform1f(p, loc, v));
TIDEPOOL_UNIFORM_TYPE(GLint, GL_INT, glProgramUniform1i(p, loc, v));
TIDEPOOL_UNIFORM_TYPE(GLuint, GL_UNSIGNED_INT, glProgramUniform1ui(p, loc, v));
TIDEPOOL_UNIFORM_TYPE(glm::vec2, GL_FLOAT_VEC2, glProgramUniform2fv(p, loc, 1, glm::value_ptr(v)));
TIDEPOOL_UNIFORM_TYPE(glm::vec3, GL_FLOAT_VEC3, glProgramUniform3fv(p, loc, 1, glm::value_ptr(v)));
TIDEPOOL_UNIFORM_TYPE(glm::vec4, GL_FLOAT_VEC4, glProgramUniform4fv(p, loc, 1, glm::value_ptr(v)));
TIDEPOOL_UNIFORM_TYPE(glm::ivec2, GL_INT_VEC2, glProgramUniform2iv(p, loc, 1, glm::value_ptr(v)));
TIDEPOOL_UNIFORM_TYPE(glm::ivec3, GL_INT_VEC3, glProgramUniform3iv(p, loc, 1, glm::value_ptr(v)));
TIDEPOOL_UNIFORM_TYPE(glm::uvec2, GL_UNSIGNED_INT_VEC2, glProgramUniform2uiv(p, loc, 1, glm::value_ptr(v)));
TIDEPOOL_UNIFORM_TYPE(glm::uvec3, GL_UNSIGNED_INT_VEC3, glProgramUniform3uiv(p, loc, 1, glm::value_ptr(v)));
TIDEPOOL_UNIFORM_TYPE(glm::uvec4, GL_UNSIGNED_INT_VEC4, glProgramUniform4uiv(p, loc, 1, glm::value_ptr(v)));
TIDEPOOL_UNIFORM_TYPE(glm::mat4, GL_FLOAT_MAT4, glProgramUniformMatrix4fv(p, loc, 1, GL_FALSE, glm::value_ptr(v)));
#undef TIDEPOOL_UNIFORM_TYPE
template <std::size_t N>
struct UniformType<std::array<glm::vec4, N>> {  // uniform vec4 name[N]
  static constexpr GLenum type = GL_FLOAT_VEC4;
  static void set(GLuint p, GLint loc, const std::array<glm::vec4, N>& v) {
    glProgramUniform4fv(p, loc, GLsizei(N), glm::value_ptr(v[0]));
  }
};

// Calls f(name, value) for every leaf field of u, nested structs in place, in declaration order.
template <UniformStruct U, class F>
void forEachUniform(const U& u, F&& f) {
  std::apply(
      [&](const auto&... fields) {
        auto one = [&](const auto& fd) {
          const auto& value = u.*(fd.member);
          if constexpr (UniformStruct<std::remove_cvref_t<decltype(value)>>)
            forEachUniform(value, f);
          else
            f(fd.name, value);
        };
        (one(fields), ...);
      },
      U::fields());
}

template <UniformStruct U>
KernelInterface kernelInterface(std::initializer_list<GLuint> storage) {
  KernelInterface k{{}, std::vector<GLuint>(storage)};
  forEachUniform(U{}, [&](const char* name, const auto& v) {
    k.uniforms.push_back({name, UniformType<std::remove_cvref_t<decltype(v)>>::type});
  });
  return k;
}

template <class U>  // a UniformStruct; not constrained here, so that a class may hold a Kernel of its nested struct
class Kernel {
 public:
  Kernel() = default;
  // Builds (or finds) file with defines and checks it; the library keeps checking it on reload.
  Kernel(ShaderLibrary& shaders, const std::string& file, std::initializer_list<GLuint> storage,
         const std::vector<ShaderDefine>& defines = {})
      : m_program(&shaders.program({file}, defines, kernelInterface<U>(storage))) {}

  void set(const U& u) const {
    refreshLocations();
    std::size_t i = 0;
    forEachUniform(u, [&](const char*, const auto& v) {
      UniformType<std::remove_cvref_t<decltype(v)>>::set(m_program->id(), m_locations[i++], v);
    });
  }
  // use(), set(u), then at least `threads` invocations (Program::dispatchThreads).
  void dispatchThreads(std::size_t threads, const U& u) const {
    m_program->use();
    set(u);
    m_program->dispatchThreads(threads);
  }
  void dispatch(glm::uvec3 groups, const U& u) const {
    m_program->use();
    set(u);
    m_program->dispatch(groups);
  }
  bool built() const { return m_program != nullptr; }  // false when default-constructed
  const Program& program() const { return *m_program; }
  glm::uvec3 localSize() const { return m_program->localSize(); }

 private:
  Program* m_program = nullptr;
  mutable std::vector<GLint> m_locations;
  mutable std::uint64_t m_generation = ~std::uint64_t(0);  // of the program the locations are for

  void refreshLocations() const {
    if (m_generation == m_program->generation()) return;
    m_locations.clear();
    forEachUniform(U{}, [&](const char* name, const auto&) { m_locations.push_back(m_program->uniform(name)); });
    m_generation = m_program->generation();
  }
};

}  // namespace tidepool::gl
