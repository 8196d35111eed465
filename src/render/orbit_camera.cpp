#include "render/orbit_camera.h"

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>

namespace tidepool {

void visit(ParamVisitor& v, OrbitCameraParams& p) {
  v.vector({"target", "Target", "world point the camera orbits"}, p.target, -100.0f, 100.0f);
  v.real({"distance", "Distance", "world units from the target"}, p.distance, 0.05f, 100.0f);
  v.real({"yaw", "Yaw", "radians around z"}, p.yaw, -6.2832f, 6.2832f);
  v.real({"pitch", "Pitch", "radians above the horizon"}, p.pitch, -1.55f, 1.55f);
  v.real({"fov", "Field of view", "vertical, degrees"}, p.fovDegrees, 10.0f, 120.0f);
}

void OrbitCamera::fit(glm::vec3 centre, float radius) {
  m_centre = centre;
  m_radius = std::max(radius, 1e-3f);
}

void OrbitCamera::handle(const Input& in) {
  const float scale = 1.0f / float(std::max(in.viewport.y, 1));
  if (in.left) {
    m_params.yaw -= 3.0f * in.cursorDelta.x * scale;
    m_params.pitch = std::clamp(m_params.pitch + 3.0f * in.cursorDelta.y * scale, -1.55f, 1.55f);
  }
  if (in.right) {
    const glm::mat4 v = view();
    const glm::vec3 right(v[0][0], v[1][0], v[2][0]), up(v[0][1], v[1][1], v[2][1]);
    const float k = m_params.distance * scale;
    m_params.target += (-in.cursorDelta.x * right + in.cursorDelta.y * up) * k;
  }
  if (in.scroll != 0.0f) m_params.distance = std::clamp(m_params.distance * std::pow(0.9f, in.scroll), 0.05f, 100.0f);
}

glm::vec3 OrbitCamera::eye() const {
  const float c = std::cos(m_params.pitch);
  return m_params.target + m_params.distance * glm::vec3(c * std::cos(m_params.yaw), c * std::sin(m_params.yaw),
                                                         std::sin(m_params.pitch));
}

glm::mat4 OrbitCamera::view() const { return glm::lookAt(eye(), m_params.target, glm::vec3(0, 0, 1)); }

glm::mat4 OrbitCamera::projection(float aspect) const {
  // Near/far from the bounding sphere as seen from the eye, with margin; near never below 1e-3 of far.
  const float d = glm::length(eye() - m_centre);
  const float far = d + 1.5f * m_radius;
  const float near = std::max(d - 1.5f * m_radius, far * 1e-3f);
  return glm::perspective(glm::radians(m_params.fovDegrees), aspect, near, far);
}

}  // namespace tidepool

namespace tidepool {

glm::vec3 OrbitCamera::rayDirection(glm::vec2 pixel, glm::ivec2 viewport) const {
  const float aspect = float(viewport.x) / float(std::max(viewport.y, 1));
  const glm::mat4 inv = glm::inverse(projection(aspect) * view());
  const glm::vec2 ndc(2.0f * pixel.x / float(viewport.x) - 1.0f, 1.0f - 2.0f * pixel.y / float(viewport.y));
  const glm::vec4 far = inv * glm::vec4(ndc, 1.0f, 1.0f);
  return glm::normalize(glm::vec3(far) / far.w - eye());
}

}  // namespace tidepool
