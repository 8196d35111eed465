// The work-efficient multi-level scan and the naive Hillis-Steele scan against the CPU reference,
// over the sizes where blocking goes wrong: 0, 1, 2, work-group and block edges, 2^k +- 1, random.
// The reduce-then-scan tests run twice: never fused (3 dispatches per level) and always fused
// where a level's block sums fit one block (scan_block sums its own offset, 2 dispatches).
#include <gtest/gtest.h>

#include <random>

#include "base/error.h"
#include "gl/buffer.h"
#include "gl/window.h"
#include "grid/grid_reference.h"
#include "grid/prefix_scan.h"
#include "support/gl_test.h"

using namespace tidepool;
using namespace tidepool::grid;

namespace {
class PrefixScanTest : public test::GlTest {};

enum class Offsets { Scanned, Fused };  // ScanConfig::fuseMaxBlocks = 0 or the largest that can fuse
class ScanPaths : public test::GlTest, public ::testing::WithParamInterface<Offsets> {
 protected:
  PrefixScan::Config withPath(PrefixScan::Config config) {
    config.fuseMaxBlocks = GetParam() == Offsets::Fused ? config.block() : 0;
    return config;
  }
};

// Runs of zeros, small counts and occasional large ones (the sum may wrap, like the CPU's).
std::vector<uint32_t> randomCounts(std::size_t n, uint32_t seed) {
  std::mt19937 rng(seed);
  std::vector<uint32_t> v(n);
  for (std::size_t i = 0; i < n;) {
    const uint32_t kind = rng() % 8;
    const std::size_t run = std::min<std::size_t>(n - i, 1 + rng() % 300);
    for (std::size_t k = 0; k < run; ++k, ++i) v[i] = kind < 3 ? 0u : kind < 7 ? rng() % 16 : rng() % (1u << 20);
  }
  return v;
}

// First mismatch as a readable message, or "" when equal.
std::string firstDifference(const std::vector<uint32_t>& got, const std::vector<uint32_t>& want) {
  if (got.size() != want.size()) return "size " + std::to_string(got.size()) + " != " + std::to_string(want.size());
  for (std::size_t i = 0; i < got.size(); ++i)
    if (got[i] != want[i])
      return "at " + std::to_string(i) + ": got " + std::to_string(got[i]) + ", want " + std::to_string(want[i]);
  return "";
}

// Scans n random values with `scan` into an output with a sentinel after the n + 1 entries.
template <class ScanT>
void expectScanMatches(ScanT& scan, std::size_t n, uint32_t seed) {
  const std::vector<uint32_t> in = randomCounts(n, seed);
  gl::Buffer inBuf(std::max<std::size_t>(n, 1) * 4), outBuf((n + 2) * 4);
  inBuf.upload(std::span<const uint32_t>(in));
  const uint32_t sentinel = 0xC0FFEEu;
  outBuf.upload(&sentinel, 4, (n + 1) * 4);
  scan.run(inBuf, outBuf, n);
  std::vector<uint32_t> got = outBuf.read<uint32_t>(n + 2);
  ASSERT_EQ(got[n + 1], sentinel) << "n = " << n << ": wrote past out[n]";
  got.pop_back();
  ASSERT_EQ(firstDifference(got, reference::exclusiveScan(in)), "") << "n = " << n;
  if (n) ASSERT_EQ(inBuf.read<uint32_t>(n), in) << "n = " << n << ": the input must be left as it was";
}

std::vector<std::size_t> edgeSizes(int maxLog2, PrefixScan::Config config = {}) {
  const std::size_t wg = config.groupSize, block = config.block();
  std::vector<std::size_t> sizes = {0, 1, 2, 3, 4, 5, wg - 1, wg, wg + 1, block - 1, block, block + 1};
  for (int k = 2; k <= maxLog2; ++k)
    for (std::size_t n : {(std::size_t(1) << k) - 1, std::size_t(1) << k, (std::size_t(1) << k) + 1})
      sizes.push_back(n);
  return sizes;
}
}  // namespace

