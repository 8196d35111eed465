#include "sim/swarm/measure/swarm_measure.h"

#include <cmath>
#include <numbers>

#include "sim/measure/bisect.h"
#include "sim/swarm/swarm.h"

namespace tidepool::sim {
namespace {
constexpr double kStrength = 1.0, kRadius = 0.5;
constexpr int kRing = 64;

double energy(glm::dvec2 x, glm::dvec2 v) { return 0.5 * glm::dot(v, v) - kStrength * std::log(glm::length(x)); }

// The oscillator in the core of a softened attractor.
constexpr double kCoreStrength = 1.0, kCoreEpsilon = 0.01;
constexpr int kOscillators = 8;

SwarmParams freeParticles(Integrator integrator, double epsilon, int count) {
  SwarmParams params;
  params.integrator = integrator;
  params.preset = Preset::None;
  params.gravity = 0.0f;
  params.friction = 0.0f;
  params.epsilon = float(epsilon);
  params.bounce = false;
  params.particles = count;
  return params;
}
}  // namespace

double orbitPeriod() { return 2.0 * std::numbers::pi * kRadius / std::sqrt(kStrength); }

double orbitEnergyError(gl::ShaderLibrary& shaders, Integrator integrator, Storage storage, int stepsPerOrbit,
                        int orbits) {
  SwarmParams params = freeParticles(integrator, 0.0, kRing);
  params.storage = storage;
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

double oscillatorOmega() { return std::sqrt(kCoreStrength / kCoreEpsilon); }

double oscillatorGrowth(gl::ShaderLibrary& shaders, Integrator integrator, double omegaDt, int periods) {
  const double omega = oscillatorOmega(), amplitude = 1e-3 * std::sqrt(kCoreEpsilon);
  std::vector<SwarmParticle> start;
  for (int k = 0; k < kOscillators; ++k) {
    const double direction = 2.0 * std::numbers::pi * (k + 0.25) / kOscillators;
    const double phase = 2.0 * std::numbers::pi * k / kOscillators;
    const glm::dvec2 dir(std::cos(direction), std::sin(direction));
    start.push_back(
        {glm::vec2(amplitude * std::cos(phase) * dir), glm::vec2(-amplitude * omega * std::sin(phase) * dir)});
  }
  Swarm swarm(shaders, freeParticles(integrator, kCoreEpsilon, kOscillators));
  swarm.setAspect(1.0);
  swarm.setExtraAttractors({{{0.0, 0.0}, kCoreStrength}});
  swarm.upload(start);
  const double dt = omegaDt / omega;
  const int steps = int(std::ceil(periods * 2.0 * std::numbers::pi / omegaDt));
  double worst = 0;
  for (int n = 0; n < steps; ++n) {
    swarm.step(dt);
    for (const SwarmParticle& p : swarm.download()) {
      const double growth = glm::length(glm::dvec2(p.pos)) / amplitude;
      if (!std::isfinite(growth) || growth > kOscillatorGrowthBound) return INFINITY;
      worst = std::max(worst, growth);
    }
  }
  return worst;
}

double oscillatorStableLimit(gl::ShaderLibrary& shaders, Integrator integrator, double tolerance) {
  auto stable = [&](double omegaDt) {
    return oscillatorGrowth(shaders, integrator, omegaDt, kOscillatorPeriods) < kOscillatorGrowthBound;
  };
  return largestStable(0.5, 4.0, tolerance, stable);
}

}  // namespace tidepool::sim
