// Particle life on the CPU in double precision: the plain statement of the force pass
// (shaders/life/forces.comp, through a cell list) and of the symplectic Euler step
// (shaders/life/integrate.comp). The reference of the life-precision study and of the fp16 test;
// the O(N^2) brute force of tests/reference/life_reference.h checks it in turn.
//
//   std::vector<CpuParticle> s = cpuState(model.downloadPositions(), model.downloadVelocities());
//   for (int k = 0; k < 40; ++k) cpuStepEuler(rules, s, 0.025);
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "sim/life/life_rules.h"

namespace tidepool::life {

struct CpuParticle {
  glm::dvec2 pos{0.0};  // world units, inside the box
  glm::dvec2 vel{0.0};  // world units / s
  int species = 0;
};

struct CpuForce {
  glm::dvec2 accel{0.0};  // force per unit mass
  double scale = 0;       // sum of |contributions|: what float rounding of the sum is relative to
};

// positions (x, y, 0, species) and velocities (vx, vy, ...) as Life::download*() gives them.
std::vector<CpuParticle> cpuState(const std::vector<glm::vec4>& positions, const std::vector<glm::vec4>& velocities);

// The force on every particle (central force included), split over the machine's cores.
std::vector<CpuForce> cpuForces(const Rules& rules, const std::vector<CpuParticle>& particles);

// One step of the article's symplectic Euler, no brush:
//   v = (v + a·dt)·exp(-friction·dt); p += v·dt; then wrap (looping) or clamp and reflect (walls).
void cpuStepEuler(const Rules& rules, std::vector<CpuParticle>& particles, double dt);

// Shortest vector from a to b: the minimum image on the torus when the rules loop.
glm::dvec2 cpuBoxDelta(const Rules& rules, glm::dvec2 a, glm::dvec2 b);

}  // namespace tidepool::life
