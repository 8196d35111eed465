// Compile errors name the original file and line; reload keeps the old program on failure.
#include <gtest/gtest.h>

#include "gl/buffer.h"
#include "support/gl_test.h"

using namespace tidepool;
using namespace tidepool::gl;
using tidepool::test::TempDir;

namespace {

class ShaderLibraryTest : public test::GlTest {};

const char* kWriter = R"(#version 430 core
#include "common/value.glsl"
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer Out { uint result[]; };
void main() { result[0] = value(); }
)";

uint32_t runWriter(Program& p) {
  Buffer out(sizeof(uint32_t));
  out.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
  p.use();
  p.dispatch({1, 1, 1});
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  return out.read<uint32_t>(1)[0];
}

// The message of the GlError that building w.comp (kWriter, then `more`) with `value` as
// common/value.glsl throws; "" when it builds.
std::string buildError(const std::string& value, const std::string& more = "") {
  TempDir dir;
  dir.write("w.comp", kWriter + more);
  dir.write("common/value.glsl", value);
  ShaderLibrary lib(dir.path());
  try {
    lib.program({"w.comp"});
  } catch (const GlError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_F(ShaderLibraryTest, CompileErrorInIncludedFileNamesThatFileAndLine) {
  const std::string msg = buildError("// value\n\nuint value() { return undeclared_thing; }\n");
  ASSERT_FALSE(msg.empty()) << "expected a compile error";
  const std::string firstLine = msg.substr(0, msg.find('\n'));
  EXPECT_NE(firstLine.find("'w.comp' failed to compile at common/value.glsl:3"), std::string::npos) << msg;
}

TEST_F(ShaderLibraryTest, ErrorInRootFileAfterAnIncludeKeepsItsLineNumber) {
  const std::string msg = buildError("uint value() { return 7u; }\n", "\n\nvoid broken() { nope(); }\n");  // line 8
  ASSERT_FALSE(msg.empty()) << "expected a compile error";
  EXPECT_NE(msg.find("at w.comp:8"), std::string::npos) << msg;
}

TEST_F(ShaderLibraryTest, DefinesAreInjectedAndCachedSeparately) {
  TempDir dir;
  dir.write("w.comp", kWriter);
  dir.write("common/value.glsl", "uint value() { return VALUE; }\n");
  ShaderLibrary lib(dir.path());
  Program& a = lib.program({"w.comp"}, {{"VALUE", "11u"}});
  Program& b = lib.program({"w.comp"}, {{"VALUE", "22u"}});
  EXPECT_NE(&a, &b);
  EXPECT_EQ(&a, &lib.program({"w.comp"}, {{"VALUE", "11u"}}));
  EXPECT_EQ(runWriter(a), 11u);
  EXPECT_EQ(runWriter(b), 22u);
  EXPECT_EQ(a.label(), "w.comp [VALUE=11u]");
}

TEST_F(ShaderLibraryTest, ReloadSwapsInNewCodeAndKeepsOldProgramOnFailure) {
  TempDir dir;
  dir.write("w.comp", kWriter);
  dir.write("common/value.glsl", "uint value() { return 1u; }\n");
  ShaderLibrary lib(dir.path());
  Program& p = lib.program({"w.comp"});
  EXPECT_EQ(runWriter(p), 1u);

  dir.write("common/value.glsl", "uint value() { return 2u; }\n");
  auto ok = lib.reload();
  EXPECT_EQ(ok.reloaded, 1);
  EXPECT_TRUE(ok.errors.empty());
  EXPECT_EQ(runWriter(p), 2u);

  dir.write("common/value.glsl", "uint value() { return syntax error }\n");
  auto bad = lib.reload();
  EXPECT_EQ(bad.reloaded, 0);
  ASSERT_EQ(bad.errors.size(), 1u);
  EXPECT_NE(bad.errors[0].find("common/value.glsl:1"), std::string::npos) << bad.errors[0];
  EXPECT_EQ(runWriter(p), 2u) << "the previous program must stay in use";
}

TEST_F(ShaderLibraryTest, LinkErrorAndUnknownStageAreReported) {
  TempDir dir;
  dir.write("a.vert", "#version 430 core\nout vec4 c;\nvoid main() { gl_Position = vec4(0); c = vec4(1); }\n");
  dir.write("a.frag", "#version 430 core\nin vec3 c;\nout vec4 o;\nvoid main() { o = vec4(c, 1); }\n");
  dir.write("a.txt", "nothing");
  ShaderLibrary lib(dir.path());
  EXPECT_THROW(lib.program({"a.vert", "a.frag"}), GlError);
  EXPECT_THROW(lib.program({"a.txt"}), GlError);
}

TEST(ShaderLibraryDir, UnreadableOrMissingDirectoryIsAClearError) {
  EXPECT_THROW(ShaderLibrary("/nonexistent/shaders"), Error);
  setenv("TIDEPOOL_SHADER_DIR", "/nonexistent/shaders", 1);
  try {
    ShaderLibrary::findRoot();
    ADD_FAILURE() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("TIDEPOOL_SHADER_DIR"), std::string::npos);
  }
  unsetenv("TIDEPOOL_SHADER_DIR");
  EXPECT_TRUE(std::filesystem::exists(ShaderLibrary::findRoot() / "common" / "index.glsl"));
}
