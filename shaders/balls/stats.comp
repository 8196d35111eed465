#version 430 core
// Live statistics and probes of the balls, reduced per work group (the CPU adds the groups):
//   [0] kinetic energy Σ ½|v|² (per unit mass)   [1] potential energy Σ −g·(x − domain min)
//   [2] Σ overlap / r over contacts (each pair seen from both sides)   [3] contacts
//   [4] max overlap / r   [5] max speed   [6] non-finite balls   [7] balls outside the walls
//   [8] surge front: largest x of balls within 2r of the floor (−inf when none)
//   [9] column height: largest z of balls within 2r of the back (x min) wall (−inf when none)
#include "balls/bindings.glsl"

layout(local_size_x = 128) in;
#include "common/index.glsl"

layout(std430, binding = BALLS_POS_IN) readonly buffer PosIn { vec4 posIn[]; };
layout(std430, binding = BALLS_VEL_IN) readonly buffer VelIn { vec4 velIn[]; };
layout(std430, binding = BALLS_STATS) writeonly buffer Stats { float partials[]; };  // 10 per group

float gMaxOverlap, gSumOverlap, gContacts;
void onContact(vec3 n, float overlap, vec3 otherVelocity, float massRatio, float share) {
  gMaxOverlap = max(gMaxOverlap, overlap);
  gSumOverlap += overlap;
  gContacts += 1.0;
}

#include "balls/neighbours.glsl"

uniform uint uCount;
uniform vec3 uGravity;
uniform vec3 uDomainMin;
uniform vec3 uWallMin;
uniform vec3 uWallMax;

const uint kGroup = 128u;
const int kValues = 10;
shared float sValues[kValues][128];

void main() {
  const uint i = globalIndex();
  const uint t = gl_LocalInvocationIndex;
  const float kNone = -3.0e38;
  float values[kValues] = float[kValues](0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, kNone, kNone);
  if (i < uCount) {
    const vec3 p = posIn[i].xyz, v = velIn[i].xyz;
    if (any(isnan(p)) || any(isinf(p)) || any(isnan(v)) || any(isinf(v))) {
      values[6] = 1.0;
    } else {
      gMaxOverlap = 0.0;
      gSumOverlap = 0.0;
      gContacts = 0.0;
      forEachContact(p);
      values[0] = 0.5 * dot(v, v);
      values[1] = -dot(uGravity, p - uDomainMin);
      values[2] = gSumOverlap / uRadius;
      values[3] = gContacts;
      values[4] = gMaxOverlap / uRadius;
      values[5] = length(v);
      values[7] = any(lessThan(p, uWallMin - 1e-6)) || any(greaterThan(p, uWallMax + 1e-6)) ? 1.0 : 0.0;
      if (p.z < uWallMin.z + 2.0 * uRadius) values[8] = p.x;
      if (p.x < uWallMin.x + 2.0 * uRadius) values[9] = p.z;
    }
  }
  for (int k = 0; k < kValues; ++k) sValues[k][t] = values[k];
  barrier();
  for (uint stride = kGroup / 2u; stride > 0u; stride /= 2u) {
    if (t < stride)
      for (int k = 0; k < kValues; ++k) {
        const float other = sValues[k][t + stride];
        sValues[k][t] = (k == 4 || k == 5 || k >= 8) ? max(sValues[k][t], other) : sValues[k][t] + other;
      }
    barrier();
  }
  if (t == 0u)
    for (int k = 0; k < kValues; ++k) partials[groupIndex() * uint(kValues) + uint(k)] = sValues[k][0];
}
