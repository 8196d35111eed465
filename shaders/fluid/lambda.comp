#version 430 core
// PBF solver, first half of an iteration (Macklin & Müller 2013, eqs. 1-11): each particle's
// density ρ_i/ρ0 = Σ_j V0 W(p_i − p_j) + Σ_b V_b W(p_i − p_b) + Σ_walls Φ(δ) (boundaries after
// Akinci et al. 2012; walls in closed form), the constraint C_i = ρ_i/ρ0 − 1 (only compression:
// a free surface is not pulled in), and λ_i = −C_i / (Σ_k |∇_k C_i|² + ε). Λ_i, the sum of λ_i
// over the step's iterations, is the pressure's: p_i = −ρ0 Λ_i / dt² (fluid/pressure.comp).
#include "fluid/bindings.glsl"

layout(local_size_x = FLUID_GROUP_SIZE) in;
#include "common/index.glsl"

layout(std430, binding = FLUID_PRED) readonly buffer Pred { vec4 pred[]; };
layout(std430, binding = FLUID_LAMBDA) writeonly buffer Lambda { vec2 lambda[]; };  // (λ, ρ/ρ0)
layout(std430, binding = FLUID_PRESSURE) buffer LambdaSum { float lambdaSum[]; };  // Λ
#define neighbourPos pred

#include "fluid/kernels.glsl"

float gDensity;
vec3 gGradient;    // ∇_i C_i
float gGradients;  // Σ_j |∇_j C_i|²
void onFluid(uint j, vec3 r, float r2) {
  gDensity += uVolume * poly6(r2);
  const float len = sqrt(r2);
  if (len <= 0.0) return;  // itself: no gradient
  const vec3 g = uVolume * spikyGrad(r, len);
  gGradient += g;
  gGradients += dot(g, g);
}
void onBoundary(vec3 r, float r2, float volume, uint k) {
  gDensity += volume * poly6(r2);
  const float len = sqrt(r2);
  if (len > 0.0) gGradient += volume * spikyGrad(r, len);
}

#include "fluid/neighbours.glsl"
#include "fluid/boundary.glsl"
#include "fluid/walls.glsl"

uniform uint uCount;
uniform float uEpsilon;  // ε, 1/m²
uniform uint uFirstIteration;  // 1: Λ starts from this λ

void main() {
  const uint i = globalIndex();
  if (i >= uCount) return;
  const vec3 p = pred[i].xyz;
  gDensity = 0.0;
  gGradient = vec3(0.0);
  gGradients = 0.0;
  forEachFluid(i, p);
#ifdef HAS_OBSTACLE
  forEachBoundary(p, uH);
#endif
  wallsDensity(p, gDensity, gGradient);
  const float c = max(gDensity - 1.0, 0.0);
  const float l = -c / (gGradients + dot(gGradient, gGradient) + uEpsilon);
  lambda[i] = vec2(l, gDensity);
  lambdaSum[i] = uFirstIteration != 0u ? l : lambdaSum[i] + l;
}
