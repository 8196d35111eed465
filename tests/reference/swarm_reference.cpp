#include "reference/swarm_reference.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tidepool::test {

std::vector<sim::Attractor> SwarmReference::attractorsAt(double t) const {
  std::vector<sim::Attractor> all = sim::presetAttractors(params.preset, t);
  all.insert(all.end(), extra.begin(), extra.end());
  return all;
}

void SwarmReference::step(double h) {
  const std::vector<sim::Attractor> a0 = attractorsAt(time), aHalf = attractorsAt(time + 0.5 * h),
                                    a1 = attractorsAt(time + h);
  const double g = params.gravity, eps = params.epsilon;
  auto force = [&](glm::dvec2 x, const std::vector<sim::Attractor>& a) { return sim::swarmForce(x, a, g, eps); };
  const glm::dvec2 toWorld(aspect, 1.0);
  const double damping = std::exp(-double(params.friction) * h);

  for (RefParticle& p : particles) {
    glm::dvec2 x = p.pos * toWorld, v = p.vel;
    switch (params.integrator) {
      case sim::Integrator::ExplicitEuler: {
        const glm::dvec2 acc = force(x, a0);
        x += h * v;
        v += h * acc;
        break;
      }
      case sim::Integrator::SymplecticEuler:
        v += h * force(x, a0);
        x += h * v;
        break;
      case sim::Integrator::Verlet: {
        const glm::dvec2 vHalf = v + 0.5 * h * force(x, a0);
        x += h * vHalf;
        v = vHalf + 0.5 * h * force(x, a1);
        break;
      }
      case sim::Integrator::Rk4: {
        const glm::dvec2 k1x = v, k1v = force(x, a0);
        const glm::dvec2 k2x = v + 0.5 * h * k1v, k2v = force(x + 0.5 * h * k1x, aHalf);
        const glm::dvec2 k3x = v + 0.5 * h * k2v, k3v = force(x + 0.5 * h * k2x, aHalf);
        const glm::dvec2 k4x = v + h * k3v, k4v = force(x + h * k3x, a1);
        x += (h / 6.0) * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
        v += (h / 6.0) * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
        break;
      }
    }
    v *= damping;
    p.pos = x / toWorld;
    p.vel = v;
    if (params.bounce) {
      for (int axis = 0; axis < 2; ++axis) {
        if (p.pos[axis] < -1.0) p.pos[axis] = -2.0 - p.pos[axis], p.vel[axis] = -p.vel[axis];
        if (p.pos[axis] > 1.0) p.pos[axis] = 2.0 - p.pos[axis], p.vel[axis] = -p.vel[axis];
        p.pos[axis] = std::clamp(p.pos[axis], -1.0, 1.0);
      }
    }
  }
  time += h;
}

std::vector<RefParticle> toReference(const std::vector<sim::SwarmParticle>& gpu) {
  std::vector<RefParticle> out;
  for (const sim::SwarmParticle& p : gpu) out.push_back({glm::dvec2(p.pos), glm::dvec2(p.vel)});
  return out;
}

sim::SwarmParams freeFlight() {
  sim::SwarmParams p;
  p.preset = sim::Preset::None;
  p.gravity = 0.0f;
  p.friction = 0.0f;
  p.epsilon = 0.0f;
  p.bounce = false;
  return p;
}

std::vector<sim::SwarmParticle> orbitRing(int count, double radius, double strength) {
  std::vector<sim::SwarmParticle> ring;
  for (int k = 0; k < count; ++k) {
    const double a = 2.0 * std::numbers::pi * k / count;
    const glm::dvec2 dir(std::cos(a), std::sin(a));
    ring.push_back({glm::vec2(radius * dir), glm::vec2(std::sqrt(strength) * glm::dvec2(-dir.y, dir.x))});
  }
  return ring;
}

void placeOrbit(sim::Swarm& swarm, const std::vector<sim::SwarmParticle>& ring, double strength) {
  swarm.setAspect(1.0);
  swarm.setExtraAttractors({{{0.0, 0.0}, strength}});
  swarm.upload(ring);
}

}  // namespace tidepool::test
