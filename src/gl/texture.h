// 2D textures with immutable-size storage (glTexStorage2D, core in 4.2) for render targets,
// images for compute shaders and sampled assets; buffer textures that let a kernel read a buffer
// through a sampler (texelFetch) instead of a storage block.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "gl/handle.h"

namespace tidepool::gl {

class Texture2D {
 public:
  Texture2D() = default;
  // internalFormat e.g. GL_RGBA8, GL_RGBA16F, GL_R32F, GL_DEPTH_COMPONENT32F.
  Texture2D(int width, int height, GLenum internalFormat, int levels = 1);

  GLuint id() const { return m_handle.get(); }
  int width() const { return m_width; }
  int height() const { return m_height; }
  GLenum format() const { return m_format; }
  explicit operator bool() const { return bool(m_handle); }

  void upload(GLenum format, GLenum type, const void* pixels, int level = 0);
  void download(GLenum format, GLenum type, void* pixels, int level = 0) const;  // whole level
  std::vector<std::uint8_t> readRgba8() const;                                   // top row first
  void setFilter(GLenum minFilter, GLenum magFilter);
  void setWrap(GLenum wrap);
  void bind(GLuint unit) const;  // sampler unit
  void bindImage(GLuint unit, GLenum access, GLenum format = 0, int level = 0) const;
  void generateMipmaps();

 private:
  Handle<Kind::Texture> m_handle;
  int m_width = 0, m_height = 0;
  GLenum m_format = 0;
};

// A buffer read through a samplerBuffer / usamplerBuffer (glTexBuffer, core in 3.1). A kernel may
// read up to 16 of them beside its 8 storage blocks (GL 4.3's minimums), each of at most
// maxTexels() elements (GL 4.3 guarantees 65,536; desktop GPUs and llvmpipe give 2^27 or more).
class BufferTexture {
 public:
  static std::size_t maxTexels();  // GL_MAX_TEXTURE_BUFFER_SIZE
  // `buffer`'s data as texels of `internalFormat` (GL_RGBA32F, GL_R32UI, ...) on sampler `unit`;
  // the texture follows the buffer until the next bind (a buffer reallocated is bound again).
  void bind(GLuint unit, GLuint buffer, GLenum internalFormat);

 private:
  Handle<Kind::Texture> m_handle;
};

}  // namespace tidepool::gl
