#version 430 core
// The step's loads (fluid/loads.glsl): one work group per slot adds that slot's partials over all
// groups of the step's kernels, each invocation a fixed stride of groups, then the invocations in
// a fixed tree, so the sums are the same on every run. Writes ΣΔ and Σ moment (two vec4) per slot.
#include "fluid/bindings.glsl"

layout(local_size_x = FLUID_GROUP_SIZE) in;

layout(std430, binding = FLUID_LOADS) readonly buffer Loads { vec4 loads[]; };
layout(std430, binding = FLUID_OUT) writeonly buffer Sums { vec4 sums[]; };

uniform uint uLoadSlots;
uniform uint uGroups;  // work groups of the step's kernels

shared vec3 sDelta[FLUID_GROUP_SIZE], sMoment[FLUID_GROUP_SIZE];

void main() {
  const uint slot = gl_WorkGroupID.x, t = gl_LocalInvocationIndex;
  vec3 delta = vec3(0.0), moment = vec3(0.0);
  for (uint g = t; g < uGroups; g += uint(FLUID_GROUP_SIZE)) {
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
    sums[2u * slot] = vec4(sDelta[0], 0.0);
    sums[2u * slot + 1u] = vec4(sMoment[0], 0.0);
  }
}
