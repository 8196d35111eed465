#include "sim/swarm/attractors.h"

#include <cmath>

namespace tidepool::sim {

std::vector<Attractor> presetAttractors(Preset preset, double t) {
  auto polar = [](double radius, double x, double y) { return glm::dvec2(radius * std::cos(x), radius * std::sin(y)); };
  switch (preset) {
    case Preset::None: return {};
    case Preset::Orbit: return {{{0.0, 0.0}, 7.0}, {polar(0.4, t, t), 5.0}, {polar(0.8, -0.9 * t, -0.9 * t), 6.0}};
    case Preset::Sines: return {{polar(0.7, t, 2.0 * t), 7.0}, {polar(0.7, 1.8 * (t + 0.5), 0.9 * (t + 0.5)), 7.0}};
    case Preset::CentralAttractive: return {{{0.0, 0.0}, 5.0}};
    case Preset::CentralRepulsive: return {{{0.0, 0.0}, -5.0}};
  }
  return {};
}

glm::dvec2 swarmForce(glm::dvec2 x, const std::vector<Attractor>& attractors, double gravity, double epsilon) {
  glm::dvec2 f(0.0, -gravity);
  for (const Attractor& a : attractors) {
    const glm::dvec2 d = a.pos - x;
    f += a.strength * d / (glm::dot(d, d) + epsilon);
  }
  return f;
}

}  // namespace tidepool::sim
