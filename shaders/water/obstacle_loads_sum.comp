#version 430 core
// The step's loads on the obstacles (water/obstacle_loads.glsl): work group k adds the shares
// and moments of obstacle k's particles, each invocation a fixed stride of them, then the
// invocations in a fixed tree, so the sums are the same on every run. Writes Σ share and
// Σ moment (two vec4) per obstacle at the start of the sums.
#include "water/loads_bindings.glsl"
#include "balls/bindings.glsl"

layout(local_size_x = LOADS_SUM_GROUP_SIZE) in;

layout(std430, binding = LOADS_SHARES) readonly buffer Shares { vec4 shares[]; };
layout(std430, binding = LOADS_MOMENTS) readonly buffer Moments { vec4 moments[]; };
layout(std430, binding = LOADS_SUMS) writeonly buffer Sums { vec4 sums[]; };

#include "balls/obstacle_poses.glsl"

uniform uint uObstacles;
#include "water/pair_sum.glsl"

void main() {
  const uint k = gl_WorkGroupID.x, t = gl_LocalInvocationIndex;
  if (k >= uObstacles) return;  // the whole group
  const uint first = poseParticles[k].x, end = first + poseParticles[k].y;
  vec4 share = vec4(0.0), moment = vec4(0.0);
  for (uint b = first + t; b < end; b += uint(LOADS_SUM_GROUP_SIZE)) {
    share += shares[b];
    moment += moments[b];
  }
  sumPairs(share, moment);
  if (t == 0u) {
    sums[2u * k] = sPairA[0];
    sums[2u * k + 1u] = sPairB[0];
  }
}
