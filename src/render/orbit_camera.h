// Orbit camera for 3D views: drag to rotate, wheel to zoom, right-drag to pan. z is up.
// Near and far planes are fitted to a bounding sphere of the scene, so depth precision follows
// the content instead of hand-tuned constants.
#pragma once

#include <glm/glm.hpp>

#include "base/input.h"
#include "base/param.h"

namespace tidepool {

struct OrbitCameraParams {
  glm::vec3 target{0.5f, 0.5f, 0.15f};  // world point the camera orbits
  float distance = 1.6f;                // from the target, world units
  float yaw = -0.785f;                  // radians around z
  float pitch = 0.62f;                  // radians above the horizon
  float fovDegrees = 45.0f;             // vertical
};
void visit(ParamVisitor& v, OrbitCameraParams& p);

class OrbitCamera {
 public:
  OrbitCameraParams& params() { return m_params; }
  const OrbitCameraParams& params() const { return m_params; }
  void fit(glm::vec3 centre, float radius);  // bounding sphere for near/far
  void handle(const Input& in);              // left drag rotates, right drag pans, wheel zooms
  glm::vec3 eye() const;
  glm::mat4 view() const;
  glm::mat4 projection(float aspect) const;
  // World-space direction of the ray from the eye through a pixel (origin top-left).
  glm::vec3 rayDirection(glm::vec2 pixel, glm::ivec2 viewport) const;

 private:
  OrbitCameraParams m_params;
  glm::vec3 m_centre{0.5f};
  float m_radius = 1.0f;
};

}  // namespace tidepool
