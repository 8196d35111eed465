#version 430 core
// PBF solver, second half of an iteration (Macklin & Müller 2013, eqs. 12-14): the position
// correction Δp_i = Σ_j V0 (λ_i + λ_j + s_corr) ∇W(p_i − p_j) + λ_i (Σ_b V_b ∇W(p_i − p_b) +
// the walls' gradient), s_corr = −k (W(r)/W(Δq))^n, then the collisions: no closer than
// uContact to an obstacle particle (no layer of them can be passed) and inside
// the walls. Jacobi: reads p and λ of all, writes the corrected p to the other buffer. With
// BOUNDARY_LOADS, the walls' and each obstacle's shares of the correction go to water/loads.glsl.
#include "fluid/bindings.glsl"

layout(local_size_x = FLUID_GROUP_SIZE) in;
#include "common/index.glsl"

layout(std430, binding = FLUID_PRED) readonly buffer Pred { vec4 pred[]; };
layout(std430, binding = FLUID_LAMBDA) readonly buffer Lambda { vec2 lambda[]; };
layout(std430, binding = FLUID_OUT) writeonly buffer PredOut { vec4 predOut[]; };
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
#ifdef BOUNDARY_LOADS
uint gTouched = 0u;  // bit k: a particle of obstacle k was within reach
int gOnly = -1;      // ≥ 0: only obstacle gOnly's particles count (its share, obstacleShare())
// The first obstacle met: its share is summed on the way, in the order a recount would sum it
// (any other obstacle's share is recounted; a particle seldom has two within reach).
int gFirst = -1;
vec3 gFirstGradient = vec3(0.0), gFirstPushed = vec3(0.0);
#endif
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
#ifdef BOUNDARY_LOADS
  if (gOnly >= 0 && k != uint(gOnly)) return;
  gTouched |= 1u << k;
  if (gFirst < 0) gFirst = int(k);
#endif
  if (gPushing) {
    const vec3 push = (uContact - len) / len * r;  // r from the corrected position: out to uContact
    gPushed += push;
#ifdef BOUNDARY_LOADS
    if (k == uint(gFirst)) gFirstPushed += push;
#endif
  } else {
    const vec3 gradient = volume * spikyGrad(r, len);
    gBoundaryGradient += gradient;
#ifdef BOUNDARY_LOADS
    if (k == uint(gFirst)) gFirstGradient += gradient;
#endif
  }
}

#include "fluid/neighbours.glsl"
#include "fluid/boundary.glsl"
#include "fluid/walls.glsl"

uniform uint uCount;

vec3 gP = vec3(0.0), gQ;  // the particle before the correction, and after it before the obstacles' push

#ifdef BOUNDARY_LOADS
#include "balls/bindings.glsl"
#include "balls/obstacle_poses.glsl"
// Obstacle k's share of this particle's correction (λ_i Σ_b V_b ∇W at p, then the push at q) and
// its moment about c_k.
void obstacleShare(uint k, out vec3 delta, out vec3 moment) {
#ifdef HAS_OBSTACLE
  vec3 gradientSum = gFirstGradient, pushed = gFirstPushed;
  if (int(k) != gFirst) {  // recounted: only k's particles
    gOnly = int(k);
    gPushing = false;
    gBoundaryGradient = vec3(0.0);
    forEachBoundary(gP, uH);
    gradientSum = gBoundaryGradient;
    gPushing = true;
    gPushed = vec3(0.0);
    forEachBoundary(gQ, uContact);
    pushed = gPushed;
  }
  const vec3 gradient = gLambda * gradientSum;
  const vec3 c = poseCentre[k].xyz;
  delta = gradient + pushed;
  moment = cross(gP - c, gradient) + cross(gQ - c, pushed);
#else
  delta = moment = vec3(0.0);
#endif
}
#define LOADS_BINDING FLUID_LOADS
#define LOADS_GROUP_SIZE FLUID_GROUP_SIZE
#include "water/loads.glsl"
#endif

// Particle i's corrected position; `wallShare`: the walls' part of its correction (λ_i times
// their gradient, then the clamp).
vec4 corrected(uint i, out vec3 wallShare) {
  const vec4 pi = pred[i];
  gP = pi.xyz;
  gLambda = lambda[i].x;
  gDelta = vec3(0.0);
  gBoundaryGradient = vec3(0.0);
  forEachFluid(i, gP);
#ifdef HAS_OBSTACLE
  forEachBoundary(gP, uH);
#endif
  float unused = 0.0;
  vec3 wallGradient = vec3(0.0);
  wallsDensity(gP, unused, wallGradient);
  gQ = gP + gDelta + gLambda * (gBoundaryGradient + wallGradient);
  vec3 q = gQ;
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
  vec3 wallShare = vec3(0.0);
  if (i < uCount) predOut[i] = corrected(i, wallShare);
#ifdef BOUNDARY_LOADS
  addLoads(wallShare, wallSides(gP), gTouched);  // by every invocation: the group adds them
#endif
}
