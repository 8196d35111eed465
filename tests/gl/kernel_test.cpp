// gl::Kernel: a kernel's uniform struct and storage bindings are checked against the program at
// build and on reload; a correct kernel sets every field and dispatches; the models' kernels are
// checked the same way.
#include "gl/kernel.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "gl/buffer.h"
#include "sim/balls/balls.h"
#include "sim/fluid/fluid.h"
#include "support/balls_fixtures.h"
#include "support/error_of.h"
#include "support/gl_test.h"

using namespace tidepool;
using namespace tidepool::gl;
using tidepool::test::TempDir;

namespace {

class KernelTest : public test::GlTest {};

// values[i] = i * uScale + uOffset for i < uCount; uOther exists only with OTHER defined, uUnused
// is declared but optimised out; EXTRA adds a second storage block at binding 3.
const char* kScale = R"(#version 430 core
layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer Out { uint values[]; };
#if EXTRA
layout(std430, binding = 3) buffer Extra { uint extra[]; };
#endif
uniform uint uCount;
uniform float uScale;
uniform uint uOffset;
uniform float uUnused;
#ifdef OTHER
uniform vec3 uOther;
#endif
void main() {
  const uint i = gl_GlobalInvocationID.x;
  if (i >= uCount) return;
  values[i] = uint(float(i) * uScale) + uOffset;
#if EXTRA
  extra[i] = i;
#endif
}
)";

struct Offset {
  GLuint offset = 0;
  static constexpr auto fields() { return std::tuple{field("uOffset", &Offset::offset)}; }
};
struct ScaleUniforms {
  GLuint count = 0;
  float scale = 1.0f;
  Offset offset;        // a nested struct of fields
  float unused = 0.0f;  // declared, optimised out: fine
  glm::vec3 other{};    // declared for another variant: fine
  static constexpr auto fields() {
    return std::tuple{field("uCount", &ScaleUniforms::count), field("uScale", &ScaleUniforms::scale),
                      field(&ScaleUniforms::offset), field("uUnused", &ScaleUniforms::unused),
                      field("uOther", &ScaleUniforms::other)};
  }
};
struct Misspelled {
  GLuint count = 0, offset = 0;
  float scale = 1.0f;
  static constexpr auto fields() {
    return std::tuple{field("uCount", &Misspelled::count), field("uScael", &Misspelled::scale),
                      field("uOffset", &Misspelled::offset)};
  }
};
struct Missing {
  GLuint count = 0, offset = 0;
  static constexpr auto fields() {
    return std::tuple{field("uCount", &Missing::count), field("uOffset", &Missing::offset)};
  }
};
struct Mistyped {
  GLuint count = 0, offset = 0;
  GLint scale = 1;
  static constexpr auto fields() {
    return std::tuple{field("uCount", &Mistyped::count), field("uScale", &Mistyped::scale),
                      field("uOffset", &Mistyped::offset)};
  }
};

