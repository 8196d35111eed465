// CPU reference of one balls step: every pair by brute force, double precision, the same laws as
// shaders/balls/contact.glsl and walls.glsl, and optionally fixed particles that move (obstacles:
// immovable, mass ratio 1, their own velocity). The oracle for the GPU step, with each of the
// model's integrators: explicit and symplectic Euler (collide.comp) and velocity Verlet as
// Balls::stepOnce runs it (drift.comp, then collide.comp's force and kick).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/glm.hpp>
#include <vector>

#include "sim/balls/balls_params.h"

namespace tidepool::balls::reference {

using dvec3 = glm::dvec3;

struct State {
  std::vector<dvec3> x, v;
  std::vector<double> foam;
  std::vector<dvec3> a;  // Verlet: the acceleration at (x, v) of the last step; empty before the first
};

struct Fixed {  // an obstacle particle: where it is, how fast it moves, and whose it is
  dvec3 x, v;
  std::size_t obstacle = 0;
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

// The CPU state of balls uploaded to the GPU as (positions, velocities).
inline State state(const std::vector<glm::vec4>& pos, const std::vector<glm::vec4>& vel) {
  State s;
  for (std::size_t i = 0; i < pos.size(); ++i) {
    s.x.emplace_back(glm::vec3(pos[i]));
    s.v.emplace_back(glm::vec3(vel[i]));
  }
  return s;
}

// How far the GPU's balls (k, in the GPU's cell order) are from the CPU's (index order[k]).
struct Gap {
  double position = 0;  // largest distance, m
  double velocity = 0;  // largest velocity difference over the largest CPU speed
};
inline Gap gap(const State& cpu, const std::vector<glm::vec4>& pos, const std::vector<glm::vec4>& vel,
               const std::vector<unsigned>& order) {
  double worstX = 0, worstV = 0, scaleV = 0;
  for (std::size_t k = 0; k < pos.size(); ++k) {
    const std::size_t i = order[k];
    worstX = std::max(worstX, glm::length(glm::dvec3(glm::vec3(pos[k])) - cpu.x[i]));
    worstV = std::max(worstV, glm::length(glm::dvec3(glm::vec3(vel[k])) - cpu.v[i]));
    scaleV = std::max(scaleV, glm::length(cpu.v[i]));
  }
  return {worstX, worstV / scaleV};
}

// Acceleration of every ball at the state's positions and velocities (collide.comp's sum): gravity,
// every other ball within 2r, the fixed particles and the walls at the domain bounds.
inline std::vector<dvec3> accelerations(const State& s, const Params& p, const std::vector<Fixed>& fixed) {
  const double r = p.radius, reach = 2 * r;
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
  return a;
}

// What the balls at the state push the walls and the obstacles with (balls/loads.comp): each wall's
// force along its axis and each obstacle's force and torque about centres[k], −m times the
// accelerations their contacts give the balls, the torque's lever from the centre to the contact's
// midpoint. Walls −x, +x, −y, +y, −z, +z.
struct Loads {
  std::array<double, 6> walls{};
  std::vector<dvec3> force, torque;
};
inline Loads loads(const State& s, const Params& p, const std::vector<Fixed>& fixed, const std::vector<dvec3>& centres,
                   double mass) {
  const double r = p.radius, reach = 2 * r;
  Loads out;
  out.force.assign(centres.size(), dvec3(0.0));
  out.torque.assign(centres.size(), dvec3(0.0));
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    for (const Fixed& f : fixed) {
      const dvec3 d = s.x[i] - f.x;
      const double dist = glm::length(d);
      if (dist >= reach || dist == 0.0) continue;
      const dvec3 f_on_obstacle = -mass * contactAccel(p, d / dist, reach - dist, s.v[i] - f.v, 1.0, 1.0);
      out.force[f.obstacle] += f_on_obstacle;
      out.torque[f.obstacle] += glm::cross(0.5 * (s.x[i] + f.x) - centres[f.obstacle], f_on_obstacle);
    }
    for (int k = 0; k < 3; ++k) {
      dvec3 axis(0.0);
      axis[k] = 1.0;
      const double below = p.domainMin[k] + r - s.x[i][k];
      if (below > 0) out.walls[2 * k] -= mass * wallAccel(p, axis, below, s.v[i])[k];
      const double above = s.x[i][k] - (p.domainMax[k] - r);
      if (above > 0) out.walls[2 * k + 1] -= mass * wallAccel(p, -axis, above, s.v[i])[k];
    }
  }
  return out;
}

// walls.glsl's confineToDomain: the CUDA sample's clamp-and-bounce, then the clamp to the domain.
inline void confine(const Params& p, dvec3& x, dvec3& v) {
  const double r = p.radius;
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
  x = glm::clamp(x, dvec3(p.domainMin), dvec3(p.domainMax));
}

// The first half of a velocity Verlet step as the model runs it. Its first step (a empty)
// evaluates a(x0, v0) without a kick; then drift.comp: v½ = v + dt/2·a, x += dt·v½, confined.
inline void drift(State& s, const Params& p, const std::vector<Fixed>& fixed = {}) {
  const double dt = p.dt;
  if (s.a.size() != s.x.size()) s.a = accelerations(s, p, fixed);
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    s.v[i] += 0.5 * dt * s.a[i];
    s.x[i] += dt * s.v[i];
    confine(p, s.x[i], s.v[i]);
  }
}

// One velocity Verlet step: the drift, then collide.comp on the drifted positions and half-step
// velocities: a = a(x, v½), v = (v½ + dt/2·a)·exp(−damping·dt). The fixed particles are where
// they are when the forces act (here they do not move).
inline void stepVerlet(State& s, const Params& p, const std::vector<Fixed>& fixed = {}) {
  const double dt = p.dt;
  drift(s, p, fixed);
  s.a = accelerations(s, p, fixed);
  const double decay = std::exp(-double(p.damping) * dt);
  for (std::size_t i = 0; i < s.x.size(); ++i) s.v[i] = (s.v[i] + 0.5 * dt * s.a[i]) * decay;
}

// One step of the model's integrator (p.integrator), walls at the domain bounds.
inline void step(State& s, const Params& p, const std::vector<Fixed>& fixed = {}) {
  if (p.integrator == Integrator::VelocityVerlet) return stepVerlet(s, p, fixed);
  const double dt = p.dt;
  const std::vector<dvec3> a = accelerations(s, p, fixed);
  const double decay = std::exp(-double(p.damping) * dt);
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    dvec3 x = s.x[i], v = s.v[i];
    if (p.integrator == Integrator::ExplicitEuler) {
      x += dt * v;
      v = (v + dt * a[i]) * decay;
    } else {
      v = (v + dt * a[i]) * decay;
      x += dt * v;
    }
    confine(p, x, v);
    s.x[i] = x;
    s.v[i] = v;
  }
}

}  // namespace tidepool::balls::reference
