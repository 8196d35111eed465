// CPU reference of one fluid step (Position Based Fluids, Macklin & Müller 2013), the oracle the
// GPU step is compared against: plain loops over all pairs, double precision, the same order of
// operations as src/sim/fluid/fluid_passes.cpp (predict, iterations of λ then Δp with s_corr,
// obstacle contact and walls, velocity, XSPH, vorticity confinement), densities as ρ/ρ0; and the
// boundaries' shares of the corrections, the loads (src/sim/water/boundary_loads.h).
#pragma once

#include <array>
#include <glm/glm.hpp>
#include <vector>

#include "sim/fluid/sph_kernels.h"

namespace tidepool::fluid::reference {

struct Boundary {
  glm::dvec3 pos;    // world, m
  double volume;     // m³
  int obstacle = 0;  // its obstacle's index
};

struct Setup {
  double h = 0.04, volume = 1e-5, epsilon = 0;  // ε absolute (1/m²)
  double scorrK = 0.1, scorrN = 4, scorrDq = 0.2;
  double dt = 1.0 / 600, decay = 1, viscosity = 0, vorticity = 0, contact = 0.012, inset = 0.01, wallScale = 1;
  int iterations = 1;
  glm::dvec3 gravity{0, 0, -9.81}, wallMin{0.0}, wallMax{1.0};
  std::vector<Boundary> boundary;
  std::vector<glm::dvec3> centres;  // each obstacle's centre, m (the moments' origin)
};

struct State {
  std::vector<glm::dvec3> x, v;
  // The step's sums of the boundaries' shares of the corrections, m: per wall (−x, +x, −y, +y,
  // −z, +z; along its normal) and per obstacle, with their moments about the centres (m²).
  std::array<double, 6> wall{};
  std::vector<glm::dvec3> obstacle, moment;
};

// The wall share Δ of one particle at p, each axis to the nearer wall.
inline void addWallShare(const Setup& s, const glm::dvec3& p, const glm::dvec3& delta, State& st) {
  for (int k = 0; k < 3; ++k) st.wall[2 * k + (p[k] - s.wallMin[k] <= s.wallMax[k] - p[k] ? 0 : 1)] += delta[k];
}

// The walls' half spaces less the quarter spaces of each pair (shaders/fluid/walls.glsl).
inline void walls(const Setup& s, const glm::dvec3& p, double& rhoOut, glm::dvec3& gOut) {
  double rho = 0;
  glm::dvec3 g(0.0);
  glm::dvec3 near(2 * s.h), side(0.0);
  for (int k = 0; k < 3; ++k) {
    const double below = p[k] - s.wallMin[k], above = s.wallMax[k] - p[k];
    if (below < s.h) {
      rho += wallDensity(below, s.h);
      g[k] -= wallGradient(below, s.h);
    }
    if (above < s.h) {
      rho += wallDensity(above, s.h);
      g[k] += wallGradient(above, s.h);
    }
    near[k] = std::min(below, above);
    side[k] = below <= above ? -1.0 : 1.0;
  }
  for (int k = 0; k < 2; ++k)
    for (int l = k + 1; l < 3; ++l) {
      if (near[k] >= s.h || near[l] >= s.h) continue;
      const glm::dvec3 q = edgeDensity(near[k] / s.h, near[l] / s.h);
      rho -= q.x;
      g[k] += side[k] * q.y / s.h;
      g[l] += side[l] * q.z / s.h;
    }
  rhoOut += s.wallScale * rho;
  gOut += s.wallScale * g;
}

inline double density(const Setup& s, const std::vector<glm::dvec3>& p, std::size_t i, glm::dvec3* gradient,
                      double* gradients) {
  double rho = 0;
  glm::dvec3 g(0.0);
  double sq = 0;
  for (const glm::dvec3& q : p) {
    const glm::dvec3 r = p[i] - q;
    rho += s.volume * poly6(glm::dot(r, r), s.h);
    const glm::dvec3 gj = s.volume * spikyGradient(r, s.h);
    g += gj;
    sq += glm::dot(gj, gj);
  }
  for (const Boundary& b : s.boundary) {
    const glm::dvec3 r = p[i] - b.pos;
    rho += b.volume * poly6(glm::dot(r, r), s.h);
    g += b.volume * spikyGradient(r, s.h);
  }
  walls(s, p[i], rho, g);
  if (gradient) *gradient = g;
  if (gradients) *gradients = sq;
  return rho;
}

inline std::vector<glm::dvec3> iterate(const Setup& s, const std::vector<glm::dvec3>& p, State& st) {
  const std::size_t n = p.size();
  std::vector<double> lambda(n);
  for (std::size_t i = 0; i < n; ++i) {
    glm::dvec3 g;
    double sq;
    const double c = std::max(density(s, p, i, &g, &sq) - 1.0, 0.0);
    lambda[i] = -c / (sq + glm::dot(g, g) + s.epsilon);
  }
  const double invQ = 1.0 / (1.0 - s.scorrDq * s.scorrDq);
  std::vector<glm::dvec3> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    glm::dvec3 delta(0.0), boundary(0.0);
    for (std::size_t j = 0; j < n; ++j) {
      const glm::dvec3 r = p[i] - p[j];
      const double len = glm::length(r);
      if (len <= 0 || len >= s.h) continue;
      const double w = (1.0 - len * len / (s.h * s.h)) * invQ;
      const double scorr = -s.scorrK * std::pow(w * w * w, s.scorrN);
      delta += (lambda[i] + lambda[j] + scorr) * s.volume * spikyGradient(r, s.h);
    }
    std::vector<glm::dvec3> gradient(s.centres.size(), glm::dvec3(0.0)), push(s.centres.size(), glm::dvec3(0.0));
    for (const Boundary& b : s.boundary) {
      boundary += b.volume * spikyGradient(p[i] - b.pos, s.h);
      gradient[std::size_t(b.obstacle)] += b.volume * spikyGradient(p[i] - b.pos, s.h);
    }
    double unused = 0;
    glm::dvec3 wallGradient(0.0);
    walls(s, p[i], unused, wallGradient);
    const glm::dvec3 q0 = p[i] + delta + lambda[i] * (boundary + wallGradient);
    glm::dvec3 q = q0, pushed(0.0);  // each obstacle particle within the contact distance pushes q out to it
    for (const Boundary& b : s.boundary) {
      const glm::dvec3 r = q - b.pos;
      const double len = glm::length(r);
      if (len > 0 && len < s.contact) {
        pushed += (s.contact - len) / len * r;
        push[std::size_t(b.obstacle)] += (s.contact - len) / len * r;
      }
    }
    q += pushed;
    out[i] = glm::clamp(q, s.wallMin + s.inset, s.wallMax - s.inset);
    addWallShare(s, p[i], lambda[i] * wallGradient + (out[i] - q), st);
    for (std::size_t k = 0; k < s.centres.size(); ++k) {
      st.obstacle[k] += lambda[i] * gradient[k] + push[k];
      st.moment[k] += glm::cross(p[i] - s.centres[k], lambda[i] * gradient[k]) + glm::cross(q0 - s.centres[k], push[k]);
    }
  }
  return out;
}

