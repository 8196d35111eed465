#include "render/life_view.h"

#include <algorithm>
#include <cmath>

#include "life/bindings.glsl"
#include "render/blue_noise.h"
#include "render/life/bindings.glsl"

namespace tidepool {

void visit(ParamVisitor& v, LifeViewParams& p) {
  v.flag({"glow", "Glow", "Gaussian halo around each particle"}, p.glow);
  v.flag({"particles", "Particles", "discs (or sub-pixel splats when zoomed out)"}, p.particles);
  v.real({"glow_size", "Glow size", "half-size of the halo, world units"}, p.glowSize, 0.5f, 100.0f);
  v.real({"glow_intensity", "Glow intensity", "peak alpha of the halo"}, p.glowIntensity, 0.0f, 1.0f);
  v.real({"radius", "Radius", "particle radius, world units"}, p.radius, 0.05f, 20.0f);
  v.real({"exposure", "Exposure", "HDR scale before the ACES tone map"}, p.exposure, 0.01f, 100.0f);
  v.flag({"dither", "Dither", "blue-noise dither to 8 bits"}, p.dither);
}

LifeView::LifeView(gl::ShaderLibrary& shaders) : m_shaders(shaders), m_blueNoise(makeBlueNoiseTexture()) {}

LifeCamera LifeView::fit(glm::vec2 box, glm::ivec2 viewport) {
  const float aspect = float(viewport.x) / float(std::max(viewport.y, 1));
  return {glm::vec2(0.0f), 0.5f * std::max(box.x, box.y * aspect)};
}

glm::vec2 LifeView::toWorld(glm::vec2 pixel, glm::ivec2 viewport) const {
  const glm::vec2 ndc(2.0f * pixel.x / float(viewport.x) - 1.0f, 1.0f - 2.0f * pixel.y / float(viewport.y));
  const glm::vec2 extent(m_camera.extentX, m_camera.extentX * float(viewport.y) / float(viewport.x));
  return m_camera.centre + ndc * extent;
}

void LifeView::pan(glm::vec2 cursor, glm::vec2 delta, glm::ivec2 viewport) {
  const glm::vec2 shift = toWorld(cursor, viewport) - toWorld(cursor - delta, viewport);
  m_camera.centre -= shift;
  m_camera.anchorWorld -= shift;  // a glide in progress keeps the panned point under its pixel
}

void LifeView::zoomAbout(glm::vec2 cursor, float clicks, glm::ivec2 viewport) {
  const float from = gliding() ? m_camera.targetExtentX : m_camera.extentX;
  m_camera.targetExtentX = from * std::pow(1.25f, -clicks);
  m_camera.anchorPixel = cursor;
  m_camera.anchorWorld = toWorld(cursor, viewport);
}

void LifeView::glide(float seconds, glm::ivec2 viewport) {
  if (!gliding()) return;
  LifeCamera& c = m_camera;
  c.extentX += (c.targetExtentX - c.extentX) * (1.0f - std::exp(-kZoomEaseRate * std::max(seconds, 0.0f)));
  if (std::abs(c.extentX - c.targetExtentX) <= 1e-5f * c.targetExtentX) {
    c.extentX = c.targetExtentX;  // arrived: the glide ends
    c.targetExtentX = 0.0f;
  }
  c.centre += c.anchorWorld - toWorld(c.anchorPixel, viewport);  // the anchor back under its pixel
}

void LifeView::drawParticles(const life::Life& model, const char* fragment, float halfSize, float ppu,
                             glm::vec2 extent) {
  gl::Program& p = m_shaders.program({"render/life/particle.vert", fragment},
                                     {{"LIFE_FP16", model.storage() == life::Storage::Fp16 ? "1" : "0"}});
  p.use();
  p.set("uCentre", m_camera.centre);
  p.set("uExtent", extent);
  p.set("uHalfSize", halfSize);
  p.set("uPixelsPerUnit", ppu);
  p.set("uRadius", m_params.radius);
  p.set("uGlowIntensity", m_params.glowIntensity);
  p.set("uExposure", m_params.exposure);
  model.positions().bindBase(GL_SHADER_STORAGE_BUFFER, LIFE_POSITIONS);
  model.speciesColors().bindBase(GL_SHADER_STORAGE_BUFFER, LIFE_SPECIES_COLORS);
  glDrawArrays(GL_TRIANGLES, 0, GLsizei(model.count() * 6));
}

void LifeView::render(const life::Life& model, RenderTarget& target, gl::GpuProfiler& profiler) {
  if (m_hdr.width() != target.width() || m_hdr.height() != target.height()) {
    m_hdr = gl::Texture2D(target.width(), target.height(), GL_RGBA16F);
    m_hdrFbo = gl::Framebuffer({&m_hdr});
  }
  const float ppu = pixelsPerUnit(target.width());
  const glm::vec2 extent(m_camera.extentX, m_camera.extentX * float(target.height()) / float(target.width()));
  m_vao.bind();
  glDisable(GL_DEPTH_TEST);
  {
    auto scope = profiler.scope("life.particles");
    m_hdrFbo.bind();
    glClearColor(0.001f, 0.001f, 0.001f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE, GL_ONE, GL_ONE);  // colour·alpha added, alpha summed
    if (m_params.glow) drawParticles(model, "render/life/glow.frag", m_params.glowSize, ppu, extent);
    if (m_params.particles) {
      if (ppu * m_params.radius >= 1.0f)
        drawParticles(model, "render/life/disc.frag", 1.5f * m_params.radius, ppu, extent);
      else
        drawParticles(model, "render/life/point.frag", 2.0f / ppu, ppu, extent);  // a 2-pixel quad
    }
    glDisable(GL_BLEND);
  }
  {
    auto scope = profiler.scope("life.compose");
    gl::Program& p = m_shaders.program({"render/common/fullscreen.vert", "render/life/compose.frag"});
    p.use();
    p.set("uDither", m_params.dither ? 1 : 0);
    m_hdr.bind(LIFE_VIEW_HDR_UNIT);
    m_blueNoise.bind(LIFE_VIEW_BLUE_NOISE_UNIT);
    target.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  glBindVertexArray(0);
}

}  // namespace tidepool
