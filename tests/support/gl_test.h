// Shared fixtures for GPU tests: one headless context per test process (EGL, Mesa llvmpipe in CI)
// and a shader library rooted at $TIDEPOOL_SHADER_DIR when it is set, else the source tree's
// shaders/ (the tidepool executable the CLI tests start reads the same variable).
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "gl/context.h"
#include "gl/shader_library.h"

namespace tidepool::test {

class GlTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite();
  static gl::ShaderLibrary& shaders();       // rooted at shaderDir()
  static std::filesystem::path shaderDir();  // $TIDEPOOL_SHADER_DIR, else the source tree's shaders/
};

// A fresh temporary folder removed at the end of the test.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  const std::filesystem::path& path() const { return m_path; }
  std::filesystem::path operator/(const std::string& name) const { return m_path / name; }
  void write(const std::string& relative, const std::string& text) const;  // creates folders

 private:
  std::filesystem::path m_path;
};

}  // namespace tidepool::test
