// The offscreen image every renderer draws into: RGBA8 colour (display-ready, tone mapped by the
// renderer where it works in HDR) and a 32-bit float depth. The window blits it to the screen,
// headless runs read it back into PNG frames or video.
#pragma once

#include <cstdint>
#include <vector>

#include "gl/framebuffer.h"
#include "gl/texture.h"

namespace tidepool {

class RenderTarget {
 public:
  RenderTarget(int width, int height);
  void resize(int width, int height);  // no-op when unchanged
  int width() const { return m_color.width(); }
  int height() const { return m_color.height(); }
  void bind() const { m_fbo.bind(); }  // framebuffer + viewport
  const gl::Texture2D& color() const { return m_color; }
  const gl::Texture2D& depth() const { return m_depth; }
  const gl::Framebuffer& framebuffer() const { return m_fbo; }
  std::vector<std::uint8_t> readRgba8() const { return m_color.readRgba8(); }  // top row first

 private:
  gl::Texture2D m_color, m_depth;
  gl::Framebuffer m_fbo;
};

}  // namespace tidepool
