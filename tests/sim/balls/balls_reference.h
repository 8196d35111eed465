// CPU reference of one balls step: every pair by brute force, double precision, the same laws as
// shaders/balls/contact.glsl and walls.glsl, and optionally fixed particles that move (obstacles:
// immovable, mass ratio 1, their own velocity). The oracle for the GPU step.
#pragma once

#include <cmath>
#include <glm/glm.hpp>
#include <vector>

#include "sim/balls/balls_params.h"

namespace tidepool::balls::reference {

using dvec3 = glm::dvec3;

struct State {
  std::vector<dvec3> x, v;
  std::vector<double> foam;
};

struct Fixed {  // an obstacle particle: where it is and how fast it moves
  dvec3 x, v;
};

inline dvec3 contactAccel(const Params& p, dvec3 n, double overlap, dvec3 relVel, double massRatio, double share) {
  switch (p.contact) {
    case Contact::Penalty: return double(p.penaltyFactor) * share * overlap / p.dt * n;
    case Contact::CudaSample: {
      const dvec3 tangential = relVel - glm::dot(relVel, n) * n;
      return (double(p.cudaSpring) * overlap * n - double(p.cudaDamping) * relVel - double(p.cudaShear) * tangential) /
             double(p.dt);
    }
    case Contact::SpringDashpot: break;
  }
  const double le = std::log(double(p.restitution));
  const double k1 = (M_PI * M_PI + le * le) / (double(p.contactTime) * p.contactTime);
  const double g1 = -2.0 * le / p.contactTime;
  const double vn = glm::dot(relVel, n);
  const double normal = massRatio * (k1 * overlap - g1 * vn);
  dvec3 a = normal * n;
  if (p.friction > 0) {
    const dvec3 vt = relVel - vn * n;
    const double speed = glm::length(vt);
    if (speed > 1e-12) a -= std::min(p.friction * std::abs(normal), massRatio * g1 * speed) * (vt / speed);
  }
  return a;
}

inline dvec3 wallAccel(const Params& p, dvec3 n, double overlap, dvec3 relVel) {
  if (p.contact == Contact::Penalty) return 2.0 * overlap / p.dt * n;
  if (p.contact == Contact::CudaSample) return dvec3(0.0);
  return contactAccel(p, n, overlap, relVel, 1.0, 1.0);
}

// One symplectic- or explicit-Euler step with fixed walls at the domain bounds.
inline void step(State& s, const Params& p, const std::vector<Fixed>& fixed = {}) {
  const double r = p.radius, dt = p.dt, reach = 2 * r;
  const std::size_t n = s.x.size();
  std::vector<dvec3> a(n, dvec3(p.gravity));
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      if (i == j) continue;
      const dvec3 d = s.x[i] - s.x[j];
      const double dist = glm::length(d);
      if (dist >= reach || dist == 0.0) continue;
      a[i] += contactAccel(p, d / dist, reach - dist, s.v[i] - s.v[j], 0.5, 0.5);
    }
    for (const Fixed& f : fixed) {
      const dvec3 d = s.x[i] - f.x;
      const double dist = glm::length(d);
      if (dist >= reach || dist == 0.0) continue;
      a[i] += contactAccel(p, d / dist, reach - dist, s.v[i] - f.v, 1.0, 1.0);
    }
    for (int k = 0; k < 3; ++k) {
      dvec3 axis(0.0);
      axis[k] = 1.0;
      const double below = p.domainMin[k] + r - s.x[i][k];
      if (below > 0) a[i] += wallAccel(p, axis, below, s.v[i]);
      const double above = s.x[i][k] - (p.domainMax[k] - r);
      if (above > 0) a[i] += wallAccel(p, -axis, above, s.v[i]);
    }
  }
  const double decay = std::exp(-double(p.damping) * dt);
  for (std::size_t i = 0; i < n; ++i) {
    dvec3 x = s.x[i], v = s.v[i];
    if (p.integrator == Integrator::ExplicitEuler) {
      x += dt * v;
      v = (v + dt * a[i]) * decay;
    } else {
      v = (v + dt * a[i]) * decay;
      x += dt * v;
    }
    if (p.contact == Contact::CudaSample)
      for (int k = 0; k < 3; ++k) {
        if (x[k] > p.domainMax[k] - r) {
          x[k] = p.domainMax[k] - r;
          v[k] *= p.cudaBoundaryDamping;
        }
        if (x[k] < p.domainMin[k] + r) {
          x[k] = p.domainMin[k] + r;
          v[k] *= p.cudaBoundaryDamping;
        }
      }
    s.x[i] = glm::clamp(x, dvec3(p.domainMin), dvec3(p.domainMax));
    s.v[i] = v;
  }
}

}  // namespace tidepool::balls::reference