TEST_F(PrefixScanTest, ExampleFromTheHeader) {
  PrefixScan scan(shaders());
  const std::vector<uint32_t> counts = {2, 0, 3, 1};
  gl::Buffer in{std::span<const uint32_t>(counts)}, out(5 * 4);
  scan.run(in, out, 4);
  EXPECT_EQ(out.readAll<uint32_t>(), (std::vector<uint32_t>{0, 2, 2, 5, 6}));
}

TEST_P(ScanPaths, MatchesCpuAtEdgeSizesUpTo2Pow22) {
  PrefixScan scan(shaders(), withPath({}));
  uint32_t seed = 1;
  for (std::size_t n : edgeSizes(22)) {
    expectScanMatches(scan, n, seed++);
    if (HasFatalFailure()) return;
  }
}

TEST_P(ScanPaths, MatchesCpuAtRandomSizes) {
  PrefixScan scan(shaders(), withPath({}));
  std::mt19937 rng(7);
  for (int i = 0; i < 24; ++i) {
    const std::size_t n = rng() % (1u << (4 + i % 17));
    expectScanMatches(scan, n, 100 + i);
    if (HasFatalFailure()) return;
  }
}

TEST_P(ScanPaths, ThreeLevelsBeyondBlockSquared) {
  PrefixScan scan(shaders(), withPath({}));
  const std::size_t block = scan.config().block();
  const std::size_t n = block * block + block + 3;  // 16M + 4099: reduce, reduce, top, scan, scan
  // Fused, level 1 (4098 sums in 2 blocks) sums its own offsets: reduce, reduce, scan, scan.
  EXPECT_EQ(scan.dispatchesFor(n), GetParam() == Offsets::Fused ? 4u : 5u);
  expectScanMatches(scan, n, 42);
}

TEST_P(ScanPaths, OtherWorkGroupShapes) {
  // Shapes smaller and larger than any subgroup: the scan must not depend on the warp size.
  for (PrefixScan::Config config : {PrefixScan::Config{32, 1}, PrefixScan::Config{64, 3}, PrefixScan::Config{512, 2},
                                    PrefixScan::Config{1024, 4}}) {
    PrefixScan scan(shaders(), withPath(config));
    uint32_t seed = 900;
    for (std::size_t n : edgeSizes(12, config)) {
      expectScanMatches(scan, n, seed++);
      if (HasFatalFailure()) return;
    }
    const std::size_t b = config.block();
    for (std::size_t n : {b * b - 1, b * b + 1, b * b + b + 7})  // two and three levels
      if (n < (std::size_t(1) << 22)) expectScanMatches(scan, n, seed++);
  }
  EXPECT_THROW(PrefixScan(shaders(), {100, 4}), Error);
  EXPECT_THROW(PrefixScan(shaders(), {256, 0}), Error);
  EXPECT_THROW(PrefixScan(shaders(), {1024, 16}), Error);  // 68 KiB of shared memory
}

TEST_P(ScanPaths, InPlaceAndZeroSize) {
  PrefixScan scan(shaders(), withPath({}));
  for (std::size_t n : {std::size_t(0), std::size_t(1), std::size_t(5000), std::size_t(70000)}) {
    const std::vector<uint32_t> in = randomCounts(n, uint32_t(n));
    gl::Buffer buf((n + 1) * 4);
    const uint32_t junk = 0xFFFFFFFFu;
    buf.upload(&junk, 4, n * 4);  // out[n] must be written even for n = 0
    buf.upload(std::span<const uint32_t>(in));
    scan.run(buf, buf, n);
    EXPECT_EQ(firstDifference(buf.readAll<uint32_t>(), reference::exclusiveScan(in)), "") << "n = " << n;
  }
}

TEST_P(ScanPaths, DeterministicAcrossRuns) {
  PrefixScan scan(shaders(), withPath({}));
  const std::size_t n = 300000;
  const std::vector<uint32_t> in = randomCounts(n, 9);
  gl::Buffer inBuf{std::span<const uint32_t>(in)}, outBuf((n + 1) * 4);
  scan.run(inBuf, outBuf, n);
  const std::vector<uint32_t> first = outBuf.readAll<uint32_t>();
  for (int r = 0; r < 3; ++r) {
    outBuf.fillZero();
    scan.run(inBuf, outBuf, n);
    EXPECT_EQ(outBuf.readAll<uint32_t>(), first);
  }
}

