#include "gl/kernel_check.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <regex>

#include "base/error.h"

namespace tidepool::gl {
namespace {

// Each active resource of `interface` (GL_UNIFORM, GL_SHADER_STORAGE_BLOCK): f(name, values of props).
template <std::size_t N, class F>
void forEachResource(GLuint program, GLenum interface, const std::array<GLenum, N>& props, F&& f) {
  GLint count = 0;
  glGetProgramInterfaceiv(program, interface, GL_ACTIVE_RESOURCES, &count);
  for (GLint i = 0; i < count; ++i) {
    std::array<GLint, N> values{};
    glGetProgramResourceiv(program, interface, GLuint(i), GLsizei(N), props.data(), GLsizei(N), nullptr, values.data());
    GLint length = 0;
    const GLenum nameLength = GL_NAME_LENGTH;
    glGetProgramResourceiv(program, interface, GLuint(i), 1, &nameLength, 1, nullptr, &length);
    std::string name(std::size_t(std::max(length, 1)), '\0');
    glGetProgramResourceName(program, interface, GLuint(i), length, nullptr, name.data());
    name.resize(name.find('\0') == std::string::npos ? name.size() : name.find('\0'));
    f(name, values);
  }
}

struct ActiveUniform {
  std::string name;  // "[0]" of an array dropped
  GLenum type;
};

// The program's own uniforms: not members of uniform blocks, not gl_* built-ins.
std::vector<ActiveUniform> activeUniforms(GLuint program) {
  std::vector<ActiveUniform> result;
  forEachResource(program, GL_UNIFORM, std::array<GLenum, 2>{GL_BLOCK_INDEX, GL_TYPE}, [&](std::string name, auto v) {
    if (v[0] != -1 || name.starts_with("gl_")) return;
    if (name.ends_with("[0]")) name.resize(name.size() - 3);
    result.push_back({name, GLenum(v[1])});
  });
  return result;
}

struct StorageBlock {
  std::string name;
  GLuint binding;
};

std::vector<StorageBlock> storageBlocks(GLuint program) {
  std::vector<StorageBlock> result;
  forEachResource(program, GL_SHADER_STORAGE_BLOCK, std::array<GLenum, 1>{GL_BUFFER_BINDING},
                  [&](const std::string& name, auto v) {
                    result.push_back({name, GLuint(v[0])});
                  });
  return result;
}

// Numeric GLSL types; every other uniform type (samplers, images) is set by its unit, an int.
bool isNumeric(GLenum type) {
  switch (type) {
    case GL_FLOAT:
    case GL_FLOAT_VEC2:
    case GL_FLOAT_VEC3:
    case GL_FLOAT_VEC4:
    case GL_DOUBLE:
    case GL_DOUBLE_VEC2:
    case GL_DOUBLE_VEC3:
    case GL_DOUBLE_VEC4:
    case GL_INT:
    case GL_INT_VEC2:
    case GL_INT_VEC3:
    case GL_INT_VEC4:
    case GL_UNSIGNED_INT:
    case GL_UNSIGNED_INT_VEC2:
    case GL_UNSIGNED_INT_VEC3:
    case GL_UNSIGNED_INT_VEC4:
    case GL_BOOL:
    case GL_BOOL_VEC2:
    case GL_BOOL_VEC3:
    case GL_BOOL_VEC4:
    case GL_FLOAT_MAT2:
    case GL_FLOAT_MAT3:
    case GL_FLOAT_MAT4:
    case GL_FLOAT_MAT2x3:
    case GL_FLOAT_MAT2x4:
    case GL_FLOAT_MAT3x2:
    case GL_FLOAT_MAT3x4:
    case GL_FLOAT_MAT4x2:
    case GL_FLOAT_MAT4x3: return true;
    default: return false;
  }
}

bool declaredInSource(const std::string& source, const std::string& name) {
  const std::regex declaration("\\buniform\\s+\\w+\\s+" + name + "\\s*[;\\[=]");
  return std::regex_search(source, declaration);
}

std::string bindingList(const std::vector<GLuint>& bindings) {
  std::string text;
  for (GLuint b : bindings) text += (text.empty() ? "" : ", ") + std::to_string(b);
  return "{" + text + "}";
}

}  // namespace

std::string glslTypeName(GLenum type) {
  switch (type) {
    case GL_FLOAT: return "float";
    case GL_FLOAT_VEC2: return "vec2";
    case GL_FLOAT_VEC3: return "vec3";
    case GL_FLOAT_VEC4: return "vec4";
    case GL_INT: return "int";
    case GL_INT_VEC2: return "ivec2";
    case GL_INT_VEC3: return "ivec3";
    case GL_INT_VEC4: return "ivec4";
    case GL_UNSIGNED_INT: return "uint";
    case GL_UNSIGNED_INT_VEC2: return "uvec2";
    case GL_UNSIGNED_INT_VEC3: return "uvec3";
    case GL_UNSIGNED_INT_VEC4: return "uvec4";
    case GL_BOOL: return "bool";
    case GL_FLOAT_MAT3: return "mat3";
    case GL_FLOAT_MAT4: return "mat4";
    default: {
      char text[24];
      std::snprintf(text, sizeof text, "type 0x%04x", unsigned(type));
      return text;
    }
  }
}

void checkKernel(const Program& program, const std::string& source, const KernelInterface& kernel) {
  const std::string what = "kernel '" + program.label() + "': ";
  const std::vector<ActiveUniform> active = activeUniforms(program.id());
  for (const UniformSpec& field : kernel.uniforms) {
    auto it = std::find_if(active.begin(), active.end(), [&](const ActiveUniform& u) { return u.name == field.name; });
    if (it == active.end()) {
      if (!declaredInSource(source, field.name))
        throw GlError(what + "uniform '" + field.name +
                      "' is set by the kernel's struct but not declared in the shader");
    } else if (it->type != field.type && !(field.type == GL_INT && !isNumeric(it->type))) {
      throw GlError(what + "uniform '" + field.name + "' is " + glslTypeName(it->type) + " in the shader but " +
                    glslTypeName(field.type) + " in the kernel's struct");
    }
  }
  for (const ActiveUniform& u : active)
    if (std::none_of(kernel.uniforms.begin(), kernel.uniforms.end(),
                     [&](const UniformSpec& f) { return f.name == u.name; }))
      throw GlError(what + "active uniform '" + u.name + "' (" + glslTypeName(u.type) +
                    ") is not set by the kernel's struct: add a field for it");
  const std::vector<StorageBlock> blocks = storageBlocks(program.id());
  for (const StorageBlock& b : blocks)
    if (std::find(kernel.storage.begin(), kernel.storage.end(), b.binding) == kernel.storage.end())
      throw GlError(what + "storage block '" + b.name + "' at binding " + std::to_string(b.binding) +
                    " is not among the kernel's declared bindings " + bindingList(kernel.storage));
  if (blocks.size() > std::size_t(kMaxKernelStorageBlocks))
    throw GlError(what + std::to_string(blocks.size()) + " storage blocks, over GL 4.3's guaranteed " +
                  std::to_string(kMaxKernelStorageBlocks) + " per compute shader");
}

}  // namespace tidepool::gl
