#include "gl/texture.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <string>

namespace tidepool::gl {
namespace {
// GL 4.3's minimum GL_MAX_TEXTURE_BUFFER_SIZE. TIDEPOOL_TEXTURE_BUFFER_TEXELS (at least this)
// lowers BufferTexture::maxTexels() to meet a small GPU's limit on a big one.
constexpr std::size_t kMinBufferTexels = 65536;
}  // namespace

Texture2D::Texture2D(int width, int height, GLenum internalFormat, int levels)
    : m_handle(Handle<Kind::Texture>::generate()), m_width(width), m_height(height), m_format(internalFormat) {
  if (width <= 0 || height <= 0)
    throw GlError("texture size " + std::to_string(width) + "x" + std::to_string(height) + " is not positive");
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  if (width > maxSize || height > maxSize)
    throw GlError("texture size " + std::to_string(width) + "x" + std::to_string(height) +
                  " exceeds this GPU's limit of " + std::to_string(maxSize));
  glBindTexture(GL_TEXTURE_2D, id());
  glTexStorage2D(GL_TEXTURE_2D, levels, internalFormat, width, height);
  const bool linear = levels == 1 && internalFormat != GL_R32UI && internalFormat != GL_R32I;
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER,
                  levels > 1 ? GL_LINEAR_MIPMAP_LINEAR
                  : linear   ? GL_LINEAR
                             : GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, linear || levels > 1 ? GL_LINEAR : GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glBindTexture(GL_TEXTURE_2D, 0);
  if (glGetError() == GL_OUT_OF_MEMORY)
    throw GlError("out of GPU memory allocating a " + std::to_string(width) + "x" + std::to_string(height) +
                  " texture");
}

void Texture2D::upload(GLenum format, GLenum type, const void* pixels, int level) {
  glBindTexture(GL_TEXTURE_2D, id());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexSubImage2D(GL_TEXTURE_2D, level, 0, 0, std::max(1, m_width >> level), std::max(1, m_height >> level), format,
                  type, pixels);
  glBindTexture(GL_TEXTURE_2D, 0);
}

void Texture2D::download(GLenum format, GLenum type, void* pixels, int level) const {
  glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
  glBindTexture(GL_TEXTURE_2D, id());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTexImage(GL_TEXTURE_2D, level, format, type, pixels);
  glBindTexture(GL_TEXTURE_2D, 0);
}

std::vector<std::uint8_t> Texture2D::readRgba8() const {
  const std::size_t row = std::size_t(m_width) * 4;
  std::vector<std::uint8_t> bottomUp(row * m_height), topDown(row * m_height);
  download(GL_RGBA, GL_UNSIGNED_BYTE, bottomUp.data());
  for (int y = 0; y < m_height; ++y) std::memcpy(&topDown[row * y], &bottomUp[row * (m_height - 1 - y)], row);
  return topDown;
}

void Texture2D::setFilter(GLenum minFilter, GLenum magFilter) {
  glBindTexture(GL_TEXTURE_2D, id());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GLint(minFilter));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GLint(magFilter));
  glBindTexture(GL_TEXTURE_2D, 0);
}

void Texture2D::setWrap(GLenum wrap) {
  glBindTexture(GL_TEXTURE_2D, id());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GLint(wrap));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GLint(wrap));
  glBindTexture(GL_TEXTURE_2D, 0);
}

void Texture2D::bind(GLuint unit) const {
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_2D, id());
}

void Texture2D::bindImage(GLuint unit, GLenum access, GLenum format, int level) const {
  glBindImageTexture(unit, id(), level, GL_FALSE, 0, access, format ? format : m_format);
}

void Texture2D::generateMipmaps() {
  glBindTexture(GL_TEXTURE_2D, id());
  glGenerateMipmap(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, 0);
}

std::size_t BufferTexture::maxTexels() {
  static const std::size_t texels = [] {
    GLint v = 0;
    glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &v);
    std::size_t limit = std::size_t(v);
    if (const char* text = std::getenv("TIDEPOOL_TEXTURE_BUFFER_TEXELS"); text && *text) {
      char* end = nullptr;
      const unsigned long long n = std::strtoull(text, &end, 10);
      if (*end != '\0' || text[0] == '-' || n < kMinBufferTexels)
        throw Error("TIDEPOOL_TEXTURE_BUFFER_TEXELS = '" + std::string(text).substr(0, 40) +
                    "' is not a texel count of at least " + std::to_string(kMinBufferTexels));
      limit = std::min<std::size_t>(limit, n);
    }
    return limit;
  }();  // a bad override throws again on every call
  return texels;
}

void BufferTexture::bind(GLuint unit, GLuint buffer, GLenum internalFormat) {
  if (!m_handle) m_handle = Handle<Kind::Texture>::generate();
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_BUFFER, m_handle.get());
  glTexBuffer(GL_TEXTURE_BUFFER, internalFormat, buffer);
  glActiveTexture(GL_TEXTURE0);
}

}  // namespace tidepool::gl
