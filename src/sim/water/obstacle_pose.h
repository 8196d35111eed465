// Where an obstacle is at time t: a rigid motion of its particles from their own frame (built
// centred on the origin, unturned) into the world, evaluated from t each step (never integrated,
// so the shape cannot drift), with the velocity field of that motion for the contact laws:
//   x(t) = c(t) + R(t)·x_body,   R(t) = Rot(spin axis, spin·t) · R(orientation)
//   v(x) = c'(t) + ω × (x − c(t)),  ω = spin · axis,  c(t) = centre + path offset (setup.h)
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "sim/water/setup.h"

namespace tidepool::water {

struct ObstaclePose {
  glm::mat3 rotation{1.0f};  // own frame -> world
  glm::vec3 centre{0.0f};    // where the own frame's origin is, m
  glm::vec3 velocity{0.0f};  // of the centre, m/s
  glm::vec3 omega{0.0f};     // angular velocity, rad/s

  glm::vec3 place(glm::vec3 body) const { return centre + rotation * body; }
  glm::vec3 toBody(glm::vec3 world) const { return glm::transpose(rotation) * (world - centre); }
  glm::vec3 velocityAt(glm::vec3 world) const { return velocity + glm::cross(omega, world - centre); }
  glm::mat4 matrix() const;  // place() as a 4x4 matrix
  bool operator==(const ObstaclePose&) const = default;
};

ObstaclePose obstaclePose(const ObstacleParams& o, double time);
std::vector<ObstaclePose> posesAt(const std::vector<ObstacleParams>& obstacles, double time);  // each one's

glm::mat3 orientationMatrix(glm::vec3 degrees);  // about x, then y, then z

}  // namespace tidepool::water
