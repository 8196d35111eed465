// PNG output has the right size and content, from the CPU and from a GL render target.
#include <gtest/gtest.h>

#include "io/png.h"
#include "render/target.h"
#include "support/gl_test.h"

using namespace tidepool;

namespace {
class PngFromGl : public test::GlTest {};
}  // namespace

TEST(Png, WriteReadRoundTrip) {
  test::TempDir dir;
  io::Image img{5, 3, std::vector<uint8_t>(5 * 3 * 4)};
  for (std::size_t i = 0; i < img.rgba.size(); ++i) img.rgba[i] = uint8_t(i * 13 + 1);
  io::writePng(dir / "a.png", img);
  io::Image back = io::readPng(dir / "a.png");
  EXPECT_EQ(back.width, 5);
  EXPECT_EQ(back.height, 3);
  EXPECT_EQ(back.rgba, img.rgba);
}

TEST(Png, ErrorsNameThePath) {
  io::Image img{2, 2, std::vector<uint8_t>(16)};
  try {
    io::writePng("/nonexistent-dir/x.png", img);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-dir/x.png"), std::string::npos);
  }
  EXPECT_THROW(io::writePng("/tmp/y.png", io::Image{2, 2, std::vector<uint8_t>(3)}), Error);
  EXPECT_THROW(io::readPng("/nonexistent.png"), Error);
}

TEST_F(PngFromGl, RenderTargetPixelsLandInThePngTopRowFirst) {
  RenderTarget target(40, 20);
  target.bind();
  glClearColor(0.0f, 0.0f, 1.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  // Paint the bottom 5 rows red: in the PNG (top row first) they are the last rows.
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, 40, 5);
  glClearColor(1.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  test::TempDir dir;
  io::writePng(dir / "t.png", io::Image{40, 20, target.readRgba8()});
  io::Image png = io::readPng(dir / "t.png");
  ASSERT_EQ(png.width, 40);
  ASSERT_EQ(png.height, 20);
  auto at = [&](int x, int y) { return &png.rgba[(std::size_t(y) * 40 + x) * 4]; };
  EXPECT_EQ(at(0, 0)[2], 255);
  EXPECT_EQ(at(0, 0)[0], 0);
  EXPECT_EQ(at(39, 19)[0], 255);
  EXPECT_EQ(at(39, 19)[2], 0);
  EXPECT_EQ(at(10, 14)[2], 255);
  EXPECT_EQ(at(10, 15)[0], 255);
}
