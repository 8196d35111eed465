#version 430 core
// PBF solver, second half of an iteration (Macklin & Müller 2013, eqs. 12-14): the position
// correction Δp_i = Σ_j V0 (λ_i + λ_j + s_corr) ∇W(p_i − p_j) + λ_i (Σ_b V_b ∇W(p_i − p_b) +
// the walls' gradient), s_corr = −k (W(r)/W(Δq))^n, then the collisions: no closer than
// uContact to an obstacle particle (no layer of them can be passed) and inside
// the walls. Jacobi: reads p and λ of all, writes the corrected p to the other buffer. With
// LOADS_WALLS, the walls' shares of the correction go to water/loads.glsl; with OBSTACLE_LOADS,
// each particle with an obstacle particle within h keeps its corrected position before the push,
// from which fluid/obstacle_loads.comp sums the obstacles' shares.
#include "fluid/bindings.glsl"

layout(local_size_x = FLUID_GROUP_SIZE) in;
#include "common/index.glsl"

layout(std430, binding = FLUID_PRED) readonly buffer Pred { vec4 pred[]; };
layout(std430, binding = FLUID_LAMBDA) readonly buffer Lambda { vec2 lambda[]; };
layout(std430, binding = FLUID_OUT) writeonly buffer PredOut { vec4 predOut[]; };
#ifdef OBSTACLE_LOADS
layout(std430, binding = FLUID_UNPUSHED) writeonly buffer Unpushed { vec4 unpushed[]; };  // q before the push
#endif
#define neighbourPos pred

#include "fluid/kernels.glsl"

uniform float uScorrK;
uniform float uScorrN;
uniform float uScorrInvQ;  // 1 / (1 − Δq²/h²): W(r)/W(Δq) = ((1 − r²/h²)·uScorrInvQ)³

float gLambda = 0.0;
vec3 gDelta;
vec3 gBoundaryGradient;
bool gPushing = false;  // the boundary loop's second use: pushing gPushed out to uContact
vec3 gPushed = vec3(0.0);
uniform float uContact;  // m: the closest a fluid particle comes to an obstacle particle
bool gNearObstacle = false;  // an obstacle particle within h of p
void onFluid(uint j, vec3 r, float r2) {
  const float len = sqrt(r2);
  if (len <= 0.0) return;
  const float w = (1.0 - r2 / (uH * uH)) * uScorrInvQ, w3 = w * w * w;
#ifdef SCORR_N4
  const float w6 = w3 * w3, scorr = -uScorrK * w6 * w6;  // n = 4, the usual: no pow per pair
#else
  const float scorr = -uScorrK * pow(w3, uScorrN);
#endif
  gDelta += (gLambda + lambda[j].x + scorr) * uVolume * spikyGrad(r, len);
}
void onBoundary(vec3 r, float r2, float volume, uint k) {
  const float len = sqrt(r2);
  if (len <= 0.0) return;
  if (gPushing) {
    gPushed += (uContact - len) / len * r;  // r from the corrected position: out to uContact
  } else {
    gBoundaryGradient += volume * spikyGrad(r, len);
    gNearObstacle = true;
  }
}

#include "fluid/neighbours.glsl"
#include "fluid/boundary.glsl"
#include "fluid/walls.glsl"

uniform uint uCount;


#ifdef LOADS_WALLS
#define LOADS_BINDING FLUID_LOADS
#define LOADS_GROUP_SIZE FLUID_GROUP_SIZE
#include "water/loads.glsl"
#endif

// Particle i's corrected position; `wallShare`: the walls' part of its correction (λ_i times
// their gradient, then the clamp).
vec4 corrected(uint i, out vec3 wallShare) {
  const vec4 pi = pred[i];
  const vec3 p = pi.xyz;
  gLambda = lambda[i].x;
  gDelta = vec3(0.0);
  gBoundaryGradient = vec3(0.0);
  forEachFluid(i, p);
#ifdef HAS_OBSTACLE
  forEachBoundary(p, uH);
#endif
  float unused = 0.0;
  vec3 wallGradient = vec3(0.0);
  wallsDensity(p, unused, wallGradient);
  vec3 q = p + gDelta + gLambda * (gBoundaryGradient + wallGradient);
#ifdef OBSTACLE_LOADS
  if (gNearObstacle) unpushed[i] = vec4(q, 0.0);
#endif
#ifdef HAS_OBSTACLE
  // Each obstacle particle within uContact of the corrected position pushes it out to uContact.
  gPushing = true;
  gPushed = vec3(0.0);
  forEachBoundary(q, uContact);
  q += gPushed;
#endif
  const vec3 inside = clampToWalls(q);
  wallShare = gLambda * wallGradient + (inside - q);
  return vec4(inside, pi.w);
}

void main() {
  const uint i = globalIndex();
  vec3 wallShare = vec3(0.0), side = vec3(1.0);
  if (i < uCount) {
    predOut[i] = corrected(i, wallShare);
#ifdef LOADS_WALLS
    side = wallSides(pred[i].xyz);
#endif
  }
#ifdef LOADS_WALLS
  addLoads(wallShare, side);  // by every invocation: the group adds them
#endif
}
