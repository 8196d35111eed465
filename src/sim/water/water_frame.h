// What the two particle-water models (balls, and fluid in sim/fluid) share about their box and
// tap, as functions of the parameters and the time: the walls (one may be a piston), the domain's
// rotation with the gravity that follows it, and the tap's next layer of particles.
#pragma once

#include <cstddef>
#include <glm/glm.hpp>
#include <vector>

#include "sim/water/setup.h"

namespace tidepool::water {

struct Walls {
  glm::vec3 min{0.0f}, max{1.0f};        // wall positions, m
  glm::vec3 minVel{0.0f}, maxVel{0.0f};  // wall velocities (the piston), m/s
};
// The piston's max wall of its axis travels in and out: offset = travel·extent·(1 − cos(2πt/T))/2;
// the contraction holds the max z wall at min.z + contraction·height (the lower of the two wins).
Walls wallsAt(const Setup& p, double time);
float domainRotation(const Setup& p, double time);  // radians about x
glm::vec3 gravityAt(const Setup& p,
                    double time);  // p.gravity turned with the domain (p as the model runs it: balls::resolved)

// One hexagonal layer of the tap's nozzle disc (spacing 2r·1.02), at most `room` particles
// (vec4 position w = 1, velocity w = 0); `interval` is the time until the jet has moved on by the
// HCP layer spacing, when the next layer is due.
struct TapLayer {
  std::vector<glm::vec4> pos, vel;
  double interval = 0;
};
TapLayer tapLayer(const Setup& p, float radius, std::size_t room);

}  // namespace tidepool::water
