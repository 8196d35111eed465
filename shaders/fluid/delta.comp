#version 430 core
// PBF solver, second half of an iteration (Macklin & Müller 2013, eqs. 12-14): the position
// correction Δp_i = Σ_j V0 (λ_i + λ_j + s_corr) ∇W(p_i − p_j) + λ_i (Σ_b V_b ∇W(p_i − p_b) +
// the walls' gradient), s_corr = −k (W(r)/W(Δq))^n, then the collisions: no closer than
// uContact to an obstacle particle (no layer of them can be passed) and inside
// the walls. Jacobi: reads p and λ of all, writes the corrected p to the other buffer.
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
void onBoundary(vec3 r, float r2, float volume) {
  const float len = sqrt(r2);
  if (len > 0.0) gBoundaryGradient += volume * spikyGrad(r, len);
}

#include "fluid/neighbours.glsl"
#include "fluid/walls.glsl"

uniform uint uCount;
uniform float uContact;  // m: the closest a fluid particle comes to an obstacle particle

#ifdef HAS_OBSTACLE
// The obstacle particles within uContact of the corrected position, each pushing it out to uContact.
void pushOutOfObstacles(inout vec3 p) {
  const vec3 g = (p - uObstacleOrigin) * uObstacleInvCell;
  if (any(lessThan(g, vec3(-1.0))) || any(greaterThan(g, vec3(uObstacleDims) + 1.0))) return;
  const ivec3 last = ivec3(uObstacleDims) - 1;
  const ivec3 oc = clamp(ivec3(floor(g)), ivec3(0), last);
  const int ox0 = max(oc.x - 1, 0), ox1 = min(oc.x + 1, last.x);
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy) {
      const ivec3 row = ivec3(ox0, oc.y + dy, oc.z + dz);
      if (row.y < 0 || row.z < 0 || row.y > last.y || row.z > last.z) continue;
      const uint first = uint(row.x) + uObstacleDims.x * (uint(row.y) + uObstacleDims.y * uint(row.z));
      const uint end = obstacleCellStart[first + uint(ox1 - ox0) + 1u];
      for (uint j = obstacleCellStart[first]; j < end; ++j) {
        const vec3 r = p - obstaclePos[j].xyz;
        const float r2 = dot(r, r);
        if (r2 >= uContact * uContact || r2 == 0.0) continue;
        const float len = sqrt(r2);
        p += (uContact - len) / len * r;
      }
    }
}
#endif

void main() {
  const uint i = globalIndex();
  if (i >= uCount) return;
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
  wallsDensity(p, unused, gBoundaryGradient);
  vec3 q = p + gDelta + gLambda * gBoundaryGradient;
#ifdef HAS_OBSTACLE
  pushOutOfObstacles(q);
#endif
  predOut[i] = vec4(clampToWalls(q), pi.w);
}
