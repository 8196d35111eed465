// Caustics of the 3D ripples view: sunlight through a grid of light points on the surface,
// refracted and followed to the floor, as light per floor texel (R16F, 1 = flat water). Each
// point carries texels / points of light, so the mean stays 1 whatever the waves do.
//   compute (default): each point increments its texel's counter (atomicAdd, exact integers);
//                      a resolve pass scales the counts to light and clears them;
//   raster:            one additive 1-px GL_POINT per light point (the original).
#include <algorithm>
#include <cmath>

#include "render/ripples/bindings.glsl"
#include "render/ripples_view3d.h"

namespace tidepool {

void RipplesView3D::renderCaustics(const ripples::Ripples& model) {
  const ripples::Params& mp = model.params();
  const float aspect = float(mp.height) / float(mp.width);
  const int tw = m_params.causticsSize, th = std::max(1, int(std::lround(tw * aspect)));
  if (m_caustics.width() != tw || m_caustics.height() != th) {
    m_caustics = gl::Texture2D(tw, th, GL_R16F);
    m_causticsFbo = gl::Framebuffer({&m_caustics});
    m_light = gl::Buffer(std::size_t(tw) * std::size_t(th) * sizeof(GLuint));
    m_ops.fill(m_light, 0);  // the resolve pass clears it from then on
  }
  const glm::ivec2 grid(m_params.lightGrid, std::max(1, int(std::lround(m_params.lightGrid * aspect))));
  const float weight = float(tw) * float(th) / (float(grid.x) * float(grid.y));
  if (m_params.renderer == RipplesRenderer::Compute)
    splatCaustics(model, grid, weight);
  else
    drawCaustics(model, grid, weight);
}

void RipplesView3D::splatCaustics(const ripples::Ripples& model, glm::ivec2 grid, float weight) {
  const glm::ivec2 size(m_caustics.width(), m_caustics.height());
  m_light.bindBase(GL_SHADER_STORAGE_BUFFER, RIPPLES_VIEW_LIGHT);
  if (m_params.caustics) {
    gl::Program& splat = m_shaders.program({"render/ripples/caustics.comp"});
    setCommon(splat, model);
    splat.set("uLightGrid", grid);
    splat.set("uLightSize", size);
    splat.dispatchThreads(std::size_t(grid.x) * std::size_t(grid.y));
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }
  gl::Program& resolve = m_shaders.program({"render/ripples/caustics_resolve.comp"});
  resolve.use();
  resolve.set("uLightSize", size);
  resolve.set("uWeight", weight);
  resolve.set("uFlat", m_params.caustics ? 0 : 1);  // without caustics the floor gets the flat-water light
  m_caustics.bindImage(RIPPLES_VIEW_LIGHT_IMAGE, GL_WRITE_ONLY, GL_R16F);
  const glm::uvec2 groups = (glm::uvec2(size) + glm::uvec2(RIPPLES_VIEW_GROUP - 1)) / glm::uvec2(RIPPLES_VIEW_GROUP);
  resolve.dispatch({groups.x, groups.y, 1});
  // The view samples the light; the next splat adds to the cleared counters.
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
}

void RipplesView3D::drawCaustics(const ripples::Ripples& model, glm::ivec2 grid, float weight) {
  m_causticsFbo.bind();
  // Without caustics the floor gets the flat-water light (1) everywhere.
  glClearColor(m_params.caustics ? 0.0f : 1.0f, 0.0f, 0.0f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  if (!m_params.caustics) return;
  gl::Program& p = m_shaders.program({"render/ripples/caustics.vert", "render/ripples/caustics.frag"});
  setCommon(p, model);
  p.set("uLightGrid", grid);
  p.set("uWeight", weight);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  glDisable(GL_DEPTH_TEST);
  m_vao.bind();
  glDrawArrays(GL_POINTS, 0, grid.x * grid.y);
  glDisable(GL_BLEND);
  glBindVertexArray(0);
}

}  // namespace tidepool
