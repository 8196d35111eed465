#include "render/target.h"

#include <string>

#include "base/error.h"

namespace tidepool {

RenderTarget::RenderTarget(int width, int height) { resize(width, height); }

void RenderTarget::resize(int width, int height) {
  if (width == this->width() && height == this->height() && m_color) return;
  if (width <= 0 || height <= 0)
    throw Error("image size " + std::to_string(width) + "x" + std::to_string(height) + " must be positive");
  m_color = gl::Texture2D(width, height, GL_RGBA8);
  m_depth = gl::Texture2D(width, height, GL_DEPTH_COMPONENT32F);
  m_fbo = gl::Framebuffer({&m_color}, &m_depth);
}

}  // namespace tidepool
