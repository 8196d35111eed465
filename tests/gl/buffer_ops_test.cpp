// gl::BufferOps: the compute-shader fill and copy write exactly the words asked for (whole
// uvec4s, the 0..3 trailing words, chunks past the SSBO size limit) and refuse bad sizes.
#include <gtest/gtest.h>

#include <glm/glm.hpp>
#include <numeric>

#include "base/error.h"
#include "gl/buffer.h"
#include "gl/buffer_ops.h"
#include "support/gl_test.h"

using namespace tidepool;
using namespace tidepool::gl;

namespace {
class BufferOpsTest : public test::GlTest {};

std::vector<uint32_t> sequence(std::size_t n, uint32_t first) {
  std::vector<uint32_t> v(n);
  std::iota(v.begin(), v.end(), first);
  return v;
}
}  // namespace

TEST_F(BufferOpsTest, FillWritesExactlyTheWordsAskedFor) {
  const BufferOps ops(shaders());
  for (std::size_t words : {1u, 3u, 4u, 5u, 37u, 1024u, 4099u}) {
    const std::vector<uint32_t> before = sequence(words + 9, 100);
    Buffer b{std::span<const uint32_t>(before)};
    ops.fill(b, 0xdeadbeefu, words * 4);
    const std::vector<uint32_t> got = b.read<uint32_t>(words + 9);
    for (std::size_t i = 0; i < got.size(); ++i)
      ASSERT_EQ(got[i], i < words ? 0xdeadbeefu : before[i]) << "word " << i << " of a " << words << "-word fill";
  }
  Buffer whole(40);
  ops.fill(whole, 7);
  EXPECT_EQ(whole.read<uint32_t>(10), std::vector<uint32_t>(10, 7u));
}

TEST_F(BufferOpsTest, CopyMovesExactlyTheWordsAskedFor) {
  const BufferOps ops(shaders());
  for (std::size_t words : {1u, 2u, 4u, 7u, 1001u, 65539u}) {
    const std::vector<uint32_t> src = sequence(words, 1), dst0(words + 5, 0u);
    Buffer a{std::span<const uint32_t>(src)}, b{std::span<const uint32_t>(dst0)};
    ops.copy(a, b, words * 4);
    const std::vector<uint32_t> got = b.read<uint32_t>(words + 5);
    for (std::size_t i = 0; i < got.size(); ++i)
      ASSERT_EQ(got[i], i < words ? src[i] : 0u) << "word " << i << " of a " << words << "-word copy";
  }
}

TEST_F(BufferOpsTest, ReadBackReturnsTheElementsAskedForAndLeavesTheBufferAlone) {
  const BufferOps ops(shaders());
  const std::vector<uint32_t> words = sequence(1001, 7);
  Buffer b{std::span<const uint32_t>(words)};
  EXPECT_EQ(ops.readBack<uint32_t>(b, 1001), words);
  EXPECT_EQ(ops.readBack<uint32_t>(b, 1, 1000), std::vector<uint32_t>{1007u});
  const std::vector<glm::uvec4> quads = ops.readBack<glm::uvec4>(b, 2, 3);  // words 12..19
  EXPECT_EQ(quads[0], glm::uvec4(19, 20, 21, 22));
  EXPECT_EQ(quads[1], glm::uvec4(23, 24, 25, 26));
  EXPECT_EQ(b.read<uint32_t>(1001), words);
  EXPECT_THROW(ops.readBack<uint32_t>(b, 2, 1000), Error);  // past the end
}

TEST_F(BufferOpsTest, BuffersBeyondTheStorageBlockLimitAreDoneInChunks) {
  GLint64 maxBlock = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlock);
  if (maxBlock > (std::int64_t(256) << 20))
    GTEST_SKIP() << "SSBO limit " << maxBlock << " bytes: too big to exceed here";
  const std::size_t bytes = std::size_t(maxBlock) + (std::size_t(1) << 20) + 12;  // past the limit, odd tail
  const BufferOps ops(shaders());
  Buffer a(bytes), b(bytes);
  ops.fill(a, 5);
  ops.copy(a, b, bytes);
  const std::size_t words = bytes / 4;
  for (std::size_t at : {std::size_t(0), std::size_t(maxBlock) / 4 - 1, std::size_t(maxBlock) / 4, words - 1})
    EXPECT_EQ(b.read<uint32_t>(1, at)[0], 5u) << "word " << at << " of " << words;
}

TEST_F(BufferOpsTest, RefusesPartialWordsOverrunsAndSelfCopies) {
  const BufferOps ops(shaders());
  Buffer a(64), b(32);
  EXPECT_THROW(ops.fill(a, 0, 6), GlError);
  EXPECT_THROW(ops.fill(a, 0, 68), GlError);
  EXPECT_THROW(ops.copy(a, b, 64), GlError);
  EXPECT_THROW(ops.copy(a, a, 16), GlError);
  EXPECT_NO_THROW(ops.copy(a, b, 32));
}
