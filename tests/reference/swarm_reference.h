// CPU reference of the swarm step in double precision: plain loops over particles, the same
// force law, presets, integrators, friction and walls as shaders/swarm/swarm_step.comp. It is
// the oracle the GPU is compared against, and the shortest description of the method.
#pragma once

#include <vector>

#include "sim/swarm/attractors.h"
#include "sim/swarm/swarm.h"

namespace tidepool::test {

struct RefParticle {
  glm::dvec2 pos;  // NDC
  glm::dvec2 vel;  // world units / s
};

struct SwarmReference {
  sim::SwarmParams params;            // integrator, gravity, friction, epsilon, bounce, preset
  double aspect = 1.0;                // world = ndc * (aspect, 1)
  std::vector<sim::Attractor> extra;  // fixed attractors after the preset's
  std::vector<RefParticle> particles;
  double time = 0.0;

  std::vector<sim::Attractor> attractorsAt(double t) const;
  void step(double dt);  // one integrator step of every particle
};

std::vector<RefParticle> toReference(const std::vector<sim::SwarmParticle>& gpu);

// Orbits about one attractor of strength s at the origin, with aspect 1 (NDC = world units):
sim::SwarmParams freeFlight();  // no preset, gravity, friction, softening (ε = 0) or walls
// `count` particles on the circular orbit of radius r (speed √s, counter-clockwise), at evenly
// spaced phases from 0.
std::vector<sim::SwarmParticle> orbitRing(int count, double radius, double strength);
void placeOrbit(sim::Swarm& swarm, const std::vector<sim::SwarmParticle>& ring, double strength);

}  // namespace tidepool::test
