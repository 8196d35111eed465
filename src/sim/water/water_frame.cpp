#include "sim/water/water_frame.h"

#include <cmath>

namespace tidepool::water {
namespace {
constexpr float kPi = 3.14159265358979f;
}

Walls wallsAt(const Setup& p, double time) {
  Walls w{p.domainMin, p.domainMax, glm::vec3(0.0f), glm::vec3(0.0f)};
  if (p.pistonAxis >= 1 && p.pistonAxis <= 3) {
    const int k = p.pistonAxis - 1;
    const float extent = p.domainMax[k] - p.domainMin[k], omega = 2.0f * kPi / p.pistonPeriod;
    const float t = float(time);
    w.max[k] = p.domainMax[k] - p.pistonTravel * extent * 0.5f * (1.0f - std::cos(omega * t));
    w.maxVel[k] = -p.pistonTravel * extent * 0.5f * omega * std::sin(omega * t);
  }
  // The static contraction, below the piston (if any) on z; 1 leaves the walls bit for bit as they were.
  const float contracted = p.domainMin.z + p.contraction * (p.domainMax.z - p.domainMin.z);
  if (p.contraction < 1.0f && contracted < w.max.z) {
    w.max.z = contracted;
    w.maxVel.z = 0.0f;
  }
  return w;
}

float domainRotation(const Setup& p, double time) { return (p.rotation + p.rotationRate * float(time)) * kPi / 180.0f; }

glm::vec3 gravityAt(const Setup& p, double time) {
  const float a = domainRotation(p, time);
  const glm::vec3 g = p.gravity;
  return {g.x, std::cos(a) * g.y - std::sin(a) * g.z, std::sin(a) * g.y + std::cos(a) * g.z};
}

TapLayer tapLayer(const Setup& p, float radius, std::size_t room) {
  TapLayer layer;
  const glm::vec3 dir = glm::length(p.tapDirection) > 0 ? glm::normalize(p.tapDirection) : glm::vec3(0, 0, 1);
  const glm::vec3 u = glm::normalize(std::abs(dir.z) < 0.9f ? glm::cross(dir, glm::vec3(0, 0, 1))
                                                            : glm::cross(dir, glm::vec3(1, 0, 0)));
  const glm::vec3 w = glm::cross(dir, u);
  const float s = 2.0f * radius * 1.02f;
  const int n = int(std::ceil(p.tapRadius / s));
  for (int j = -n; j <= n; ++j)
    for (int i = -n; i <= n; ++i) {
      const glm::vec2 q((float(i) + 0.5f * float(j & 1)) * s, float(j) * s * 0.8660254f);
      if (glm::length(q) > p.tapRadius + 1e-6f) continue;
      if (layer.pos.size() >= room) break;
      layer.pos.emplace_back(p.tapPosition + q.x * u + q.y * w, 1.0f);
      layer.vel.emplace_back(p.tapSpeed * dir, 0.0f);
    }
  layer.interval = s * 0.8165 / p.tapSpeed;  // HCP layer spacing 2r·√(2/3)
  return layer;
}

}  // namespace tidepool::water
