// The raster renderer of the 3D ripples view: walls, ball and a displaced surface mesh drawn with
// the depth test, shaded per fragment (the original renderer; the compute ray caster is the
// default and is checked against this one).
#include <algorithm>

#include "render/ripples_view3d.h"

namespace tidepool {

void RipplesView3D::rasterise(const ripples::Ripples& model, RenderTarget& target, const glm::mat4& viewProj) {
  const ripples::Params& mp = model.params();
  target.bind();
  glClearColor(0.07f, 0.08f, 0.1f, 1.0f);  // kBackground in render/ripples/shading.glsl
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  m_vao.bind();
  gl::Program& walls = m_shaders.program({"render/ripples/walls.vert", "render/ripples/walls.frag"});
  setShading(walls, model);
  walls.set("uViewProj", viewProj);
  walls.set("uWallTop", 2.0f * m_params.waterLevel);
  glDrawArrays(GL_TRIANGLES, 0, 24);
  if (const glm::vec4 b = ball(model); b.w > 0.0f) {
    gl::Program& p = m_shaders.program({"render/ripples/sphere.vert", "render/ripples/sphere.frag"});
    p.use();
    p.set("uSegments", glm::ivec2(48, 24));
    p.set("uCentre", glm::vec3(b));
    p.set("uRadius", b.w);
    p.set("uViewProj", viewProj);
    p.set("uColor", glm::vec3(0.85f, 0.35f, 0.12f));
    p.set("uSunDir", glm::normalize(m_params.sunDir));
    p.set("uEye", m_camera.eye());
    p.set("uOrtho", m_camera.params().projection == Projection::Orthographic ? 1 : 0);
    p.set("uViewDir", m_camera.viewDirection());
    glCullFace(GL_FRONT);  // the generated winding faces inwards
    glDrawArrays(GL_TRIANGLES, 0, 6 * 48 * 24);
    glCullFace(GL_BACK);
  }
  glDisable(GL_CULL_FACE);  // the surface is seen from both sides at grazing angles
  gl::Program& surface = m_shaders.program({"render/ripples/surface.vert", "render/ripples/surface.frag"});
  setShading(surface, model);
  surface.set("uViewProj", viewProj);
  const glm::ivec2 mesh(m_params.meshCells,
                        std::max(1, int(std::lround(m_params.meshCells * float(mp.height) / float(mp.width)))));
  surface.set("uMesh", mesh);
  glDrawArrays(GL_TRIANGLES, 0, 6 * mesh.x * mesh.y);
  glDisable(GL_DEPTH_TEST);
  glBindVertexArray(0);
}

}  // namespace tidepool
