// Orbit camera for 3D views: drag to rotate, wheel to zoom, right-drag to pan. z is up.
// Near and far planes are fitted to a bounding sphere of the scene, so depth precision follows
// the content instead of hand-tuned constants.
#pragma once

#include <array>
#include <glm/glm.hpp>

#include "base/input.h"
#include "base/param.h"

namespace tidepool {

// Perspective: rays from the eye, fovDegrees wide. Orthographic: parallel rays along the view
// direction, the picture as wide as the perspective one at the target's distance (half height
// distance · tan(fov / 2); water-webgpu's 2.5 / zoom is its distance 10 / zoom times tan 15°).
enum class Projection { Perspective, Orthographic };
inline constexpr std::array<const char*, 2> kProjectionNames = {"perspective", "orthographic"};

struct OrbitCameraParams {
  glm::vec3 target{0.5f, 0.5f, 0.15f};  // world point the camera orbits
  float distance = 1.6f;                // from the target, world units
  float yaw = -0.785f;                  // radians around z
  float pitch = 0.62f;                  // radians above the horizon
  float fovDegrees = 45.0f;             // vertical
  Projection projection = Projection::Perspective;
};
void visit(ParamVisitor& v, OrbitCameraParams& p);

class OrbitCamera {
 public:
  OrbitCameraParams& params() { return m_params; }
  const OrbitCameraParams& params() const { return m_params; }
  void fit(glm::vec3 centre, float radius);  // bounding sphere for near/far
  void handle(const Input& in);              // left drag rotates, right drag pans, wheel zooms
  // Perspective: distance from the target. Orthographic: backed off, if need be, to keep the
  // whole bounding sphere in front of the eye (near > 0).
  float eyeDistance() const;
  glm::vec3 eye() const;
  glm::vec3 viewDirection() const { return glm::normalize(m_params.target - eye()); }  // world, unit
  glm::mat4 view() const;
  // glm::perspective or glm::ortho; near and far fitted to the bounding sphere (orthographic:
  // its whole depth).
  glm::mat4 projection(float aspect) const;
  // World-space ray through a pixel (origin top-left): from the eye (perspective) or from the
  // pixel's point on the eye's plane (orthographic: every ray along the view direction).
  glm::vec3 rayOrigin(glm::vec2 pixel, glm::ivec2 viewport) const;
  glm::vec3 rayDirection(glm::vec2 pixel, glm::ivec2 viewport) const;  // unit

 private:
  OrbitCameraParams m_params;
  glm::vec3 m_centre{0.5f};
  float m_radius = 1.0f;
};

}  // namespace tidepool
