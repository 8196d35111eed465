// The smoothing kernels of Position Based Fluids (Macklin & Müller, "Position Based Fluids",
// SIGGRAPH 2013), after Müller, Charypar & Gross, "Particle-Based Fluid Simulation for
// Interactive Applications" (SCA 2003): poly6 for the density estimate ρ_i = Σ_j m W(x_i − x_j, h)
// and the spiky kernel's gradient for the constraint gradients (poly6's gradient vanishes at
// r = 0, which lets particles clump). Both have support h (the smoothing radius, metres), are
// normalised so that ∫ W dV = 1, and are templates so that the CPU references (double) and the
// float path the shaders mirror use one definition. Issue 18's fluid model and the density
// metric of both water models (balls measured with the same kernel and h) build on these.
//
//   W_poly6(r, h)  = 315 / (64 π h⁹) · (h² − r²)³        for 0 ≤ r < h, else 0
//   W_spiky(r, h)  =  15 / (π h⁶)    · (h − r)³          for 0 ≤ r < h, else 0
//   ∇W_spiky(r, h) = −45 / (π h⁶)    · (h − r)² · r / |r|  for 0 < r < h, else 0
#pragma once

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

}  // namespace tidepool::fluid
