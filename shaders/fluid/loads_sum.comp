#version 430 core
// The step's loads (fluid/loads.glsl): work group (c, s) adds slot s's partials of the step's
// groups c·LOADS_CHUNK .. (c + 1)·LOADS_CHUNK − 1, each invocation a fixed stride of them, then the
// invocations in a fixed tree, so the sums are the same on every run. Writes ΣΔ and Σ moment (two
// vec4) per chunk and slot; the CPU adds the chunks (src/sim/fluid/boundary_loads.cpp).
#include "fluid/bindings.glsl"

layout(local_size_x = FLUID_GROUP_SIZE) in;

layout(std430, binding = FLUID_LOADS) readonly buffer Loads { vec4 loads[]; };
layout(std430, binding = FLUID_OUT) writeonly buffer Sums { vec4 sums[]; };

uniform uint uLoadSlots;
uniform uint uGroups;  // work groups of the step's kernels
#define LOADS_CHUNK (8u * uint(FLUID_GROUP_SIZE))

shared vec3 sDelta[FLUID_GROUP_SIZE], sMoment[FLUID_GROUP_SIZE];

void main() {
  const uint chunk = gl_WorkGroupID.x, slot = gl_WorkGroupID.y, t = gl_LocalInvocationIndex;
  const uint end = min(uGroups, (chunk + 1u) * LOADS_CHUNK);
  vec3 delta = vec3(0.0), moment = vec3(0.0);
  for (uint g = chunk * LOADS_CHUNK + t; g < end; g += uint(FLUID_GROUP_SIZE)) {
    const uint at = 2u * (g * uLoadSlots + slot);
    delta += loads[at].xyz;
    moment += loads[at + 1u].xyz;
  }
  sDelta[t] = delta;
  sMoment[t] = moment;
  barrier();
  for (uint stride = uint(FLUID_GROUP_SIZE) / 2u; stride > 0u; stride /= 2u) {
    if (t < stride) {
      sDelta[t] += sDelta[t + stride];
      sMoment[t] += sMoment[t + stride];
    }
    barrier();
  }
  if (t == 0u) {
    const uint at = 2u * (chunk * uLoadSlots + slot);
    sums[at] = vec4(sDelta[0], 0.0);
    sums[at + 1u] = vec4(sMoment[0], 0.0);
  }
}
