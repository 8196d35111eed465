// GL 4.3 guarantees 8 storage blocks per compute shader. Each kernel's text, with its #includes
// pasted in and every #if branch counted, declares at most 8, so no variant can need more and a
// reader sees the bound at a glance (read-only arrays beyond them come through buffer textures:
// shaders/common/obstacle_grid.glsl). CPU only: the shader library's own assembly, no GL context.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "gl/shader_source.h"

using namespace tidepool;

namespace {

std::filesystem::path shaderRoot() {
  if (const char* dir = std::getenv("TIDEPOOL_SHADER_DIR")) return dir;
  return std::filesystem::path(TIDEPOOL_SOURCE_DIR) / "shaders";
}

// Storage-block declarations ("buffer Name {") outside comments.
int storageBlocks(std::string text) {
  text = std::regex_replace(text, std::regex(R"(/\*[\s\S]*?\*/)"), " ");
  text = std::regex_replace(text, std::regex(R"(//[^\n]*)"), "");
  const std::regex block(R"(\bbuffer\s+\w+\s*\{)");
  return int(std::distance(std::sregex_iterator(text.begin(), text.end(), block), std::sregex_iterator()));
}

}  // namespace

TEST(ShaderLimits, EveryComputeShaderDeclaresAtMostEightStorageBlocks) {
  const std::filesystem::path root = shaderRoot();
  const gl::ShaderFileReader read = [&](const std::string& path) -> std::optional<std::string> {
    std::ifstream in(root / path);
    if (!in) return std::nullopt;
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  };
  int kernels = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
    if (entry.path().extension() != ".comp") continue;
    const std::string path = std::filesystem::relative(entry.path(), root).generic_string();
    const gl::AssembledShader shader = gl::assembleShader(path, read);
    EXPECT_LE(storageBlocks(shader.text), 8) << path << ": GL 4.3 guarantees 8 storage blocks per compute shader";
    ++kernels;
  }
  EXPECT_GT(kernels, 20) << "no compute shaders found under " << root;
  EXPECT_EQ(storageBlocks("layout(std430) buffer A { uint a[]; };\n// buffer B { }\n/* buffer C {\n} */"), 1);
}