// The GlError message of building kernel U from kScale ("" when it builds).
template <class U>
std::string buildError(std::initializer_list<GLuint> storage, const std::vector<ShaderDefine>& defines = {}) {
  TempDir dir;
  dir.write("scale.comp", kScale);
  ShaderLibrary lib(dir.path());
  try {
    Kernel<U> kernel(lib, "scale.comp", storage, defines);
  } catch (const GlError& e) {
    return e.what();
  }
  return "";
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_F(KernelTest, MisspelledFieldIsAnErrorNamingTheKernelAndTheUniform) {
  const std::string msg = buildError<Misspelled>({0});
  EXPECT_TRUE(has(msg, "kernel 'scale.comp'") && has(msg, "'uScael'") && has(msg, "not declared")) << msg;
  EXPECT_EQ(msg.find('\n'), std::string::npos) << "one line: " << msg;
}

TEST_F(KernelTest, ActiveUniformWithoutAFieldIsAnError) {
  const std::string msg = buildError<Missing>({0});
  EXPECT_TRUE(has(msg, "active uniform 'uScale'") && has(msg, "not set")) << msg;
}

TEST_F(KernelTest, FieldTypeDifferentFromTheShadersIsAnError) {
  const std::string msg = buildError<Mistyped>({0});
  EXPECT_TRUE(has(msg, "'uScale' is float in the shader but int")) << msg;
}

TEST_F(KernelTest, StorageBlockAtAnUndeclaredBindingIsAnError) {
  EXPECT_EQ(buildError<ScaleUniforms>({0, 3}, {{"EXTRA", "1"}}), "");
  const std::string msg = buildError<ScaleUniforms>({0}, {{"EXTRA", "1"}});
  EXPECT_TRUE(has(msg, "storage block 'Extra' at binding 3") && has(msg, "declared bindings {0}")) << msg;
}

TEST_F(KernelTest, FieldsOfOtherVariantsAndOptimisedOutOnesAreFine) {
  EXPECT_EQ(buildError<ScaleUniforms>({0}), "");
  EXPECT_EQ(buildError<ScaleUniforms>({0}, {{"OTHER", ""}}), "");  // uOther declared but unused
}

TEST_F(KernelTest, CorrectKernelSetsEveryFieldAndDispatches) {
  TempDir dir;
  dir.write("scale.comp", kScale);
  ShaderLibrary lib(dir.path());
  const Kernel<ScaleUniforms> kernel(lib, "scale.comp", {0});
  Buffer out(200 * sizeof(GLuint));
  out.fillZero();
  out.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
  kernel.dispatchThreads(150, {.count = 150, .scale = 3.0f, .offset = {5}});
  kernel.dispatchThreads(10, {.count = 10, .scale = 2.0f, .offset = {1}});  // values change per dispatch
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  const std::vector<GLuint> got = out.read<GLuint>(200);
  for (GLuint i = 0; i < 200; ++i) {
    const GLuint want = i < 10 ? i * 2 + 1 : i < 150 ? i * 3 + 5 : 0;
    ASSERT_EQ(got[i], want) << "value " << i;
  }
}

TEST_F(KernelTest, ReloadChecksAgainAndKeepsTheOldProgramOnFailure) {
  TempDir dir;
  dir.write("scale.comp", kScale);
  ShaderLibrary lib(dir.path());
  const Kernel<ScaleUniforms> kernel(lib, "scale.comp", {0});
  const GLuint before = kernel.program().id();
  std::string renamed = kScale;
  renamed.replace(renamed.find("uScale;"), 6, "uScale2");  // the struct's uScale no longer exists
  renamed.replace(renamed.find("float(i) * uScale"), 17, "float(i) * uScale2");
  dir.write("scale.comp", renamed);
  const ShaderLibrary::ReloadResult result = lib.reload();
  ASSERT_EQ(result.errors.size(), 1u);
  EXPECT_TRUE(has(result.errors[0], "'uScale'") || has(result.errors[0], "'uScale2'")) << result.errors[0];
  EXPECT_EQ(kernel.program().id(), before);
  dir.write("scale.comp", kScale);
  EXPECT_TRUE(lib.reload().errors.empty());
  EXPECT_NE(kernel.program().id(), before);
  Buffer out(4 * sizeof(GLuint));
  out.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
  kernel.dispatchThreads(4, {.count = 4, .scale = 1.0f, .offset = {2}});  // locations of the new program
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  EXPECT_EQ(out.read<GLuint>(4), (std::vector<GLuint>{2, 3, 4, 5}));
}

namespace {

// The shader folder copied into dir with `from` replaced by `to` everywhere in `file`.
void copyShadersRenaming(const std::filesystem::path& shaders, const TempDir& dir, const std::string& file,
                         const std::string& from, const std::string& to) {
  std::filesystem::copy(shaders, dir.path(), std::filesystem::copy_options::recursive);
  std::ifstream in(dir / file);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_NE(text.find(from), std::string::npos) << file << " has no " << from;
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  dir.write(file, text);
}

}  // namespace

// The models' own kernels are typed: a uniform renamed in a shader (it still compiles) is an
// error naming the kernel and the uniform the first time the pass runs, not a silent zero.
TEST_F(KernelTest, ABallsOrFluidUniformRenamedInItsShaderIsAnError) {
  {
    TempDir dir;
    copyShadersRenaming(shaderDir(), dir, "balls/contact.glsl", "uFriction", "uFrictionRenamed");
    ShaderLibrary lib(dir.path());
    balls::Params p = test::emptyTank();
    p.contact = balls::Contact::SpringDashpot;
    balls::Balls b(lib, p);
    b.upload({glm::vec4(0.2f, 0.15f, 0.1f, 1.0f)}, {glm::vec4(0.0f)});
    const std::string msg = test::errorOf([&] { b.stepOnce(); });
    EXPECT_TRUE(has(msg, "balls/collide.comp") && has(msg, "'uFriction'") && has(msg, "not declared")) << msg;
  }
  {
    TempDir dir;
    copyShadersRenaming(shaderDir(), dir, "fluid/viscosity.comp", "uViscosity", "uViscosityRenamed");
    ShaderLibrary lib(dir.path());
    fluid::Params p;
    p.setSpacing(0.02f);
    p.domainMax = glm::vec3(0.2f, 0.2f, 0.3f);
    p.fill = water::Fill::None;
    p.viscosity = 0.01f;
    fluid::Fluid f(lib, p);
    f.upload({glm::vec4(0.1f, 0.1f, 0.1f, 1.0f)}, {glm::vec4(0.0f)});
    const std::string msg = test::errorOf([&] { f.stepOnce(); });
    EXPECT_TRUE(has(msg, "fluid/viscosity.comp") && has(msg, "'uViscosity'") && has(msg, "not declared")) << msg;
  }
}
