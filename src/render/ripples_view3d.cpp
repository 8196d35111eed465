#include "render/ripples_view3d.h"

#include <algorithm>

#include "render/textures.h"
#include "ripples/bindings.glsl"

namespace tidepool {

void visit(ParamVisitor& v, RipplesView3DParams& p) {
  v.real({"exaggeration", "Exaggeration", "heights and slopes; 1 = physical"}, p.exaggeration, 0.0f, 100.0f);
  v.real({"water_level", "Water level", "rest surface above the floor, tank widths"}, p.waterLevel, 0.01f, 2.0f);
  v.integer({"mesh_cells", "Mesh cells", "surface quads along x"}, p.meshCells, 8, 2048);
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
    : m_shaders(shaders), m_floor(loadRepeatingTexture("tiles.png")) {}

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

void RipplesView3D::renderCaustics(const ripples::Ripples& model) {
  const ripples::Params& mp = model.params();
  const float aspect = float(mp.height) / float(mp.width);
  const int tw = m_params.causticsSize, th = std::max(1, int(std::lround(tw * aspect)));
  if (m_caustics.width() != tw || m_caustics.height() != th) {
    m_caustics = gl::Texture2D(tw, th, GL_R16F);
    m_causticsFbo = gl::Framebuffer({&m_caustics});
  }
  m_causticsFbo.bind();
  // Without caustics the floor gets the flat-water light (1) everywhere.
  glClearColor(m_params.caustics ? 0.0f : 1.0f, 0.0f, 0.0f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  if (!m_params.caustics) return;
  const glm::ivec2 grid(m_params.lightGrid, std::max(1, int(std::lround(m_params.lightGrid * aspect))));
  gl::Program& p = m_shaders.program({"render/ripples_caustics.vert", "render/ripples_caustics.frag"});
  setCommon(p, model);
  p.set("uLightGrid", grid);
  p.set("uWeight", float(tw) * th / (float(grid.x) * grid.y));
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  glDisable(GL_DEPTH_TEST);
  m_vao.bind();
  glDrawArrays(GL_POINTS, 0, grid.x * grid.y);
  glDisable(GL_BLEND);
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
  target.bind();
  glClearColor(0.07f, 0.08f, 0.1f, 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  m_floor.bind(0);
  m_caustics.bind(1);
  m_vao.bind();
  auto shading = [&](gl::Program& p) {
    setCommon(p, model);
    p.set("uViewProj", viewProj);
    p.set("uEye", m_camera.eye());
    p.set("uFloor", 0);
    p.set("uCaustics", 1);
    p.set("uTileRepeat", m_params.tileRepeat);
    p.set("uWaterColor", m_params.waterColor);
    p.set("uViewDistance", m_params.viewDistance);
    p.set("uAmbient", m_params.ambient);
  };
  gl::Program& walls = m_shaders.program({"render/ripples_walls.vert", "render/ripples_walls.frag"});
  shading(walls);
  walls.set("uWallTop", 2.0f * m_params.waterLevel);
  glDrawArrays(GL_TRIANGLES, 0, 24);
  if (model.sphereActive()) {
    // The ball at true scale (heights are exaggerated, the ball is not).
    const float metresToWorld = 1.0f / (float(mp.width) * mp.cellSize);
    const glm::vec3 c = model.sphereCentre();
    gl::Program& ball = m_shaders.program({"render/sphere.vert", "render/sphere.frag"});
    ball.use();
    ball.set("uSegments", glm::ivec2(48, 24));
    ball.set("uCentre", glm::vec3(c.x * metresToWorld, c.y * metresToWorld, m_params.waterLevel + c.z * metresToWorld));
    ball.set("uRadius", mp.sphereRadius * metresToWorld);
    ball.set("uViewProj", viewProj);
    ball.set("uColor", glm::vec3(0.85f, 0.35f, 0.12f));
    ball.set("uSunDir", glm::normalize(m_params.sunDir));
    ball.set("uEye", m_camera.eye());
    glCullFace(GL_FRONT);  // the generated winding faces inwards
    glDrawArrays(GL_TRIANGLES, 0, 6 * 48 * 24);
    glCullFace(GL_BACK);
  }
  glDisable(GL_CULL_FACE);  // the surface is seen from both sides at grazing angles
  gl::Program& surface = m_shaders.program({"render/ripples_surface.vert", "render/ripples_surface.frag"});
  shading(surface);
  const glm::ivec2 mesh(m_params.meshCells, std::max(1, int(std::lround(m_params.meshCells * tank.y))));
  surface.set("uMesh", mesh);
  glDrawArrays(GL_TRIANGLES, 0, 6 * mesh.x * mesh.y);
  glDisable(GL_DEPTH_TEST);
  glBindVertexArray(0);
}

bool RipplesView3D::pick(glm::vec2 pixel, glm::ivec2 viewport, glm::ivec2 grid, glm::vec2& uv) const {
  const glm::vec3 dir = m_camera.rayDirection(pixel, viewport), eye = m_camera.eye();
  if (std::abs(dir.z) < 1e-6f) return false;
  const float t = (m_params.waterLevel - eye.z) / dir.z;
  if (t <= 0) return false;
  const glm::vec3 hit = eye + t * dir;
  uv = glm::vec2(hit.x, hit.y * float(grid.x) / float(grid.y));
  return uv.x >= 0 && uv.y >= 0 && uv.x <= 1 && uv.y <= 1;
}

}  // namespace tidepool
