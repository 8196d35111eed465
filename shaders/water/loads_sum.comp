#version 430 core
// The step's loads on the walls (water/loads.glsl): work group c adds the partials of the
// measuring kernel's groups c·uChunkGroups .. (c + 1)·uChunkGroups − 1, each invocation a fixed
// stride of them, then the invocations in a fixed tree, so the sums are the same on every run.
// Writes two vec4 per chunk from sums[uSumsFirst] on; the CPU adds the chunks
// (src/sim/water/boundary_loads.cpp). Partials past one storage block are summed a window of
// chunks at a time: the partials bound from chunk uFirstChunk on.
#include "water/loads_bindings.glsl"

layout(local_size_x = LOADS_SUM_GROUP_SIZE) in;

layout(std430, binding = LOADS_PARTIALS) readonly buffer Loads { vec4 loads[]; };
layout(std430, binding = LOADS_SUMS) writeonly buffer Sums { vec4 sums[]; };

uniform uint uGroups;      // the measuring kernel's work groups in the bound partials
uniform uint uFirstChunk;  // the first chunk bound
uniform uint uChunkGroups; // the measuring kernel's work groups per chunk
uniform uint uSumsFirst;   // the walls' first vec4 in the sums

#include "water/pair_sum.glsl"

void main() {
  const uint chunk = gl_WorkGroupID.x, t = gl_LocalInvocationIndex;
  const uint end = min(uGroups, (chunk + 1u) * uChunkGroups);
  vec4 low = vec4(0.0), high = vec4(0.0);
  for (uint g = chunk * uChunkGroups + t; g < end; g += uint(LOADS_SUM_GROUP_SIZE)) {
    low += loads[2u * g];
    high += loads[2u * g + 1u];
  }
  sumPairs(low, high);
  if (t == 0u) {
    const uint at = uSumsFirst + 2u * (uFirstChunk + chunk);
    sums[at] = sPairA[0];
    sums[at + 1u] = sPairB[0];
  }
}