INSTANTIATE_TEST_SUITE_P(NeverAndAlwaysFused, ScanPaths, ::testing::Values(Offsets::Scanned, Offsets::Fused),
                         [](const auto& info) {
                           return std::string(info.param == Offsets::Fused ? "fused" : "scanned");
                         });

TEST_F(PrefixScanTest, DispatchesForEachPath) {
  const PrefixScan::Config defaults;
  const std::size_t block = defaults.block(), limit = defaults.fuseMaxBlocks;
  ASSERT_GT(limit, 1u);
  PrefixScan scan(shaders()), never(shaders(), {.fuseMaxBlocks = 0}), always(shaders(), {.fuseMaxBlocks = block});
  for (std::size_t n : {std::size_t(0), std::size_t(1), block})
    for (PrefixScan* s : {&scan, &never, &always}) EXPECT_EQ(s->dispatchesFor(n), 1u) << "n = " << n;
  for (std::size_t n : {block + 1, 2 * block, limit * block - 1, limit * block}) {  // (block, limit * block]
    EXPECT_EQ(scan.dispatchesFor(n), 2u) << "n = " << n;
    EXPECT_EQ(never.dispatchesFor(n), 3u) << "n = " << n;
  }
  EXPECT_EQ(scan.dispatchesFor(limit * block + 1), limit < block ? 3u : 4u);  // past it: unfused, or level 1 fuses
  EXPECT_EQ(always.dispatchesFor(block * block), 2u);
  EXPECT_EQ(always.dispatchesFor(block * block + 1), 4u);  // level 0 of 4097 blocks, level 1 of 2 fused
  EXPECT_EQ(never.dispatchesFor(block * block + 1), 5u);
}

// Fused offsets over every tail of the block sums (blocks % 4 words after the uvec4 loads) and
// over several uvec4 per invocation (up to 512 blocks / 4 / 32 invocations = 4).
TEST_F(PrefixScanTest, FusedOffsetsAtEveryTailOfTheBlockSums) {
  PrefixScan scan(shaders(), {.groupSize = 32, .vecsPerThread = 4, .fuseMaxBlocks = 512});  // blocks of 512
  ASSERT_EQ(scan.dispatchesFor(512 * 512), 2u);
  uint32_t seed = 300;
  for (std::size_t blocks : {2, 3, 4, 5, 6, 7, 8, 9, 129, 130, 131, 132, 510, 511, 512})
    for (std::size_t n : {512 * blocks - 1, 512 * blocks}) {
      expectScanMatches(scan, n, seed++);
      if (HasFatalFailure()) return;
    }
}

TEST_F(PrefixScanTest, NaiveScanMatchesCpu) {
  NaiveScan naive(shaders());
  EXPECT_EQ(NaiveScan::passesFor(0), 1u);
  EXPECT_EQ(NaiveScan::passesFor(4), 3u);  // 5 entries: strides 1, 2, 4
  uint32_t seed = 500;
  for (std::size_t n : edgeSizes(16)) {
    if (n > (std::size_t(1) << 16) + 1) continue;
    expectScanMatches(naive, n, seed++);
    if (HasFatalFailure()) return;
  }
  expectScanMatches(naive, (std::size_t(1) << 20) + 1, 3);
}

TEST_F(PrefixScanTest, BadSizesThrowOneLineErrors) {
  PrefixScan scan(shaders());
  NaiveScan naive(shaders());
  gl::Buffer small(16), out(64);
  EXPECT_THROW(scan.run(small, out, 5), Error);  // input holds 4
  EXPECT_THROW(scan.run(out, small, 4), Error);  // output needs 5
  EXPECT_THROW(naive.run(out, out, 4), Error);   // naive scan is not in place
  const std::size_t tooBig = gl::storageBlockBytes() / 4;
  try {
    scan.run(out, out, tooBig);
    ADD_FAILURE() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
  }
}
