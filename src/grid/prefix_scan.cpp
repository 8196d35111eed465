#include "grid/prefix_scan.h"

#include <string>

#include "base/error.h"
#include "gl/window.h"
#include "grid/bindings.glsl"

namespace tidepool::grid {
namespace {
constexpr std::size_t kWord = sizeof(uint32_t);

// Every binding of scan_io.glsl and scan_block.comp.
constexpr std::initializer_list<GLuint> kScanBindings = {SCAN_IN_VEC,   SCAN_IN_WORD,    SCAN_OUT_VEC,
                                                         SCAN_OUT_WORD, SCAN_BLOCK_SUMS, SCAN_BLOCK_SUMS_VEC};

std::vector<gl::ShaderDefine> scanDefines(const PrefixScan::Config& c) {
  const std::size_t g = c.groupSize, v = c.vecsPerThread;
  if (g < 32 || g > 1024 || (g & (g - 1)) || v < 1 || v > 16)
    throw Error("prefix scan: work group " + std::to_string(g) + " x " + std::to_string(v) +
                " uvec4 is not supported (group size a power of two in 32..1024, 1..16 uvec4 per invocation)");
  // Shared memory of scan_block.comp: chunk sums and the tree, padded one word per 32.
  auto padded = [](std::size_t words) { return words + words / 32; };
  const std::size_t shared = 4 * (padded(g * v) + padded(g));
  GLint maxShared = 0;
  glGetIntegerv(GL_MAX_COMPUTE_SHARED_MEMORY_SIZE, &maxShared);
  if (shared > std::size_t(maxShared))
    throw Error("prefix scan: work group " + std::to_string(g) + " x " + std::to_string(v) + " uvec4 needs " +
                std::to_string(shared) + " bytes of shared memory, this driver offers " + std::to_string(maxShared));
  return {{"WG", std::to_string(g)}, {"VECS", std::to_string(v)}};
}

void checkSizes(const char* what, const gl::Buffer& in, const gl::Buffer& out, std::size_t n, std::size_t limit) {
  if (n > PrefixScan::kMaxCount)
    throw Error(std::string(what) + " of " + std::to_string(n) + " elements: at most 2^31 are supported");
  if (in.size() < n * kWord)
    throw Error(std::string(what) + " of " + std::to_string(n) + " elements: the input buffer holds only " +
                std::to_string(in.size() / kWord));
  if (out.size() < (n + 1) * kWord)
    throw Error(std::string(what) + " of " + std::to_string(n) + " elements: the output buffer needs n + 1 = " +
                std::to_string(n + 1) + " uints, it holds " + std::to_string(out.size() / kWord));
  if ((n + 1) * kWord > limit)
    throw Error(std::string(what) + " of " + std::to_string(n) + " elements needs " + gl::sizeText((n + 1) * kWord) +
                " arrays, over this driver's SSBO limit of " + gl::sizeText(limit));
}
}  // namespace

PrefixScan::PrefixScan(gl::ShaderLibrary& shaders, Config config)
    : m_config(config),
      m_maxBlockBytes(gl::storageBlockBytes()),
      m_reduce(shaders, "grid/scan_reduce.comp", kScanBindings, scanDefines(config)),
      m_block(shaders, "grid/scan_block.comp", kScanBindings, scanDefines(config)) {}

std::size_t PrefixScan::blocksOf(std::size_t n) const {
  return std::max<std::size_t>(1, (n + m_config.block() - 1) / m_config.block());
}

void PrefixScan::reserve(std::size_t n) {
  for (std::size_t level = 0; n > m_config.block(); ++level) {
    n = blocksOf(n);
    if (m_sums.size() <= level) m_sums.emplace_back();
    if (m_sums[level].size() < (n + 1) * kWord) m_sums[level] = gl::Buffer((n + 1) * kWord);
  }
}

std::size_t PrefixScan::memoryBytes() const {
  std::size_t bytes = 0;
  for (const gl::Buffer& b : m_sums) bytes += b.size();
  return bytes;
}

std::size_t PrefixScan::dispatchesFor(std::size_t n) const {
  std::size_t dispatches = 0;
  for (; n > m_config.block(); n = blocksOf(n)) {
    dispatches += 2;  // scan_reduce + scan_block
    if (m_config.fuses(blocksOf(n))) return dispatches;
  }
  return dispatches + 1;  // the top: one work group
}

void PrefixScan::run(const gl::Buffer& in, gl::Buffer& out, std::size_t n) {
  checkSizes("prefix scan", in, out, n, m_maxBlockBytes);
  reserve(n);
  scanLevel(in, out, n, 0);
}

void PrefixScan::scanLevel(const gl::Buffer& in, gl::Buffer& out, std::size_t n, std::size_t level) {
  const std::size_t blocks = blocksOf(n);
  gl::Buffer* sums = blocks > 1 ? &m_sums[level] : nullptr;
  const bool fused = m_config.fuses(blocks);  // scan_block sums blockSums[0..b) itself: no level above
  auto bind = [&](const gl::Buffer& src, const gl::Buffer& dst) {
    src.bindBase(GL_SHADER_STORAGE_BUFFER, SCAN_IN_VEC);
    src.bindBase(GL_SHADER_STORAGE_BUFFER, SCAN_IN_WORD);
    dst.bindBase(GL_SHADER_STORAGE_BUFFER, SCAN_OUT_VEC);
    dst.bindBase(GL_SHADER_STORAGE_BUFFER, SCAN_OUT_WORD);
    (sums ? *sums : dst).bindBase(GL_SHADER_STORAGE_BUFFER, SCAN_BLOCK_SUMS);  // unused at the top
    (sums ? *sums : dst).bindBase(GL_SHADER_STORAGE_BUFFER, SCAN_BLOCK_SUMS_VEC);
  };
  const std::size_t threads = blocks * m_config.groupSize;
  if (sums) {
    bind(in, out);
    m_reduce.dispatchThreads(threads, {GLuint(n)});
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    if (!fused) scanLevel(*sums, *sums, blocks, level + 1);  // block sums -> block offsets, in place
  }
  bind(in, out);  // again: the recursion rebinds the same points
  m_block.dispatchThreads(threads, {GLuint(n), fused ? 2u : sums ? 1u : 0u});
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

NaiveScan::NaiveScan(gl::ShaderLibrary& shaders)
    : m_maxBlockBytes(gl::storageBlockBytes()),
      m_pass(shaders, "grid/scan_naive.comp", {SCAN_NAIVE_IN, SCAN_NAIVE_OUT}) {}

std::size_t NaiveScan::passesFor(std::size_t n) {
  std::size_t passes = 0;
  while ((std::size_t(1) << passes) < n + 1) ++passes;
  return std::max<std::size_t>(passes, 1);
}

void NaiveScan::reserve(std::size_t n) {
  if (m_temp.size() < (n + 1) * kWord) m_temp = gl::Buffer((n + 1) * kWord);
}

void NaiveScan::run(const gl::Buffer& in, gl::Buffer& out, std::size_t n) {
  checkSizes("naive scan", in, out, n, m_maxBlockBytes);
  if (in.id() == out.id()) throw Error("naive scan: input and output must be different buffers");
  reserve(n);
  const std::size_t passes = passesFor(n);
  const gl::Buffer* src = &in;
  for (std::size_t p = 0; p < passes; ++p) {
    // Ping-pong so that the last pass lands in `out`.
    const gl::Buffer* dst = (passes - 1 - p) % 2 == 0 ? &out : &m_temp;
    src->bindBase(GL_SHADER_STORAGE_BUFFER, SCAN_NAIVE_IN);
    dst->bindBase(GL_SHADER_STORAGE_BUFFER, SCAN_NAIVE_OUT);
    m_pass.dispatchThreads(n + 1, {GLuint(n), GLuint(1) << p, p == 0 ? 1u : 0u});
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    src = dst;
  }
}

}  // namespace tidepool::grid
