#include "support/gl_test.h"

#include <cstdlib>
#include <fstream>
#include <memory>
#include <random>

namespace tidepool::test {
namespace {
std::unique_ptr<gl::Context> g_context;
std::unique_ptr<gl::ShaderLibrary> g_shaders;
}  // namespace

void GlTest::SetUpTestSuite() {
  if (g_context) return;
  // EGL is what CI and the GPU machine use; KHR_debug messages go to the log.
  g_context = gl::createHeadlessContext({gl::Backend::Egl, true});
  g_shaders = std::make_unique<gl::ShaderLibrary>(shaderDir());
}

std::filesystem::path GlTest::shaderDir() {
  // The program's own rule for the variable (an unreadable folder is an error, not a fallback),
  // so that a mutated copy of the tree runs through the suite without a rebuild.
  if (std::getenv("TIDEPOOL_SHADER_DIR")) return gl::ShaderLibrary::findRoot();
  return std::filesystem::path(TIDEPOOL_SOURCE_DIR) / "shaders";
}

gl::ShaderLibrary& GlTest::shaders() { return *g_shaders; }

TempDir::TempDir() {
  std::random_device rd;
  m_path = std::filesystem::temp_directory_path() / ("tidepool-test-" + std::to_string(rd()));
  std::filesystem::create_directories(m_path);
}

TempDir::~TempDir() {
  std::error_code ec;
  std::filesystem::permissions(m_path, std::filesystem::perms::owner_all, std::filesystem::perm_options::add, ec);
  std::filesystem::remove_all(m_path, ec);
}

void TempDir::write(const std::string& relative, const std::string& text) const {
  const std::filesystem::path p = m_path / relative;
  std::filesystem::create_directories(p.parent_path());
  std::ofstream(p) << text;
}

}  // namespace tidepool::test
