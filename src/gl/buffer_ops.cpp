#include "gl/buffer_ops.h"

#include <algorithm>
#include <string>

#include "common/words_bindings.glsl"

namespace tidepool::gl {
namespace {
void checkWords(std::size_t bytes, std::size_t size, const char* what) {
  if (bytes % 4)
    throw GlError(std::string("buffer ") + what + " of " + std::to_string(bytes) + " bytes is not whole 32-bit words");
  if (bytes > size)
    throw GlError(std::string("buffer ") + what + " of " + std::to_string(bytes) + " bytes overruns a buffer of " +
                  std::to_string(size) + " bytes");
}
}  // namespace

BufferOps::BufferOps(ShaderLibrary& shaders)
    : m_fill(shaders, "common/words_fill.comp", {WORDS_FILL_TARGET}),
      m_copy(shaders, "common/words_copy.comp", {WORDS_COPY_SRC, WORDS_COPY_DST}) {
  GLint64 maxBlock = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlock);
  // Chunk offsets stay multiples of 64 KiB, far above any SSBO offset alignment.
  m_chunk = std::max<std::size_t>(
      std::min<std::size_t>(std::size_t(maxBlock), std::size_t(1) << 30) & ~std::size_t(0xffff), std::size_t(1) << 16);
}

void BufferOps::fill(Buffer& buffer, uint32_t value, std::size_t bytes) const {
  if (bytes == SIZE_MAX) bytes = buffer.size() & ~std::size_t(3);
  checkWords(bytes, buffer.size(), "fill");
  if (!bytes) return;
  for (std::size_t offset = 0; offset < bytes; offset += m_chunk) {
    const std::size_t n = std::min(m_chunk, bytes - offset);
    buffer.bindRange(GL_SHADER_STORAGE_BUFFER, WORDS_FILL_TARGET, offset, n);
    m_fill.dispatchThreads((n / 4 + 3) / 4, {.words = unsigned(n / 4), .value = value});
  }
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  buffer.markWritten();
}

void BufferOps::copy(const Buffer& src, Buffer& dst, std::size_t bytes) const {
  checkWords(bytes, src.size(), "copy source");
  checkWords(bytes, dst.size(), "copy destination");
  if (!bytes) return;
  if (src.id() == dst.id()) throw GlError("buffer copy onto itself");
  for (std::size_t offset = 0; offset < bytes; offset += m_chunk) {
    const std::size_t n = std::min(m_chunk, bytes - offset);
    src.bindRange(GL_SHADER_STORAGE_BUFFER, WORDS_COPY_SRC, offset, n);
    dst.bindRange(GL_SHADER_STORAGE_BUFFER, WORDS_COPY_DST, offset, n);
    m_copy.dispatchThreads((n / 4 + 3) / 4, {.words = unsigned(n / 4)});
  }
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  dst.markWritten();
}

}  // namespace tidepool::gl
