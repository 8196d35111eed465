#include "render/water_blur.h"

#include <algorithm>
#include <string>

#include "gl/kernel.h"
#include "render/balls/bindings.glsl"

namespace tidepool {
namespace {
struct BlurUniforms {
  float pixelRadius = 0.0f;                                         // px: kernel radius of a ball at view depth 1 m
  float depthThreshold = 0.0f;                                      // m
  GLint perspective = 0;                                            // 1: the radius shrinks as 1 / depth
  GLint source = BALLS_VIEW_BLUR_IN, target = BALLS_VIEW_BLUR_OUT;  // texture and image units
  static constexpr auto fields() {
    using U = BlurUniforms;
    return std::tuple{gl::field("uPixelRadius", &U::pixelRadius), gl::field("uDepthThreshold", &U::depthThreshold),
                      gl::field("uPerspective", &U::perspective), gl::field("uSource", &U::source),
                      gl::field("uTarget", &U::target)};
  }
};
}  // namespace

void WaterBlur::pass(int axis, const gl::Texture2D& from, const gl::Texture2D& to, float pixelRadius,
                     float depthThreshold, bool perspective) {
  const gl::Kernel<BlurUniforms> blur(m_shaders, "render/balls/water_blur.comp", {}, {{"AXIS", std::to_string(axis)}});
  from.bind(BALLS_VIEW_BLUR_IN);
  to.bindImage(BALLS_VIEW_BLUR_OUT, GL_WRITE_ONLY, GL_RGBA32F);
  const int useful = kGroup - 2 * kApron;  // outputs per work group
  const int along = axis == 0 ? from.width() : from.height();
  const int lines = axis == 0 ? from.height() : from.width();
  blur.dispatch({unsigned((along + useful - 1) / useful), unsigned(lines), 1u},
                {.pixelRadius = pixelRadius, .depthThreshold = depthThreshold, .perspective = perspective ? 1 : 0});
  // The next pass (or the compose pass, or a read-back) samples what this one stored.
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
}

void WaterBlur::run(const gl::Texture2D& source, float pixelRadius, float depthThreshold, int iterations,
                    bool perspective) {
  if (!m_out || m_out.width() != source.width() || m_out.height() != source.height()) {
    m_rows = gl::Texture2D(source.width(), source.height(), GL_RGBA32F);
    m_out = gl::Texture2D(source.width(), source.height(), GL_RGBA32F);
  }
  for (int i = 0; i < std::max(iterations, 1); ++i) {
    pass(0, i == 0 ? source : m_out, m_rows, pixelRadius, depthThreshold, perspective);
    pass(1, m_rows, m_out, pixelRadius, depthThreshold, perspective);
  }
}

}  // namespace tidepool