inline void step(const Setup& s, State& st) {
  const std::size_t n = st.x.size();
  std::vector<glm::dvec3> p(n);
  st.wall = {};
  st.obstacle.assign(s.centres.size(), glm::dvec3(0.0));
  st.moment.assign(s.centres.size(), glm::dvec3(0.0));
  for (std::size_t i = 0; i < n; ++i) {
    const glm::dvec3 free = st.x[i] + s.dt * ((st.v[i] + s.dt * s.gravity) * s.decay);
    p[i] = glm::clamp(free, s.wallMin + s.inset, s.wallMax - s.inset);
    addWallShare(s, free, p[i] - free, st);
  }
  for (int k = 0; k < s.iterations; ++k) p = iterate(s, p, st);
  std::vector<glm::dvec3> v(n), omega(n, glm::dvec3(0.0));
  for (std::size_t i = 0; i < n; ++i) v[i] = (p[i] - st.x[i]) / s.dt;
  std::vector<glm::dvec3> out = v;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      const glm::dvec3 r = p[i] - p[j];
      const glm::dvec3 dv = v[j] - v[i];
      out[i] += s.viscosity * s.volume * poly6(glm::dot(r, r), s.h) * dv;
      omega[i] += s.volume * glm::cross(dv, -spikyGradient(r, s.h));
    }
  if (s.vorticity > 0)
    for (std::size_t i = 0; i < n; ++i) {
      glm::dvec3 eta(0.0);
      for (std::size_t j = 0; j < n; ++j) eta += s.volume * glm::length(omega[j]) * spikyGradient(p[i] - p[j], s.h);
      const double len = glm::length(eta);
      const glm::dvec3 nrm = len > 1e-12 ? eta / len : glm::dvec3(0.0);
      out[i] += s.dt * s.vorticity * glm::cross(nrm, omega[i]);
    }
  st.x = p;
  st.v = out;
}

}  // namespace tidepool::fluid::reference
