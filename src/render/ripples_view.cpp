#include "render/ripples_view.h"

#include "render/ripples/bindings.glsl"
#include "render/textures.h"
#include "ripples/bindings.glsl"

namespace tidepool {

void visit(ParamVisitor& v, RipplesViewParams& p) {
  v.real({"slope_scale", "Slope scale", "exaggerates slopes; 1 = physical"}, p.slopeScale, 0.0f, 100.0f);
  v.real({"floor_depth", "Floor depth", "grid widths below the surface"}, p.floorDepth, 0.0f, 2.0f);
  v.real({"eta", "Refraction ratio", "air/water index ratio (seed 0.9)"}, p.eta, 0.5f, 1.0f);
  v.color({"water_color", "Water colour", "linear RGB"}, p.waterColor);
  v.real({"view_distance", "View distance", "grid widths of water that look opaque"}, p.viewDistance, 0.01f, 10.0f);
  v.vector({"light_dir", "Light direction", "towards the surface"}, p.lightDir, -10.0f, 10.0f);
  v.real({"tile_repeat", "Tile repeat", "floor tiles across the grid"}, p.tileRepeat, 0.25f, 64.0f);
}

RipplesView::RipplesView(gl::ShaderLibrary& shaders) : m_shaders(shaders), m_floor(loadRepeatingTexture("tiles.png")) {}

void RipplesView::coverMapping(glm::ivec2 viewport, glm::ivec2 grid, glm::vec2& scale, glm::vec2& offset) const {
  // Fill the viewport, cropping the grid's longer side, with square cells on screen.
  const float screenAspect = float(viewport.x) / float(std::max(viewport.y, 1));
  const float gridAspect = float(grid.x) / float(grid.y);
  scale = screenAspect > gridAspect ? glm::vec2(1.0f, gridAspect / screenAspect)
                                    : glm::vec2(screenAspect / gridAspect, 1.0f);
  offset = 0.5f * (1.0f - scale);
}

glm::vec2 RipplesView::gridUv(glm::vec2 pixel, glm::ivec2 viewport, glm::ivec2 grid) const {
  glm::vec2 scale, offset;
  coverMapping(viewport, grid, scale, offset);
  const glm::vec2 screenUv(pixel.x / float(viewport.x), 1.0f - pixel.y / float(viewport.y));
  return screenUv * scale + offset;
}

void RipplesView::setUniforms(gl::Program& p, const ripples::Ripples& model, glm::ivec2 viewport) const {
  const ripples::Params& mp = model.params();
  const glm::ivec2 grid(mp.width, mp.height);
  glm::vec2 scale, offset;
  coverMapping(viewport, grid, scale, offset);
  p.use();
  p.set("uSize", grid);
  p.set("uUvScale", scale);
  p.set("uUvOffset", offset);
  p.set("uSlopeScale", m_params.slopeScale);
  p.set("uCellSize", mp.cellSize);
  p.set("uFloorDepth", m_params.floorDepth);
  p.set("uEta", m_params.eta);
  p.set("uWaterColor", m_params.waterColor);
  p.set("uViewDistance", m_params.viewDistance);
  p.set("uLightDir", m_params.lightDir);
  p.set("uTileRepeat", m_params.tileRepeat);
  glm::vec4 sphere(0.0f);
  if (model.sphereActive()) {
    const float width = float(mp.width) * mp.cellSize, height = float(mp.height) * mp.cellSize;
    const glm::vec3 c = model.sphereCentre();
    sphere = glm::vec4(c.x / width, c.y / height, mp.sphereRadius / width, c.z / mp.sphereRadius);
  }
  p.set("uSphere", sphere);
  m_floor.bind(RIPPLES_VIEW_FLOOR_UNIT);
  model.state().bindBase(GL_SHADER_STORAGE_BUFFER, RIPPLES_STATE_IN);
}

void RipplesView::render(const ripples::Ripples& model, RenderTarget& target, gl::GpuProfiler& profiler) {
  auto scope = profiler.scope("ripples.view2d");
  const glm::ivec2 size(target.width(), target.height());
  if (m_params.renderer == RipplesRenderer::Compute) {
    gl::Program& p = m_shaders.program({"render/ripples/view_2d.comp"});
    setUniforms(p, model, size);
    p.set("uTargetSize", size);
    target.color().bindImage(RIPPLES_VIEW_COLOR_IMAGE, GL_WRITE_ONLY, GL_RGBA8);
    const glm::uvec2 groups = (glm::uvec2(size) + glm::uvec2(RIPPLES_VIEW_GROUP - 1)) / glm::uvec2(RIPPLES_VIEW_GROUP);
    p.dispatch({groups.x, groups.y, 1});
    // Readers of the image: read-backs, the window's blit, texture fetches.
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    return;
  }
  gl::Program& p = m_shaders.program({"render/common/fullscreen.vert", "render/ripples/view_2d.frag"});
  setUniforms(p, model, size);
  target.bind();
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  m_vao.bind();
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
}

}  // namespace tidepool
