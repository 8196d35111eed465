// Reading a few bytes back from the GPU without stalling it: request() copies them into a
// staging buffer and drops a fence; poll() returns them once the fence has passed, never waiting.
// Used by the divergence watch (a handful of reduced values every few frames), the particle
// export (a model's state buffers, one after the other, every exported frame) and the fluid's
// bodies (their loads, read while the GPU starts the next step).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "gl/buffer.h"

namespace tidepool::gl {

class AsyncReadback {
 public:
  AsyncReadback() = default;
  ~AsyncReadback();
  AsyncReadback(const AsyncReadback&) = delete;
  AsyncReadback& operator=(const AsyncReadback&) = delete;

  // Starts a copy of `bytes` from `src` (replacing any request still in flight).
  void request(const Buffer& src, std::size_t bytes, std::size_t offset = 0);
  // The same for several buffers: their ranges come back one after the other, in this order.
  struct Range {
    const Buffer* buffer;
    std::size_t bytes;
    std::size_t offset = 0;
  };
  void request(std::span<const Range> ranges);
  bool pending() const { return m_fence != nullptr; }
  // True (and `out` filled) once the copy has completed on the GPU; false while it has not.
  bool poll(std::vector<std::byte>& out);
  // Blocks until the copy is done (the bodies' loads, which the next step needs; tests, shutdown).
  void wait(std::vector<std::byte>& out);

 private:
  void dropFence();
  Buffer m_staging;
  GLsync m_fence = nullptr;
  std::size_t m_bytes = 0;
};

}  // namespace tidepool::gl
