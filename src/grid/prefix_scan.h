// Exclusive prefix sum of uint32 on the GPU, any size from 0 to 2^31 elements, no host round
// trip: out[i] = in[0] + ... + in[i - 1] for i <= n, so out[n] holds the total.
//
//   in  = {2, 0, 3, 1}          (n = 4 uints)
//   out = {0, 2, 2, 5, 6}       (n + 1 uints)
//
// PrefixScan works on blocks of 4096 elements, one work group each, in the reduce-then-scan order
// (Merrill & Grimshaw 2009), level L of n_L elements in B_L blocks:
//     scan_reduce   blockSums[b] = sum of block b                         reads n_L
//     (scan blockSums in place: level L + 1, recursively)
//     scan_block    scan each block in shared memory, + blockSums[b]     reads n_L, writes n_L
//   fused reduce-then-scan, the same when B_L <= ScanConfig::fuseMaxBlocks and B_L <= one block:
//     scan_reduce   blockSums[b] = sum of block b                         reads n_L
//     scan_block    offset = blockSums[0] + ... + blockSums[b - 1], summed by the work group itself
//                   (no dispatch scans the sums), + scan each block      reads n_L + B_L^2 / 2, writes n_L
//   A level of at most one block is a single work group with no offsets: the top.
// Reduce-then-scan moves 3 N words at level 0 against the textbook scan-then-propagate's 4 N (docs/
// ARCHITECTURE.md, "Rejected designs"), which is what lets the scan approach copy bandwidth; its
// uniform add is fused into scan_block's store. Unfused, 16M elements take
// three dispatches: reduce (4096 groups), one group over the 4096 sums, scan (4096 groups). Fused
// (the default fuseMaxBlocks of 4096 fuses every level up to 16M), 1M elements (256 blocks) take
// two: reduce, then scan, each of the 256 groups summing the block sums before its own (at most
// 255 words, from L2). A dispatch costs microseconds of launch and drain, the middle one more than
// its tiny work; the fused sums grow as B^2 / 2 words, 32 MB of L2 reads at 4096 blocks, hence the
// threshold. Measured on the H100 (docs/ARCHITECTURE.md, "Rejected designs"), fusing wins at
// every size up to 16M: 1M 0.024 -> 0.018 ms, 16M 53.5% -> 57.1% of a copy. Any level may fuse:
// past 16M, level 1 (the sums, in a few blocks) does, so 16M + 1 elements take four dispatches,
// not five.
// Inside a block (default shape): 16 elements per invocation as 4 coalesced uvec4 loads, a scan
// of the 1024 chunk sums, and a Blelloch up-sweep/down-sweep of the 256 invocation totals in
// padded shared memory (shaders/grid/scan_group.glsl). No warp or subgroup size is assumed.
//
// NaiveScan is the log2(N)-pass Hillis-Steele scan (as in the particle-life article), kept as
// the reference for tests and the benchmark.
//
// Both end every pass with glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT), so the next shader
// may read `out`; Buffer::download adds the read-back barrier itself. Results are exact and
// deterministic (integer adds); the sum wraps modulo 2^32 like the CPU reference.
#pragma once

#include <cstddef>
#include <vector>

#include "gl/buffer.h"
#include "gl/kernel.h"

namespace tidepool::grid {

// Work-group shape of PrefixScan (compile-time defines of its kernels) and when a level sums its
// own offsets. The program uses the defaults; the tests take small blocks to reach the deeper
// levels of the recursion with few elements.
struct ScanConfig {
  std::size_t groupSize = 256;       // invocations per work group: a power of two, 32..1024
  std::size_t vecsPerThread = 4;     // uvec4 loads per invocation: 1..16
  std::size_t fuseMaxBlocks = 4096;  // levels of 2..min(this, block()) blocks: 2 dispatches, not 3 (0: never)
  std::size_t block() const { return groupSize * vecsPerThread * 4; }  // elements per work group
  bool fuses(std::size_t blocks) const {  // does a level of `blocks` blocks sum its own offsets?
    return blocks > 1 && blocks <= fuseMaxBlocks && blocks <= block();
  }
};

class PrefixScan {
 public:
  using Config = ScanConfig;
  static constexpr std::size_t kMaxCount = std::size_t(1) << 31;  // uint indices in the kernels

  explicit PrefixScan(gl::ShaderLibrary& shaders, Config config = {});  // throws Error for a bad shape

  // out[0..n] = exclusive scan of in[0..n). `in` holds >= n uints, `out` >= n + 1; they may be
  // the same buffer (in place). n = 0 writes out[0] = 0. Throws Error for bad sizes.
  void run(const gl::Buffer& in, gl::Buffer& out, std::size_t n);
  void reserve(std::size_t n);                     // allocates the block sums for n up front
  std::size_t memoryBytes() const;                 // block-sum buffers (bytes)
  std::size_t dispatchesFor(std::size_t n) const;  // compute dispatches one run(n) issues
  const Config& config() const { return m_config; }

 private:
  std::size_t blocksOf(std::size_t n) const;
  void scanLevel(const gl::Buffer& in, gl::Buffer& out, std::size_t n, std::size_t level);

  Config m_config;
  std::size_t m_maxBlockBytes;  // queried once: glGet may sync a threaded driver
  struct ReduceUniforms {
    GLuint count = 0;  // elements at this level
    static constexpr auto fields() { return std::tuple{gl::field("uCount", &ReduceUniforms::count)}; }
  };
  struct BlockUniforms {
    GLuint count = 0;    // elements at this level
    GLuint offsets = 0;  // 0: none, 1: the scanned block sums, 2: sums of the block sums (fused)
    static constexpr auto fields() {
      return std::tuple{gl::field("uCount", &BlockUniforms::count), gl::field("uOffsets", &BlockUniforms::offsets)};
    }
  };
  gl::Kernel<ReduceUniforms> m_reduce;
  gl::Kernel<BlockUniforms> m_block;
  std::vector<gl::Buffer> m_sums;  // m_sums[L]: block sums of level L (+1 entry for their total)
};

class NaiveScan {
 public:
  explicit NaiveScan(gl::ShaderLibrary& shaders);

  // Same contract as PrefixScan::run, but `in` and `out` must be different buffers.
  void run(const gl::Buffer& in, gl::Buffer& out, std::size_t n);
  void reserve(std::size_t n);                               // allocates the ping-pong buffer for n up front
  std::size_t memoryBytes() const { return m_temp.size(); }  // ping-pong buffer (bytes)
  static std::size_t passesFor(std::size_t n);               // ceil(log2(n + 1)), at least 1

 private:
  std::size_t m_maxBlockBytes;
  struct PassUniforms {
    GLuint count = 0;   // elements of the input
    GLuint stride = 0;  // 2^pass
    GLuint shift = 0;   // 1 on the first pass
    static constexpr auto fields() {
      return std::tuple{gl::field("uCount", &PassUniforms::count), gl::field("uStride", &PassUniforms::stride),
                        gl::field("uShift", &PassUniforms::shift)};
    }
  };
  gl::Kernel<PassUniforms> m_pass;
  gl::Buffer m_temp;
};

}  // namespace tidepool::grid
