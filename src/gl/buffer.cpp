#include "gl/buffer.h"

#include <string>

namespace tidepool::gl {
namespace {
void checkRange(std::size_t offset, std::size_t bytes, std::size_t size, const char* what) {
  if (offset + bytes > size)
    throw GlError(std::string("buffer ") + what + " of " + std::to_string(bytes) + " bytes at offset " +
                  std::to_string(offset) + " overruns a buffer of " + std::to_string(size) + " bytes");
}
}  // namespace

Buffer::Buffer(std::size_t bytes, const void* data, GLenum usage) : m_handle(Handle<Kind::Buffer>::generate()) {
  glBindBuffer(GL_COPY_WRITE_BUFFER, id());
  glBufferData(GL_COPY_WRITE_BUFFER, GLsizeiptr(bytes), data, usage);
  GLint64 made = -1;  // what the driver says it made: a size it cut short would be read wrong later
  glGetBufferParameteri64v(GL_COPY_WRITE_BUFFER, GL_BUFFER_SIZE, &made);
  glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
  if (glGetError() == GL_OUT_OF_MEMORY)
    throw GlError("out of GPU memory allocating a buffer of " + std::to_string(bytes) + " bytes");
  if (made != GLint64(bytes))
    throw GlError("the GL driver made a buffer of " + std::to_string(made) + " bytes when " + std::to_string(bytes) +
                  " were asked");
  m_size = bytes;
  markWritten();
}

void Buffer::markWritten() {
  static std::uint64_t versions = 0;  // GL objects live on one thread
  m_version = ++versions;
}

void Buffer::resize(std::size_t bytes, GLenum usage) { *this = Buffer(bytes, nullptr, usage); }

void Buffer::upload(const void* data, std::size_t bytes, std::size_t offset) {
  checkRange(offset, bytes, m_size, "upload");
  if (!bytes) return;
  glBindBuffer(GL_COPY_WRITE_BUFFER, id());
  glBufferSubData(GL_COPY_WRITE_BUFFER, GLintptr(offset), GLsizeiptr(bytes), data);
  glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
  markWritten();
}

void Buffer::download(void* data, std::size_t bytes, std::size_t offset) const {
  checkRange(offset, bytes, m_size, "download");
  if (!bytes) return;
  // Writes by compute shaders must be visible to the read-back.
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glBindBuffer(GL_COPY_READ_BUFFER, id());
  glGetBufferSubData(GL_COPY_READ_BUFFER, GLintptr(offset), GLsizeiptr(bytes), data);
  glBindBuffer(GL_COPY_READ_BUFFER, 0);
}

void Buffer::fillZero() {
  if (!m_size) return;
  glBindBuffer(GL_COPY_WRITE_BUFFER, id());
  glClearBufferData(GL_COPY_WRITE_BUFFER, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
  glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
  // NVIDIA's driver (580) let a later glBufferSubData of the same buffer land before a clear it
  // had not yet submitted, so a checkpoint loaded over a freshly reset model came back half zeros
  // (docs/RELIABILITY.md, "Resume on your GPU"). Submitting the clear at once keeps the order.
  glFlush();
  markWritten();
}

void Buffer::copyTo(Buffer& dst, std::size_t bytes, std::size_t srcOffset, std::size_t dstOffset) const {
  checkRange(srcOffset, bytes, m_size, "copy source");
  checkRange(dstOffset, bytes, dst.m_size, "copy destination");
  if (!bytes) return;
  glBindBuffer(GL_COPY_READ_BUFFER, id());
  glBindBuffer(GL_COPY_WRITE_BUFFER, dst.id());
  glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, GLintptr(srcOffset), GLintptr(dstOffset),
                      GLsizeiptr(bytes));
  glBindBuffer(GL_COPY_READ_BUFFER, 0);
  glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
  dst.markWritten();
}

void Buffer::bindBase(GLenum target, GLuint index) const { glBindBufferBase(target, index, id()); }

void Buffer::bindRange(GLenum target, GLuint index, std::size_t offset, std::size_t bytes) const {
  checkRange(offset, bytes, m_size, "binding range");
  glBindBufferRange(target, index, id(), GLintptr(offset), GLsizeiptr(bytes));
}

}  // namespace tidepool::gl
