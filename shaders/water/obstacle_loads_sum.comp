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

shared vec3 sShare[LOADS_SUM_GROUP_SIZE], sMoment[LOADS_SUM_GROUP_SIZE];

void main() {
  const uint k = gl_WorkGroupID.x, t = gl_LocalInvocationIndex;
  if (k >= uObstacles) return;  // the whole group
  const uint first = poseParticles[k].x, end = first + poseParticles[k].y;
  vec3 share = vec3(0.0), moment = vec3(0.0);
  for (uint b = first + t; b < end; b += uint(LOADS_SUM_GROUP_SIZE)) {
    share += shares[b].xyz;
    moment += moments[b].xyz;
  }
  sShare[t] = share;
  sMoment[t] = moment;
  barrier();
  for (uint stride = uint(LOADS_SUM_GROUP_SIZE) / 2u; stride > 0u; stride /= 2u) {
    if (t < stride) {
      sShare[t] += sShare[t + stride];
      sMoment[t] += sMoment[t + stride];
    }
    barrier();
  }
  if (t == 0u) {
    sums[2u * k] = vec4(sShare[0], 0.0);
    sums[2u * k + 1u] = vec4(sMoment[0], 0.0);
  }
}
