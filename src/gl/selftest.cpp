#include "gl/selftest.h"

#include "gl/buffer.h"
#include "gl/kernel.h"
#include "selftest/bindings.glsl"

namespace tidepool::gl {
namespace {
struct FillUniforms {
  GLuint count = 0, mul = 0;
  static constexpr auto fields() {
    return std::tuple{field("uCount", &FillUniforms::count), field("uMul", &FillUniforms::mul)};
  }
};
}  // namespace

std::string computeSelfTest(ShaderLibrary& shaders, unsigned count) {
  const Kernel<FillUniforms> fill(shaders, "selftest/fill.comp", {SELFTEST_OUT});
  Buffer out(std::size_t(count) * sizeof(GLuint));
  out.bindBase(GL_SHADER_STORAGE_BUFFER, SELFTEST_OUT);
  fill.dispatchThreads(count, {.count = count, .mul = 7u});
  const std::vector<GLuint> got = out.read<GLuint>(count);
  for (unsigned i = 0; i < count; ++i)
    if (got[i] != i * 7u + 1u)
      return "value " + std::to_string(i) + " is " + std::to_string(got[i]) + ", expected " +
             std::to_string(i * 7u + 1u);
  return "";
}

}  // namespace tidepool::gl
