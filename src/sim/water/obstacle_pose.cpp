#include "sim/water/obstacle_pose.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace tidepool::water {
namespace {
constexpr double kTwoPi = 6.283185307179586;
}  // namespace

glm::mat3 orientationMatrix(glm::vec3 degrees) {
  const glm::vec3 a = glm::radians(degrees);
  glm::mat4 m = glm::rotate(glm::mat4(1.0f), a.z, glm::vec3(0, 0, 1));
  m = glm::rotate(m, a.y, glm::vec3(0, 1, 0));
  return glm::mat3(glm::rotate(m, a.x, glm::vec3(1, 0, 0)));
}

glm::mat4 ObstaclePose::matrix() const {
  glm::mat4 m(rotation);
  m[3] = glm::vec4(centre, 1.0f);
  return m;
}

ObstaclePose obstaclePose(const ObstacleParams& o, double time) {
  ObstaclePose pose;
  pose.rotation = orientationMatrix(o.orientation);
  pose.centre = o.centre;
  if (o.dynamic) return pose;  // at rest where it starts: bodies.h moves it
  const float axisLength = glm::length(o.spinAxis);
  if (o.spin != 0.0f && axisLength > 0.0f) {
    const glm::vec3 axis = o.spinAxis / axisLength;
    // The angle in double, reduced to one turn, so late times keep full float precision.
    const float angle = float(std::fmod(double(o.spin) * time, kTwoPi));
    pose.rotation = glm::mat3(glm::rotate(glm::mat4(1.0f), angle, axis)) * pose.rotation;
    pose.omega = o.spin * axis;
  }
  if (o.path.kind != PathKind::None) {
    const double w = kTwoPi / double(o.path.period);
    const double theta = std::fmod(w * time, kTwoPi) + double(o.path.phase) * kTwoPi / 360.0;
    const float s = float(std::sin(theta)), c = float(std::cos(theta)), fw = float(w);
    const glm::vec3 a = o.path.amplitude;
    if (o.path.kind == PathKind::Oscillate) {
      pose.centre += a * s;
      pose.velocity = a * (fw * c);
    } else {
      pose.centre += glm::vec3(a.x * c, a.y * s, a.z * s);
      pose.velocity = fw * glm::vec3(-a.x * s, a.y * c, a.z * c);
    }
  }
  return pose;
}

std::vector<ObstaclePose> posesAt(const std::vector<ObstacleParams>& obstacles, double time) {
  std::vector<ObstaclePose> out;
  out.reserve(obstacles.size());
  for (const ObstacleParams& o : obstacles) out.push_back(obstaclePose(o, time));
  return out;
}

}  // namespace tidepool::water
