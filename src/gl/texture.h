// 2D textures with immutable-size storage (glTexStorage2D, core in 4.2) for render targets,
// images for compute shaders and sampled assets.
#pragma once

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

}  // namespace tidepool::gl
