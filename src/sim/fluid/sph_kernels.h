// The smoothing kernels of Position Based Fluids (Macklin & Müller, "Position Based Fluids",
// SIGGRAPH 2013), after Müller, Charypar & Gross, "Particle-Based Fluid Simulation for
// Interactive Applications" (SCA 2003): poly6 for the density estimate ρ_i = Σ_j m W(x_i − x_j, h)
// and the spiky kernel's gradient for the constraint gradients (poly6's gradient vanishes at
// r = 0, which lets particles clump). Both have support h (the smoothing radius, metres), are
// normalised so that ∫ W dV = 1, and are templates so that the CPU references (double) and the
// float path the shaders mirror use one definition. The fluid model and the density
// metric of both water models (balls measured with the same kernel and h) build on these.
//
//   W_poly6(r, h)  = 315 / (64 π h⁹) · (h² − r²)³        for 0 ≤ r < h, else 0
//   W_spiky(r, h)  =  15 / (π h⁶)    · (h − r)³          for 0 ≤ r < h, else 0
//   ∇W_spiky(r, h) = −45 / (π h⁶)    · (h − r)² · r / |r|  for 0 < r < h, else 0
//
// The box walls are boundaries of the density sum in closed form (the continuous limit of Akinci
// et al. 2012's boundary particles: the half space beyond a wall filled at rest density), so a
// particle at distance δ from a wall (s = δ/h) reads from it
//   ρ_wall = ρ0 · Φ(δ),  Φ = ∫_{beyond} W_poly6 dV = ½ − 315/256 · (s − 4s³/3 + 6s⁵/5 − 4s⁷/7 + s⁹/9)
// and the constraint gradient the spiky kernel gives the same half space, of magnitude
//   G(δ) = |∫_{beyond} ∇W_spiky dV| = 30/h · ((1 − s)⁴/4 − (1 − s)⁵/5)   (1.5/h at the wall, 0 at h)
// pointing out of the fluid. Where two walls meet, their half spaces overlap in a quarter space
// that the sum would count twice; it is taken off again (inclusion–exclusion; the eighth spaces
// at the box's corners, within h of three walls, are left out): in units of h (a, b = δ/h),
//   Q(a, b) = ∫_{x>a, y>b} W_poly6 dV = 9/(2π) ∫∫_{x>a, y>b, x²+y²<1} (1 − x² − y²)^{7/2} dx dy
// tabulated on a 17 × 17 grid over [0, 1]² and interpolated bilinearly (edgeDensity), as the
// shaders do with the same table. shaders/fluid/kernels.glsl is the float twin of all of these.
#pragma once

#include <array>
#include <cmath>
#include <glm/glm.hpp>
#include <numbers>

namespace tidepool::fluid {

template <class T>
T poly6(T r2, T h) {  // r2 = |r|² (m²): the density sum needs no square root
  const T h2 = h * h;
  if (r2 >= h2) return T(0);
  const T d = h2 - r2;
  return T(315) / (T(64) * std::numbers::pi_v<T> * glm::pow(h, T(9))) * d * d * d;
}

template <class T>
T spiky(T r, T h) {  // the kernel whose gradient spikyGradient() is; r = |r| (m)
  if (r >= h) return T(0);
  const T d = h - r;
  return T(15) / (std::numbers::pi_v<T> * glm::pow(h, T(6))) * d * d * d;
}

template <class T>
glm::vec<3, T> spikyGradient(const glm::vec<3, T>& r, T h) {  // ∇ with respect to the first particle
  const T len = glm::length(r);
  if (len >= h || len <= T(0)) return glm::vec<3, T>(T(0));  // r = 0: no direction, no push
  const T d = h - len;
  return (T(-45) / (std::numbers::pi_v<T> * glm::pow(h, T(6))) * d * d / len) * r;
}

template <class T>
T wallDensity(T delta, T h) {  // Φ(δ): the fraction of ρ0 the wall half space adds; δ = distance to the wall (m)
  const T s = glm::clamp(delta / h, T(-1), T(1));
  const T s2 = s * s;
  return T(0.5) -
         T(315) / T(256) * s * (T(1) + s2 * (T(-4) / T(3) + s2 * (T(6) / T(5) + s2 * (T(-4) / T(7) + s2 / T(9)))));
}

template <class T>
T wallGradient(T delta, T h) {  // G(δ), 1/m: |∇| of the spiky kernel's half-space integral
  const T u = T(1) - glm::clamp(glm::abs(delta) / h, T(0), T(1));
  const T u4 = u * u * u * u;
  return T(30) / h * (u4 / T(4) - u4 * u / T(5));
}

constexpr int kEdgeTableSize = 17;  // entries per axis: a, b = i / 16
using EdgeTable = std::array<float, kEdgeTableSize * kEdgeTableSize>;

// Q(a, b) at a = i/16, b = j/16, entry [i + 17 j]; computed once (midpoint rule, 1e-5 absolute),
// in sph_kernels.cpp.
const EdgeTable& edgeTable();

// (Q, ∂Q/∂a, ∂Q/∂b) of the bilinear interpolant, a and b in units of h (clamped to [0, 1]).
template <class T>
glm::vec<3, T> edgeDensity(T a, T b) {
  const EdgeTable& t = edgeTable();
  const T x = glm::clamp(a, T(0), T(1)) * T(16), y = glm::clamp(b, T(0), T(1)) * T(16);
  const int i = glm::min(int(x), 15), j = glm::min(int(y), 15);
  const T fx = x - T(i), fy = y - T(j);
  auto at = [&](int u, int v) { return T(t[std::size_t(u + kEdgeTableSize * v)]); };
  const T q00 = at(i, j), q10 = at(i + 1, j), q01 = at(i, j + 1), q11 = at(i + 1, j + 1);
  const T lo = q00 + (q10 - q00) * fx, hi = q01 + (q11 - q01) * fx;
  return {lo + (hi - lo) * fy, T(16) * ((q10 - q00) + ((q11 - q01) - (q10 - q00)) * fy), T(16) * (hi - lo)};
}

}  // namespace tidepool::fluid
