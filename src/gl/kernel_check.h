// What a typed kernel (gl/kernel.h) declares about its program, and the check of that declaration
// against the linked program, run by the ShaderLibrary at build and on every hot reload.
#pragma once

#include <string>
#include <vector>

#include "gl/program.h"

namespace tidepool::gl {

// GL 4.3's guaranteed minimum of GL_MAX_COMPUTE_SHADER_STORAGE_BLOCKS: kernels stay within it on
// every driver, even where this one offers more.
inline constexpr int kMaxKernelStorageBlocks = 8;

struct UniformSpec {
  std::string name;  // GLSL name, e.g. "uCount"
  GLenum type;       // of the C++ field: GL_UNSIGNED_INT, GL_FLOAT_VEC3, ...; GL_INT also sets a sampler or image unit
  bool operator==(const UniformSpec&) const = default;
};

struct KernelInterface {
  std::vector<UniformSpec> uniforms;  // every uniform the kernel sets
  std::vector<GLuint> storage;        // the storage-block binding points it may use
  bool operator==(const KernelInterface&) const = default;
};

// Throws GlError, one line naming the kernel and the uniform or block, when
//  - a declared uniform is neither active nor declared in the source as `uniform <type> <name>`
//    (misspelled; one optimised out or under another variant's #if is fine),
//  - an active uniform outside uniform blocks (gl_* aside) has no field (missing),
//  - an active uniform's GL type differs from its field's (int fields may set sampler/image units),
//  - an active storage block sits at an undeclared binding, or there are more than
//    kMaxKernelStorageBlocks of them.
void checkKernel(const Program& program, const std::string& source, const KernelInterface& kernel);

std::string glslTypeName(GLenum type);  // "uint", "vec3", ...; "type 0x8b5e" when unknown

}  // namespace tidepool::gl
