#include "render/balls_gbuffer.h"

#include "gl/window.h"
#include "render/balls/bindings.glsl"

namespace tidepool {

BallsGBuffer::BallsGBuffer(gl::ShaderLibrary& shaders) : m_shaders(shaders), m_splat(shaders) {}

void BallsGBuffer::resize(int width, int height) {
  if (m_surface && m_surface.width() == width && m_surface.height() == height) return;
  m_surface = gl::Texture2D(width, height, GL_RGBA32F);
  m_foam = gl::Texture2D(width, height, GL_R16F);
  m_depth = gl::Texture2D(width, height, GL_DEPTH_COMPONENT32F);
  m_depthImage = gl::Texture2D(width, height, GL_R32F);
  for (gl::Texture2D* t : {&m_surface, &m_foam, &m_depth, &m_depthImage}) t->setFilter(GL_NEAREST, GL_NEAREST);
  m_impostorFbo = gl::Framebuffer({&m_surface, &m_foam}, &m_depth);
  m_thicknessFbo = gl::Framebuffer();
  m_thicknessDepthId = 0;
}

void BallsGBuffer::drawSpheres(gl::Program& program, const SphereBatch& balls, const BallsCamera& camera) {
  program.use();
  program.set("uModelView", camera.view * balls.model);
  program.set("uProj", camera.proj);
  program.set("uRadius", balls.radius);
  program.set("uHasFoam", balls.velocities ? 1 : 0);
  // Arrays over one storage block: a draw per window, gl_VertexID / 6 the ball in it (gl/window.h).
  for (const gl::Window& w : gl::windows(balls.count, sizeof(glm::vec4))) {
    gl::bindWindow(*balls.positions, BALLS_VIEW_POSITIONS, w, sizeof(glm::vec4));
    if (balls.velocities) gl::bindWindow(*balls.velocities, BALLS_VIEW_VELOCITIES, w, sizeof(glm::vec4));
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(6 * w.count));
  }
}

std::vector<float> BallsGBuffer::readDepth() const {
  std::vector<float> out(std::size_t(depth().width()) * std::size_t(depth().height()));
  depth().download(m_compute ? GL_RED : GL_DEPTH_COMPONENT, GL_FLOAT, out.data());
  return out;
}

void BallsGBuffer::draw(const SphereBatch& balls, const BallsCamera& camera, const SceneDepth& scene, bool thickness,
                        BallsRaster raster, gl::GpuProfiler& profiler) {
  resize(camera.width, camera.height);
  // The compute raster resolves each pixel's ball from anywhere in the arrays: all of them bound at
  // once. Balls over one storage block are drawn as fragments, a window at a time.
  m_compute = raster == BallsRaster::Compute && !gl::needsWindows(balls.count, sizeof(glm::vec4));
  if (m_compute)
    m_splat.draw(balls, camera, scene, thickness, m_surface, m_foam, m_depthImage, profiler);
  else
    drawFragments(balls, camera, scene.texture, thickness, profiler);
}

void BallsGBuffer::drawFragments(const SphereBatch& balls, const BallsCamera& camera, const gl::Texture2D* sceneDepth,
                                 bool thickness, gl::GpuProfiler& profiler) {
  m_vao.bind();
  glDisable(GL_BLEND);
  {
    auto scope = profiler.scope("balls.gbuffer");
    m_impostorFbo.bind();
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    const float zero[4] = {0, 0, 0, 0};
    const float one = 1.0f;
    glClearBufferfv(GL_COLOR, 0, zero);
    glClearBufferfv(GL_COLOR, 1, zero);
    glClearBufferfv(GL_DEPTH, 0, &one);
    if (balls.count > 0) {
      glEnable(GL_DEPTH_TEST);
      glDepthFunc(GL_LESS);
      glColorMaski(0, GL_TRUE, GL_TRUE, GL_FALSE, GL_TRUE);  // B is the thickness pass's
      drawSpheres(m_shaders.program({"render/balls/gbuffer.vert", "render/balls/gbuffer.frag"}), balls, camera);
    }
  }
  if (thickness && balls.count > 0) {
    auto scope = profiler.scope("balls.thickness");
    const GLuint depthId = sceneDepth ? sceneDepth->id() : 0;
    if (!m_thicknessFbo.id() || m_thicknessDepthId != depthId) {
      m_thicknessFbo = gl::Framebuffer({&m_surface}, sceneDepth);
      m_thicknessDepthId = depthId;
    }
    m_thicknessFbo.bind();
    if (sceneDepth) glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_FALSE);
    glColorMaski(0, GL_FALSE, GL_FALSE, GL_TRUE, GL_FALSE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    drawSpheres(m_shaders.program({"render/balls/gbuffer.vert", "render/balls/thickness.frag"}), balls, camera);
    glDisable(GL_BLEND);
  }
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
  glDisable(GL_DEPTH_TEST);
  glBindVertexArray(0);
}

}  // namespace tidepool
