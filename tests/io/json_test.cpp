// Malformed JSON is reported with file, line and column.
#include <gtest/gtest.h>

#include "io/json.h"
#include "support/gl_test.h"

using namespace tidepool;

TEST(Json, MalformedInputNamesLineAndColumn) {
  try {
    io::parseJson("{\n  \"a\": 1,\n  \"b\": ]\n}\n", "scene.json");
    FAIL();
  } catch (const Error& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind("scene.json:3:8: malformed JSON:", 0), 0u) << m;
  }
  try {
    io::parseJson("{\"a\": 1", "t.json");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("t.json:1:", 0), 0u) << e.what();
  }
}

TEST(Json, MissingAndDirectoryPathsAreClear) {
  try {
    io::readJsonFile("/nonexistent/scene.json");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "file not found: '/nonexistent/scene.json'");
  }
  EXPECT_THROW(io::readJsonFile("/tmp"), Error);
}
