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
  v.choice({"projection", "Projection",
            "perspective, or orthographic: parallel rays, as wide as the perspective view at the target"},
           p.projection, kProjectionNames);
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

float OrbitCamera::eyeDistance() const {
  if (m_params.projection == Projection::Perspective) return m_params.distance;
  // The picture does not depend on it; the G-buffer takes view depth > 0 as "a ball here".
  return std::max(m_params.distance, glm::length(m_params.target - m_centre) + 2.0f * m_radius);
}

glm::vec3 OrbitCamera::eye() const {
  const float c = std::cos(m_params.pitch);
  return m_params.target +
         eyeDistance() * glm::vec3(c * std::cos(m_params.yaw), c * std::sin(m_params.yaw), std::sin(m_params.pitch));
}

glm::mat4 OrbitCamera::view() const { return glm::lookAt(eye(), m_params.target, glm::vec3(0, 0, 1)); }

glm::mat4 OrbitCamera::projection(float aspect) const {
  // Near/far from the bounding sphere as seen from the eye, with margin; near never below 1e-3 of far.
  const float d = glm::length(eye() - m_centre);
  const float far = d + 1.5f * m_radius;
  const float fovY = glm::radians(m_params.fovDegrees);
  if (m_params.projection == Projection::Orthographic) {
    // water-webgpu: planes at distance - 3.75 and distance + 1.1 around its unit domain.
    const float halfHeight = m_params.distance * std::tan(0.5f * fovY);
    return glm::ortho(-halfHeight * aspect, halfHeight * aspect, -halfHeight, halfHeight, d - 1.5f * m_radius, far);
  }
  const float near = std::max(d - 1.5f * m_radius, far * 1e-3f);
  return glm::perspective(fovY, aspect, near, far);
}

}  // namespace tidepool

namespace tidepool {

namespace {

// World points of a pixel on the near (z = -1) or far (z = 1) plane.
glm::vec3 unproject(const OrbitCamera& camera, glm::vec2 pixel, glm::ivec2 viewport, float ndcZ) {
  const float aspect = float(viewport.x) / float(std::max(viewport.y, 1));
  const glm::mat4 inv = glm::inverse(camera.projection(aspect) * camera.view());
  const glm::vec2 ndc(2.0f * pixel.x / float(viewport.x) - 1.0f, 1.0f - 2.0f * pixel.y / float(viewport.y));
  const glm::vec4 p = inv * glm::vec4(ndc, ndcZ, 1.0f);
  return glm::vec3(p) / p.w;
}

}  // namespace

glm::vec3 OrbitCamera::rayOrigin(glm::vec2 pixel, glm::ivec2 viewport) const {
  if (m_params.projection == Projection::Perspective) return eye();
  // On the near plane, moved along the (parallel) ray to the plane through the eye.
  const glm::vec3 dir = viewDirection();
  const glm::vec3 onNear = unproject(*this, pixel, viewport, -1.0f);
  return onNear - glm::dot(onNear - eye(), dir) * dir;
}

glm::vec3 OrbitCamera::rayDirection(glm::vec2 pixel, glm::ivec2 viewport) const {
  if (m_params.projection == Projection::Orthographic) return viewDirection();
  return glm::normalize(unproject(*this, pixel, viewport, 1.0f) - eye());
}

}  // namespace tidepool
