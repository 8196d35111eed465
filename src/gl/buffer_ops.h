// Buffer fill and copy run as compute shaders (shaders/common/words_*.comp) instead of
// glClearBufferData / glCopyBufferSubData: on the NVIDIA H100 driver those two run at about
// 25 GB/s and 170 GB/s, the shader cores at over 2 TB/s (`tidepool bench memory` shows both).
// Both end with GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT, so later kernels
// and read-backs see the result; the caller makes earlier shader writes to the source visible.
//
//   gl::BufferOps ops(shaders);
//   ops.fill(cellCount, 0);            // every word of the buffer
//   ops.copy(state, backup, bytes);    // bytes: a multiple of 4
#pragma once

#include <cstdint>

#include "gl/buffer.h"
#include "gl/shader_library.h"

namespace tidepool::gl {

class BufferOps {
 public:
  explicit BufferOps(ShaderLibrary& shaders);

  // Sets the first `bytes` bytes (a multiple of 4; all of the buffer when omitted) to `value`
  // in every 32-bit word. Throws GlError on overrun or a size that is not whole words.
  void fill(Buffer& buffer, uint32_t value = 0, std::size_t bytes = SIZE_MAX) const;
  // The first `bytes` bytes (a multiple of 4) of src into dst. Throws GlError on overrun.
  void copy(const Buffer& src, Buffer& dst, std::size_t bytes) const;

 private:
  Program* m_fill;
  Program* m_copy;
  std::size_t m_chunk;  // bytes bound per dispatch: under GL_MAX_SHADER_STORAGE_BLOCK_SIZE
};

}  // namespace tidepool::gl
