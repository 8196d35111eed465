#include "gl/selftest.h"

#include "gl/buffer.h"
#include "selftest/bindings.glsl"

namespace tidepool::gl {

std::string computeSelfTest(ShaderLibrary& shaders, unsigned count) {
  Program& fill = shaders.program({"selftest/fill.comp"});
  Buffer out(std::size_t(count) * sizeof(GLuint));
  out.bindBase(GL_SHADER_STORAGE_BUFFER, SELFTEST_OUT);
  fill.use();
  fill.set("uCount", count);
  fill.set("uMul", 7u);
  fill.dispatchThreads(count);
  const std::vector<GLuint> got = out.read<GLuint>(count);
  for (unsigned i = 0; i < count; ++i)
    if (got[i] != i * 7u + 1u)
      return "value " + std::to_string(i) + " is " + std::to_string(got[i]) + ", expected " +
             std::to_string(i * 7u + 1u);
  return "";
}

}  // namespace tidepool::gl
