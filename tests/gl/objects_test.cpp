// RAII GL objects release exactly once; a compute shader's SSBO writes read back exactly.
#include <gtest/gtest.h>

#include <numeric>

#include "gl/buffer.h"
#include "gl/framebuffer.h"
#include "gl/texture.h"
#include "selftest/bindings.glsl"
#include "support/gl_test.h"

using namespace tidepool;
using namespace tidepool::gl;

namespace {
class GlObjects : public test::GlTest {};
}  // namespace

TEST_F(GlObjects, MovesTransferOwnershipAndReleaseExactlyOnce) {
  const int before = liveCount(Kind::Buffer);
  GLuint name = 0;
  {
    Buffer a(64);
    name = a.id();
    EXPECT_TRUE(glIsBuffer(name));
    EXPECT_EQ(liveCount(Kind::Buffer), before + 1);
    Buffer b(std::move(a));
    EXPECT_EQ(a.id(), 0u);
    EXPECT_EQ(b.id(), name);
    Buffer c;
    c = std::move(b);
    EXPECT_EQ(c.id(), name);
    EXPECT_EQ(liveCount(Kind::Buffer), before + 1) << "moves must not create or release";
    c = Buffer(16);  // releases the old name
    EXPECT_FALSE(glIsBuffer(name));
    EXPECT_EQ(liveCount(Kind::Buffer), before + 1);
  }
  EXPECT_EQ(liveCount(Kind::Buffer), before);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(GlObjects, EveryKindIsReleased) {
  int before[int(Kind::Count)];
  for (int k = 0; k < int(Kind::Count); ++k) before[k] = liveCount(Kind(k));
  {
    Texture2D color(8, 8, GL_RGBA8), depth(8, 8, GL_DEPTH_COMPONENT32F);
    Framebuffer fbo({&color}, &depth);
    VertexArray vao = VertexArray::create();
    Query q = Query::create();
    Program p = shaders().build({"selftest/fill.comp"}, {});
    EXPECT_EQ(liveCount(Kind::Texture), before[int(Kind::Texture)] + 2);
    EXPECT_EQ(liveCount(Kind::Framebuffer), before[int(Kind::Framebuffer)] + 1);
    EXPECT_EQ(liveCount(Kind::Program), before[int(Kind::Program)] + 1);
    EXPECT_EQ(liveCount(Kind::Shader), before[int(Kind::Shader)]) << "shaders are freed once linked";
  }
  for (int k = 0; k < int(Kind::Count); ++k) EXPECT_EQ(liveCount(Kind(k)), before[k]) << "kind " << k;
}

TEST_F(GlObjects, ComputeShaderWritesSsboThatReadsBackExactly) {
  Program& fill = shaders().program({"selftest/fill.comp"});
  constexpr uint32_t kCount = 1000;  // not a multiple of the work-group size
  Buffer out(std::size_t(kCount + 1) * sizeof(uint32_t));
  const uint32_t sentinel = 0xDEADBEEFu;
  out.upload(&sentinel, sizeof sentinel, kCount * sizeof(uint32_t));
  out.bindBase(GL_SHADER_STORAGE_BUFFER, SELFTEST_OUT);
  fill.use();
  fill.set("uCount", kCount);
  fill.set("uMul", 3u);
  fill.dispatchThreads(kCount);
  std::vector<uint32_t> got = out.read<uint32_t>(kCount + 1);
  for (uint32_t i = 0; i < kCount; ++i) ASSERT_EQ(got[i], i * 3u + 1u) << "at " << i;
  EXPECT_EQ(got[kCount], sentinel) << "the bounds check must stop extra invocations";
}

TEST_F(GlObjects, DispatchBeyondTheGroupCountLimitSpillsIntoY) {
  Program& fill = shaders().program({"selftest/fill.comp"});
  GLint maxX = 0;
  glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, 0, &maxX);
  const std::size_t local = fill.localSize().x;
  const std::size_t count = std::size_t(maxX) * local + 3 * local + 5;  // needs a second row of groups
  if (count * 4 > 256u << 20) GTEST_SKIP() << "group-count limit too large to test cheaply here";
  Buffer out(count * sizeof(uint32_t));
  out.bindBase(GL_SHADER_STORAGE_BUFFER, SELFTEST_OUT);
  fill.use();
  fill.set("uCount", uint32_t(count));
  fill.set("uMul", 1u);
  fill.dispatchThreads(count);
  std::vector<uint32_t> got = out.readAll<uint32_t>();
  std::size_t wrong = 0;
  for (std::size_t i = 0; i < count; ++i) wrong += got[i] != uint32_t(i + 1);
  EXPECT_EQ(wrong, 0u);
}

TEST_F(GlObjects, BufferCopyZeroAndRangeChecks) {
  std::vector<uint32_t> data(100);
  std::iota(data.begin(), data.end(), 1u);
  Buffer a{std::span<const uint32_t>(data)}, b(data.size() * 4);
  a.copyTo(b, 40 * 4, 10 * 4, 0);
  EXPECT_EQ(b.read<uint32_t>(3), (std::vector<uint32_t>{11, 12, 13}));
  b.fillZero();
  EXPECT_EQ(b.read<uint32_t>(2, 50), (std::vector<uint32_t>{0, 0}));
  EXPECT_THROW(a.upload(data.data(), 4, 400), GlError);
  EXPECT_THROW(a.copyTo(b, 8, 396, 0), GlError);
}

TEST_F(GlObjects, TextureRoundTripAndBadSizes) {
  Texture2D t(3, 2, GL_RGBA8);
  std::vector<uint8_t> px(3 * 2 * 4);
  for (std::size_t i = 0; i < px.size(); ++i) px[i] = uint8_t(i * 7);
  t.upload(GL_RGBA, GL_UNSIGNED_BYTE, px.data());
  std::vector<uint8_t> back = t.readRgba8();  // top row first: rows swapped
  for (int x = 0; x < 12; ++x) {
    EXPECT_EQ(back[x], px[12 + x]);
    EXPECT_EQ(back[12 + x], px[x]);
  }
  EXPECT_THROW(Texture2D(0, 4, GL_RGBA8), GlError);
  EXPECT_THROW(Texture2D(1 << 20, 4, GL_RGBA8), GlError);
}
