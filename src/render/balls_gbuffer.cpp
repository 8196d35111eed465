#include "render/balls_gbuffer.h"

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
  balls.positions->bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_VIEW_POSITIONS);
  if (balls.velocities) balls.velocities->bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_VIEW_VELOCITIES);
  glDrawArrays(GL_TRIANGLES, 0, GLsizei(6 * balls.count));
}

std::vector<float> BallsGBuffer::readDepth() const {
  std::vector<float> out(std::size_t(depth().width()) * std::size_t(depth().height()));
  depth().download(m_compute ? GL_RED : GL_DEPTH_COMPONENT, GL_FLOAT, out.data());
  return out;
}

void BallsGBuffer::draw(const SphereBatch& balls, const BallsCamera& camera, const SceneDepth& scene, bool thickness,
                        BallsRaster raster, gl::GpuProfiler& profiler) {
  resize(camera.width, camera.height);
  m_compute = raster == BallsRaster::Compute;
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
