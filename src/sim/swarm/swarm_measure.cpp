#include "sim/swarm/swarm_measure.h"

#include <cmath>
#include <numbers>

#include "sim/swarm/swarm.h"

namespace tidepool::sim {
namespace {
constexpr double kStrength = 1.0, kRadius = 0.5;
constexpr int kRing = 64;

double energy(glm::dvec2 x, glm::dvec2 v) { return 0.5 * glm::dot(v, v) - kStrength * std::log(glm::length(x)); }
}  // namespace

double orbitPeriod() { return 2.0 * std::numbers::pi * kRadius / std::sqrt(kStrength); }

double orbitEnergyError(gl::ShaderLibrary& shaders, Integrator integrator, Storage storage, int stepsPerOrbit,
                        int orbits) {
  SwarmParams params;
  params.integrator = integrator;
  params.storage = storage;
  params.preset = Preset::None;
  params.gravity = 0.0f;
  params.friction = 0.0f;
  params.epsilon = 0.0f;
  params.bounce = false;
  params.particles = kRing;
  std::vector<SwarmParticle> start;
  for (int k = 0; k < kRing; ++k) {
    const double a = 2.0 * std::numbers::pi * k / kRing;
    const glm::dvec2 dir(std::cos(a), std::sin(a));
    start.push_back({glm::vec2(kRadius * dir), glm::vec2(std::sqrt(kStrength) * glm::dvec2(-dir.y, dir.x))});
  }
  Swarm swarm(shaders, params);
  swarm.setAspect(1.0);
  swarm.setExtraAttractors({{{0.0, 0.0}, kStrength}});
  swarm.upload(start);
  std::vector<double> e0;
  for (const SwarmParticle& p : swarm.download()) e0.push_back(energy(glm::dvec2(p.pos), glm::dvec2(p.vel)));
  const double dt = orbitPeriod() / stepsPerOrbit;
  const int sampleEvery = std::max(1, stepsPerOrbit / 50);
  double worst = 0;
  for (int n = 1; n <= stepsPerOrbit * orbits; ++n) {
    swarm.step(dt);
    if (n % sampleEvery) continue;
    const std::vector<SwarmParticle> got = swarm.download();
    for (int k = 0; k < kRing; ++k) {
      const double e = energy(glm::dvec2(got[k].pos), glm::dvec2(got[k].vel));
      worst = std::max(worst, std::isfinite(e) ? std::abs(e - e0[k]) / kStrength : INFINITY);
    }
  }
  return worst;
}

}  // namespace tidepool::sim
