#include "render/ripples_view3d.h"

#include <algorithm>

#include "render/ripples/bindings.glsl"
#include "render/textures.h"
#include "ripples/bindings.glsl"

namespace tidepool {

void visit(ParamVisitor& v, RipplesView3DParams& p) {
  v.real({"exaggeration", "Exaggeration", "heights and slopes; 1 = physical"}, p.exaggeration, 0.0f, 100.0f);
  v.real({"water_level", "Water level", "rest surface above the floor, tank widths"}, p.waterLevel, 0.01f, 2.0f);
  v.integer({"mesh_cells", "Mesh cells", "surface quads along x (raster renderer)"}, p.meshCells, 8, 2048);
  v.integer({"light_grid", "Light points", "caustic light points along x"}, p.lightGrid, 16, 4096);
  v.integer({"caustics_size", "Caustics texels", "floor light texels along x"}, p.causticsSize, 16, 4096);
  v.vector({"sun_dir", "Sun direction", "towards the sun"}, p.sunDir, -10.0f, 10.0f);
  v.real({"ambient", "Ambient", "floor light without sun"}, p.ambient, 0.0f, 1.0f);
  v.color({"water_color", "Water colour", "linear RGB of deep water"}, p.waterColor);
  v.real({"view_distance", "View distance", "tank widths of water that absorb 63%"}, p.viewDistance, 0.01f, 10.0f);
  v.real({"tile_repeat", "Tile repeat", "floor tiles across the tank"}, p.tileRepeat, 0.25f, 64.0f);
  v.flag({"caustics", "Caustics", "refracted sunlight on the floor"}, p.caustics);
}

RipplesView3D::RipplesView3D(gl::ShaderLibrary& shaders)
    : m_shaders(shaders), m_ops(shaders), m_floor(loadRepeatingTexture("tiles.png")), m_range(2 * sizeof(GLuint)) {}

void RipplesView3D::setCommon(gl::Program& p, const ripples::Ripples& model) const {
  const ripples::Params& mp = model.params();
  p.use();
  p.set("uSize", glm::ivec2(mp.width, mp.height));
  p.set("uCellSize", mp.cellSize);
  p.set("uTank", glm::vec2(1.0f, float(mp.height) / float(mp.width)));
  p.set("uWaterLevel", m_params.waterLevel);
  p.set("uExaggeration", m_params.exaggeration);
  p.set("uSunDir", glm::normalize(m_params.sunDir));
  model.state().bindBase(GL_SHADER_STORAGE_BUFFER, RIPPLES_STATE_IN);
}

void RipplesView3D::setShading(gl::Program& p, const ripples::Ripples& model) const {
  setCommon(p, model);
  p.set("uEye", m_camera.eye());
  p.set("uOrtho", m_camera.params().projection == Projection::Orthographic ? 1 : 0);
  p.set("uViewDir", m_camera.viewDirection());
  p.set("uTileRepeat", m_params.tileRepeat);
  p.set("uWaterColor", m_params.waterColor);
  p.set("uViewDistance", m_params.viewDistance);
  p.set("uAmbient", m_params.ambient);
  m_floor.bind(RIPPLES_VIEW_FLOOR_UNIT);
  m_caustics.bind(RIPPLES_VIEW_CAUSTICS_UNIT);
}

glm::vec4 RipplesView3D::ball(const ripples::Ripples& model) const {
  if (!model.sphereActive()) return glm::vec4(0.0f);
  // The ball at true scale (heights are exaggerated, the ball is not).
  const ripples::Params& mp = model.params();
  const float metresToWorld = 1.0f / (float(mp.width) * mp.cellSize);
  const glm::vec3 c = model.sphereCentre();
  return {c.x * metresToWorld, c.y * metresToWorld, m_params.waterLevel + c.z * metresToWorld,
          mp.sphereRadius * metresToWorld};
}

void RipplesView3D::render(const ripples::Ripples& model, RenderTarget& target, gl::GpuProfiler& profiler) {
  const ripples::Params& mp = model.params();
  const glm::vec2 tank(1.0f, float(mp.height) / float(mp.width));
  {
    auto scope = profiler.scope("ripples.caustics");
    renderCaustics(model);
  }
  auto scope = profiler.scope("ripples.view3d");
  m_camera.fit(glm::vec3(0.5f * tank, 0.5f * m_params.waterLevel),
               0.5f * glm::length(glm::vec3(tank, 1.5f * m_params.waterLevel)));
  const glm::mat4 viewProj = m_camera.projection(float(target.width()) / float(target.height())) * m_camera.view();
  if (m_params.renderer == RipplesRenderer::Compute)
    rayCast(model, target, viewProj);
  else
    rasterise(model, target, viewProj);
}

void RipplesView3D::rayCast(const ripples::Ripples& model, RenderTarget& target, const glm::mat4& viewProj) {
  const ripples::Params& mp = model.params();
  // Tiles of RIPPLES_VIEW_TILE^2 dual cells; dual cells k = 0 .. size along each axis.
  const glm::ivec2 tiles = glm::ivec2(mp.width, mp.height) / RIPPLES_VIEW_TILE + 1;
  const std::size_t tileBytes = std::size_t(tiles.x) * std::size_t(tiles.y) * 2 * sizeof(float);
  if (m_tiles.size() != tileBytes) m_tiles = gl::Buffer(tileBytes);
  const GLuint empty[2] = {0xffffffffu, 0u};  // ordered bits: min = +inf-ish, max = -inf-ish
  m_range.upload(empty, sizeof empty);
  gl::Program& bounds = m_shaders.program({"render/ripples/tiles.comp"});
  setCommon(bounds, model);
  bounds.set("uTiles", tiles);
  m_tiles.bindBase(GL_SHADER_STORAGE_BUFFER, RIPPLES_VIEW_TILES);
  m_range.bindBase(GL_SHADER_STORAGE_BUFFER, RIPPLES_VIEW_RANGE);
  bounds.dispatch({unsigned(tiles.x + 7) / 8, unsigned(tiles.y + 7) / 8, 1});
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

  gl::Program& p = m_shaders.program({"render/ripples/raycast.comp"});
  setShading(p, model);
  const glm::ivec2 size(target.width(), target.height());
  p.set("uTiles", tiles);
  p.set("uTargetSize", size);
  p.set("uInvViewProj", glm::inverse(viewProj));
  p.set("uWallTop", 2.0f * m_params.waterLevel);
  p.set("uBall", ball(model));
  p.set("uBallColor", glm::vec3(0.85f, 0.35f, 0.12f));
  target.color().bindImage(RIPPLES_VIEW_COLOR_IMAGE, GL_WRITE_ONLY, GL_RGBA8);
  const glm::uvec2 groups = (glm::uvec2(size) + glm::uvec2(RIPPLES_VIEW_GROUP - 1)) / glm::uvec2(RIPPLES_VIEW_GROUP);
  p.dispatch({groups.x, groups.y, 1});
  // Readers of the image: read-backs, the window's blit, texture fetches.
  glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
}

bool RipplesView3D::pick(glm::vec2 pixel, glm::ivec2 viewport, glm::ivec2 grid, glm::vec2& uv) const {
  const glm::vec3 dir = m_camera.rayDirection(pixel, viewport), eye = m_camera.rayOrigin(pixel, viewport);
  if (std::abs(dir.z) < 1e-6f) return false;
  const float t = (m_params.waterLevel - eye.z) / dir.z;
  if (t <= 0) return false;
  const glm::vec3 hit = eye + t * dir;
  uv = glm::vec2(hit.x, hit.y * float(grid.x) / float(grid.y));
  return uv.x >= 0 && uv.y >= 0 && uv.x <= 1 && uv.y <= 1;
}

}  // namespace tidepool
