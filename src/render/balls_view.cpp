#include "render/balls_view.h"

#include <glm/gtc/matrix_transform.hpp>

namespace tidepool {

void visit(ParamVisitor& v, BallsViewParams& p) {
  v.color({"water_color", "Water colour", "linear RGB"}, p.waterColor);
  v.color({"obstacle_color", "Obstacle colour", "linear RGB"}, p.obstacleColor);
  v.color({"background", "Background", "linear RGB"}, p.background);
  v.flag({"show_box", "Show box", "domain wireframe"}, p.showBox);
  v.flag({"show_obstacle", "Show obstacle", "a mesh obstacle's triangles, the others' fixed particles"},
         p.showObstacle);
  v.flag({"obstacle_balls", "Mesh obstacle balls", "a mesh obstacle's fixed particles too"}, p.obstacleBalls);
}

BallsView::BallsView(gl::ShaderLibrary& shaders) : m_shaders(shaders) {}

glm::mat4 BallsView::domainModel(const balls::Balls& model) const {
  // The box turns on screen while gravity stays pointing down (water-webgpu's domain rotation).
  const balls::Params& p = model.params();
  const glm::vec3 centre = 0.5f * (p.domainMin + p.domainMax);
  glm::mat4 m = glm::translate(glm::mat4(1.0f), centre);
  m = glm::rotate(m, -model.domainRotation(), glm::vec3(1, 0, 0));
  return glm::translate(m, -centre);
}

void BallsView::uploadMesh(const balls::Balls& model) {
  const io::TriangleMesh* mesh = model.obstacleMesh();
  if (m_meshVersion == model.obstacleVersion() && m_meshSource == mesh) return;
  m_meshVersion = model.obstacleVersion();
  m_meshSource = mesh;
  m_meshCorners = 0;
  if (!mesh) return;
  std::vector<glm::vec4> corners;
  corners.reserve(3 * mesh->triangles.size());
  for (const glm::uvec3& t : mesh->triangles)
    for (int k = 0; k < 3; ++k) corners.emplace_back(mesh->vertices[t[k]], 1.0f);
  m_meshVertices = gl::Buffer(corners.size() * sizeof(glm::vec4), corners.data(), GL_STATIC_DRAW);
  m_meshCorners = GLsizei(corners.size());
}

void BallsView::render(const balls::Balls& model, RenderTarget& target, gl::GpuProfiler& profiler) {
  auto scope = profiler.scope("balls.view");
  const balls::Params& p = model.params();
  const glm::vec3 centre = 0.5f * (p.domainMin + p.domainMax);
  m_camera.fit(centre, 0.5f * glm::length(p.domainMax - p.domainMin));
  const glm::mat4 view = m_camera.view();
  const glm::mat4 proj = m_camera.projection(float(target.width()) / float(target.height()));
  const glm::mat4 world = domainModel(model);
  target.bind();
  glClearColor(m_params.background.r, m_params.background.g, m_params.background.b, 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_BLEND);
  m_vao.bind();
  gl::Program& balls = m_shaders.program({"render/balls_impostor.vert", "render/balls_impostor.frag"});
  balls.use();
  balls.set("uView", view);
  balls.set("uProj", proj);
  balls.set("uRadius", model.radius());
  balls.set("uLightView", glm::normalize(glm::vec3(view * glm::vec4(0.5f, 0.3f, 1.0f, 0.0f))));
  if (model.count() > 0) {
    balls.set("uModel", world);
    balls.set("uColor", m_params.waterColor);
    balls.set("uHasVelocity", 1);
    model.positions().bindBase(GL_SHADER_STORAGE_BUFFER, 0);
    model.velocities().bindBase(GL_SHADER_STORAGE_BUFFER, 1);
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(6 * model.count()));
  }
  // Obstacle frame -> simulation: spin about the vertical axis through its centre.
  glm::mat4 spin = glm::translate(glm::mat4(1.0f), p.obstacleCentre);
  spin = glm::rotate(spin, model.obstacleAngle(), glm::vec3(0, 0, 1));
  spin = glm::translate(spin, -p.obstacleCentre);
  uploadMesh(model);
  const bool mesh = model.obstacleMesh() && m_meshCorners > 0;
  if (m_params.showObstacle && model.obstacleCount() > 0 && (!mesh || m_params.obstacleBalls)) {
    balls.set("uModel", world * spin);
    balls.set("uColor", m_params.obstacleColor);
    balls.set("uHasVelocity", 0);
    model.obstaclePositions().bindBase(GL_SHADER_STORAGE_BUFFER, 0);
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(6 * model.obstacleCount()));
  }
  if (m_params.showObstacle && mesh) {
    gl::Program& flat = m_shaders.program({"render/obstacle_mesh.vert", "render/obstacle_mesh.frag"});
    flat.use();
    flat.set("uModel", world * spin);
    flat.set("uView", view);
    flat.set("uProj", proj);
    flat.set("uColor", m_params.obstacleColor);
    flat.set("uLightView", glm::normalize(glm::vec3(view * glm::vec4(0.5f, 0.3f, 1.0f, 0.0f))));
    m_meshVertices.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
    glDrawArrays(GL_TRIANGLES, 0, m_meshCorners);
  }
  if (m_params.showBox) {
    gl::Program& lines = m_shaders.program({"render/box_lines.vert", "render/flat_color.frag"});
    lines.use();
    lines.set("uMin", model.wallMin());
    lines.set("uMax", model.wallMax());
    lines.set("uViewProjModel", proj * view * world);
    lines.set("uColor", glm::vec4(0.7f, 0.72f, 0.75f, 1.0f));
    glDrawArrays(GL_LINES, 0, 24);
  }
  glDisable(GL_DEPTH_TEST);
  glBindVertexArray(0);
}

}  // namespace tidepool
