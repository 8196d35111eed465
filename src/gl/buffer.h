// Shader storage / uniform / vertex buffers. GL 4.3 has no DSA, so every operation binds to the
// copy targets (GL_COPY_READ/WRITE_BUFFER) and leaves the indexed SSBO bindings alone.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "gl/handle.h"

namespace tidepool::gl {

class Buffer {
 public:
  Buffer() = default;
  explicit Buffer(std::size_t bytes, const void* data = nullptr, GLenum usage = GL_DYNAMIC_COPY);
  template <class T>
  explicit Buffer(std::span<const T> data, GLenum usage = GL_DYNAMIC_COPY)
      : Buffer(data.size_bytes(), data.data(), usage) {}

  GLuint id() const { return m_handle.get(); }
  std::size_t size() const { return m_size; }  // bytes
  // Changes with every write made through this class or gl::BufferOps (made, uploaded, filled,
  // copied into), never with a kernel's: whoever keeps something derived from the contents (the
  // balls' grid counts) can tell that someone else wrote them since. Unique across buffers.
  std::uint64_t version() const { return m_version; }
  void markWritten();
  explicit operator bool() const { return bool(m_handle); }

  void resize(std::size_t bytes, GLenum usage = GL_DYNAMIC_COPY);  // contents are lost
  void upload(const void* data, std::size_t bytes, std::size_t offset = 0);
  void download(void* data, std::size_t bytes, std::size_t offset = 0) const;
  void fillZero();  // glClearBufferData
  void copyTo(Buffer& dst, std::size_t bytes, std::size_t srcOffset = 0, std::size_t dstOffset = 0) const;
  void bindBase(GLenum target, GLuint index) const;  // SSBO / UBO binding point
  void bindRange(GLenum target, GLuint index, std::size_t offset, std::size_t bytes) const;

  template <class T>
  void upload(std::span<const T> data, std::size_t offsetElems = 0) {
    upload(data.data(), data.size_bytes(), offsetElems * sizeof(T));
  }
  template <class T>
  std::vector<T> read(std::size_t count, std::size_t offsetElems = 0) const {
    std::vector<T> out(count);
    download(out.data(), count * sizeof(T), offsetElems * sizeof(T));
    return out;
  }
  template <class T>
  std::vector<T> readAll() const {
    return read<T>(m_size / sizeof(T));
  }

 private:
  Handle<Kind::Buffer> m_handle;
  std::size_t m_size = 0;
  std::uint64_t m_version = 0;
};

}  // namespace tidepool::gl
