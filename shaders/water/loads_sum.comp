#version 430 core
// The step's loads (water/loads.glsl): work group (c, s) adds slot s's partials of the measuring
// kernel's groups c·uChunkGroups .. (c + 1)·uChunkGroups − 1, each invocation a fixed
// stride of them, then the invocations in a fixed tree, so the sums are the same on every run.
// Writes ΣΔ and Σ moment (two vec4) per chunk and slot; the CPU adds the chunks
// (src/sim/water/boundary_loads.cpp). Partials past one storage block are summed a window of
// chunks at a time: the partials bound from chunk uFirstChunk on.
#include "water/loads_bindings.glsl"

layout(local_size_x = LOADS_SUM_GROUP_SIZE) in;

layout(std430, binding = LOADS_PARTIALS) readonly buffer Loads { vec4 loads[]; };
layout(std430, binding = LOADS_SUMS) writeonly buffer Sums { vec4 sums[]; };

uniform uint uLoadSlots;
uniform uint uGroups;      // the measuring kernel's work groups in the bound partials
uniform uint uFirstChunk;  // the first chunk bound
uniform uint uChunkGroups; // the measuring kernel's work groups per chunk

shared vec3 sDelta[LOADS_SUM_GROUP_SIZE], sMoment[LOADS_SUM_GROUP_SIZE];

void main() {
  const uint chunk = gl_WorkGroupID.x, slot = gl_WorkGroupID.y, t = gl_LocalInvocationIndex;
  const uint end = min(uGroups, (chunk + 1u) * uChunkGroups);
  vec3 delta = vec3(0.0), moment = vec3(0.0);
  for (uint g = chunk * uChunkGroups + t; g < end; g += uint(LOADS_SUM_GROUP_SIZE)) {
    const uint at = 2u * (g * uLoadSlots + slot);
    delta += loads[at].xyz;
    moment += loads[at + 1u].xyz;
  }
  sDelta[t] = delta;
  sMoment[t] = moment;
  barrier();
  for (uint stride = uint(LOADS_SUM_GROUP_SIZE) / 2u; stride > 0u; stride /= 2u) {
    if (t < stride) {
      sDelta[t] += sDelta[t + stride];
      sMoment[t] += sMoment[t + stride];
    }
    barrier();
  }
  if (t == 0u) {
    const uint at = 2u * ((uFirstChunk + chunk) * uLoadSlots + slot);
    sums[at] = vec4(sDelta[0], 0.0);
    sums[at + 1u] = vec4(sMoment[0], 0.0);
  }
}
