#version 430 core
// Live statistics and probes of the balls, reduced per work group (the CPU adds the groups): the
// BALLS_STATS_VALUES floats of balls/stats_layout.glsl, sums and maxima, for each work group.
#include "balls/bindings.glsl"
#include "balls/stats_layout.glsl"

layout(local_size_x = BALLS_GROUP_SIZE) in;
#include "common/index.glsl"

layout(std430, binding = BALLS_POS_IN) readonly buffer PosIn { vec4 posIn[]; };
layout(std430, binding = BALLS_VEL_IN) readonly buffer VelIn { vec4 velIn[]; };
layout(std430, binding = BALLS_STATS) writeonly buffer Stats { float partials[]; };  // BALLS_STATS_VALUES per group

float gMaxOverlap, gSumOverlap, gContacts;
void onContact(vec3 n, float overlap, vec3 otherVelocity, float massRatio, float share) {
  gMaxOverlap = max(gMaxOverlap, overlap);
  gSumOverlap += overlap;
  gContacts += 1.0;
}

#include "balls/neighbours.glsl"

// Balls [uFirst, uCount), as in collide.comp: the partials are bound from uFirst's work group on.
uniform uint uFirst;
uniform uint uCount;
uniform vec3 uGravity;
uniform vec3 uDomainMin;
uniform vec3 uWallMin;
uniform vec3 uWallMax;

const int kValues = BALLS_STATS_VALUES;
bool reducedByMax(int k) {
  return k == BALLS_STATS_MAX_OVERLAP || k == BALLS_STATS_MAX_SPEED || k == BALLS_STATS_FRONT ||
         k == BALLS_STATS_BACK_HEIGHT;
}

#define GROUP_SIZE BALLS_GROUP_SIZE
#include "common/group_reduce.glsl"

void main() {
  const uint i = uFirst + globalIndex();
  const float kNone = -3.0e38;
  float values[kValues];
  for (int k = 0; k < kValues; ++k) values[k] = 0.0;
  values[BALLS_STATS_FRONT] = kNone;
  values[BALLS_STATS_BACK_HEIGHT] = kNone;
  if (i < uCount) {
    const vec3 p = posIn[i - uSourceFirst].xyz, v = velIn[i - uSourceFirst].xyz;
    if (any(isnan(p)) || any(isinf(p)) || any(isnan(v)) || any(isinf(v))) {
      values[BALLS_STATS_NON_FINITE] = 1.0;
    } else {
      gMaxOverlap = 0.0;
      gSumOverlap = 0.0;
      gContacts = 0.0;
      forEachContact(i, p);
      values[BALLS_STATS_KINETIC] = 0.5 * dot(v, v);
      values[BALLS_STATS_POTENTIAL] = -dot(uGravity, p - uDomainMin);
      values[BALLS_STATS_OVERLAP] = gSumOverlap / uRadius;
      values[BALLS_STATS_CONTACTS] = gContacts;
      values[BALLS_STATS_MAX_OVERLAP] = gMaxOverlap / uRadius;
      values[BALLS_STATS_MAX_SPEED] = length(v);
      values[BALLS_STATS_OUTSIDE] = any(lessThan(p, uWallMin - 1e-6)) || any(greaterThan(p, uWallMax + 1e-6)) ? 1.0 : 0.0;
      if (p.z < uWallMin.z + 2.0 * uRadius) values[BALLS_STATS_FRONT] = p.x;
      if (p.x < uWallMin.x + 2.0 * uRadius) values[BALLS_STATS_BACK_HEIGHT] = p.z;
    }
  }
  reduceGroup(values);
}
