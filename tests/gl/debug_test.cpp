// KHR_debug: driver messages reach the log (the test context is created with debug output on).
#include <gtest/gtest.h>

#include <mutex>
#include <vector>

#include "base/log.h"
#include "support/gl_test.h"

using namespace tidepool;

namespace {
class DebugOutput : public test::GlTest {};
}  // namespace

TEST_F(DebugOutput, GlErrorsAreLoggedAsErrors) {
  std::vector<std::string> errors;
  log::setSink([&](log::Level level, const std::string& message) {
    if (level == log::Level::Error) errors.push_back(message);
  });
  glBindBuffer(GL_TEXTURE_2D, 0);  // not a buffer target: GL_INVALID_ENUM
  log::setSink(nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  ASSERT_FALSE(errors.empty()) << "the debug callback should have reported the invalid enum";
  EXPECT_EQ(errors[0].rfind("GL [", 0), 0u) << errors[0];
}
