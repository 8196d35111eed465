// Include resolution, guards, cycle detection and log mapping: CPU only, no GL context.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "gl/shader_source.h"
#include "support/error_of.h"

using namespace tidepool;
using namespace tidepool::gl;

namespace {

ShaderFileReader files(std::map<std::string, std::string> table) {
  return [table](const std::string& path) -> std::optional<std::string> {
    auto it = table.find(path);
    return it == table.end() ? std::nullopt : std::optional(it->second);
  };
}

using test::errorOf;

int count(const std::string& text, const std::string& needle) {
  int n = 0;
  for (std::size_t p = text.find(needle); p != std::string::npos; p = text.find(needle, p + 1)) ++n;
  return n;
}

}  // namespace

// Line k of the assembled text (1-based) as "file:line".
std::string origin(const AssembledShader& s, int k) {
  const SourceLine& l = s.lines.at(std::size_t(k - 1));
  return s.files.at(std::size_t(l.file)) + ":" + std::to_string(l.line);
}

int lineOf(const std::string& text, const std::string& needle) {
  const std::size_t at = text.find(needle);
  return at == std::string::npos ? -1 : 1 + int(std::count(text.begin(), text.begin() + long(at), '\n'));
}

TEST(ShaderSource, VersionFirstThenDefinesAndALineTable) {
  auto read = files({{"a.comp", "// header comment\n#version 430 core\nvoid main() {}\n"}});
  const ShaderDefine defines[] = {{"WG", "256"}, {"USE_FOO", ""}};
  AssembledShader s = assembleShader("a.comp", read, defines);
  EXPECT_EQ(s.text, "// header comment\n#version 430 core\n#define WG 256\n#define USE_FOO \nvoid main() {}\n");
  ASSERT_EQ(s.files, std::vector<std::string>{"a.comp"});
  ASSERT_EQ(s.lines.size(), 5u);
  EXPECT_EQ(origin(s, 1), "a.comp:1");
  EXPECT_EQ(origin(s, 3), "a.comp:2") << "injected defines map to the #version line";
  EXPECT_EQ(origin(s, 5), "a.comp:3");
}

TEST(ShaderSource, IncludesArePastedOnceAndMappedToTheirFiles) {
  auto read = files(
      {{"main.comp", "#version 430 core\n#include \"common/a.glsl\"\n#include \"common/b.glsl\"\nvoid main() {}\n"},
       {"common/a.glsl", "// a\nfloat a() { return 1.0; }\n"},
       {"common/b.glsl", "#include \"common/a.glsl\"\nfloat b() { return a(); }\n"}});
  AssembledShader s = assembleShader("main.comp", read);
  EXPECT_EQ(count(s.text, "float a()"), 1) << "a.glsl is included twice but must be pasted once";
  EXPECT_EQ(count(s.text, "float b()"), 1);
  EXPECT_EQ(s.files, (std::vector<std::string>{"main.comp", "common/a.glsl", "common/b.glsl"}));
  EXPECT_EQ(origin(s, lineOf(s.text, "float a()")), "common/a.glsl:2");
  EXPECT_EQ(origin(s, lineOf(s.text, "float b()")), "common/b.glsl:2");
  EXPECT_EQ(origin(s, lineOf(s.text, "void main()")), "main.comp:4");
  EXPECT_EQ(s.text.find("#include"), std::string::npos);
  EXPECT_EQ(s.lines.size(), std::size_t(count(s.text, "\n")));
}

TEST(ShaderSource, CycleIsReportedWithTheChain) {
  auto read = files({{"main.comp", "#version 430 core\n#include \"x.glsl\"\n"},
                     {"x.glsl", "// x\n#include \"y.glsl\"\n"},
                     {"y.glsl", "#include \"x.glsl\"\n"}});
  const std::string e = errorOf([&] { assembleShader("main.comp", read); });
  EXPECT_NE(e.find("y.glsl:1: include cycle: main.comp -> x.glsl -> y.glsl -> x.glsl"), std::string::npos) << e;
}

TEST(ShaderSource, MissingIncludeNamesFileAndLine) {
  auto read = files({{"main.comp", "#version 430 core\n\n#include \"common/nope.glsl\"\n"}});
  const std::string e = errorOf([&] { assembleShader("main.comp", read); });
  EXPECT_NE(e.find("main.comp:3: cannot include \"common/nope.glsl\""), std::string::npos) << e;
}

TEST(ShaderSource, MalformedDirectivesAreErrors) {
  EXPECT_NE(errorOf([&] {
              assembleShader("m.comp", files({{"m.comp", "#version 430 core\n#include <a.glsl>\n"}}));
            }).find("m.comp:2: malformed #include"),
            std::string::npos);
  EXPECT_NE(errorOf([&] {
              assembleShader("m.comp", files({{"m.comp", "void main() {}\n"}}));
            }).find("m.comp:1: expected '#version 430 core'"),
            std::string::npos);
  EXPECT_NE(errorOf([&] {
              assembleShader("m.comp", files({{"m.comp", "#version 430 core\n#include \"i.glsl\"\n"},
                                              {"i.glsl", "#version 430 core\n"}}));
            }).find("i.glsl:1: #version is only allowed in the top-level shader"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { assembleShader("missing.comp", files({})); }).find("'missing.comp' not found"),
            std::string::npos);
}

TEST(ShaderSource, DriverLogsMapToFilesAndLines) {
  auto read = files({{"grid/scan.comp", "#version 430 core\n#include \"common/index.glsl\"\nvoid main() {}\n"},
                     {"common/index.glsl", "// 1\n// 2\nuint globalIndex() { return x; }\n"}});
  AssembledShader s = assembleShader("grid/scan.comp", read);
  // Assembled: 1 #version, 2-4 index.glsl, 5 main.
  EXPECT_EQ(mapShaderLog("0:4(12): error: `x' undeclared\n", s), "common/index.glsl:3: error: `x' undeclared\n");
  EXPECT_EQ(mapShaderLog("0(5) : error C1008: undefined variable \"y\"\n", s),
            "grid/scan.comp:3: error C1008: undefined variable \"y\"\n");
  EXPECT_EQ(mapShaderLog("ERROR: 0:4: 'z' : undeclared identifier\n", s),
            "common/index.glsl:3: error: 'z' : undeclared identifier\n");
  EXPECT_EQ(mapShaderLog("0:99(1): error: odd\nplain note\n", s), "<assembled line 99>: error: odd\nplain note\n");
  EXPECT_EQ(firstLogLocation("common/index.glsl:12: error: `x' undeclared\n"), "common/index.glsl:12");
}
