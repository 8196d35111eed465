// Attractors of the swarm model: the seed's animated presets, in world units (x spans
// [-aspect, aspect], y spans [-1, 1]) at simulated time t. Double precision so that the CPU
// reference integrators in the tests use exactly the same positions as the GPU (rounded once).
//
//   orbit:   s = 7 at (0,0); s = 5 at 0.4 (cos t, sin t); s = 6 at 0.8 (cos -0.9t, sin -0.9t)
//   sines:   s = 7 at 0.7 (cos t, sin 2t); s = 7 at 0.7 (cos 1.8(t+0.5), sin 0.9(t+0.5))
//   central: s = +5 (attractive) or -5 (repulsive) at the origin
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "sim/swarm/swarm_params.h"

namespace tidepool::sim {

struct Attractor {
  glm::dvec2 pos{0.0};    // world units
  double strength = 0.0;  // world units^2 / s^2: a circular orbit around it has speed sqrt(strength)
};

std::vector<Attractor> presetAttractors(Preset preset, double t);

// Acceleration at world position x: gravity (downwards) + sum_k s_k d_k / (|d_k|^2 + eps).
glm::dvec2 swarmForce(glm::dvec2 x, const std::vector<Attractor>& attractors, double gravity, double epsilon);

}  // namespace tidepool::sim
