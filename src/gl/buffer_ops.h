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
#include <vector>

#include "gl/buffer.h"
#include "gl/kernel.h"

namespace tidepool::gl {

class BufferOps {
 public:
  explicit BufferOps(ShaderLibrary& shaders);

  // Sets the first `bytes` bytes (a multiple of 4; all of the buffer when omitted) to `value`
  // in every 32-bit word. Throws GlError on overrun or a size that is not whole words.
  void fill(Buffer& buffer, uint32_t value = 0, std::size_t bytes = SIZE_MAX) const;
  // The first `bytes` bytes (a multiple of 4) of src into dst. Throws GlError on overrun.
  void copy(const Buffer& src, Buffer& dst, std::size_t bytes) const;
  // `count` elements from element `offset` of `buffer`, read through a temporary buffer (sizeof(T)
  // a multiple of 4). A plain Buffer::read can make the driver move the buffer to memory the CPU
  // reads faster: on the H100, kernels over a 64 MiB buffer ran 2.4x slower after one read-back
  // (`bench grid` before it checked through here). Use it on buffers that are still worked on.
  template <class T>
  std::vector<T> readBack(const Buffer& buffer, std::size_t count, std::size_t offset = 0) const {
    static_assert(sizeof(T) % 4 == 0, "readBack copies whole 32-bit words");
    Buffer staging((offset + count) * sizeof(T));
    copy(buffer, staging, staging.size());
    return staging.read<T>(count, offset);
  }

 private:
  struct FillUniforms {
    GLuint words = 0, value = 0;
    static constexpr auto fields() {
      return std::tuple{field("uWords", &FillUniforms::words), field("uValue", &FillUniforms::value)};
    }
  };
  struct CopyUniforms {
    GLuint words = 0;
    static constexpr auto fields() { return std::tuple{field("uWords", &CopyUniforms::words)}; }
  };
  Kernel<FillUniforms> m_fill;
  Kernel<CopyUniforms> m_copy;
  std::size_t m_chunk;  // bytes bound per dispatch: under GL_MAX_SHADER_STORAGE_BLOCK_SIZE
};

}  // namespace tidepool::gl
