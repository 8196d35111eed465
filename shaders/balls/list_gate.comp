#version 430 core
// Verlet lists, before each step's forces: rebuild the lists (and the grid they come from) when
// the balls may have come closer than the lists know. A pair left out at the build lay at least
// 2r + skin apart; since then each ball moved by d_i, so the pair is at least 2r + skin − |d_i − d_j|
// apart, and |d_i − d_j| is at most the diagonal of the box of all displacements (so a block
// falling as one, or sloshing side by side, does not count). Rebuild when that diagonal reaches
// the skin, on the CPU's word (new balls, a restore) or after an overflow. One work group.
#include "balls/bindings.glsl"

layout(local_size_x = 64) in;
#include "balls/lists.glsl"
#include "common/dispatch_gate.glsl"

uniform float uSkin;   // m
uniform uint uForce;   // 1: rebuild regardless

shared bool sOpen;

void main() {
  const uint t = gl_LocalInvocationIndex;
  if (t == 0u) {
    uvec3 lo = uvec3(0xffffffffu), hi = uvec3(0u);
    for (uint s = 0u; s < uint(BALLS_LIST_SLOTS); ++s)
      for (int c = 0; c < 3; ++c) {
        lo[c] = min(lo[c], lists[uControl + s * 6u + uint(c)]);
        hi[c] = max(hi[c], lists[uControl + s * 6u + 3u + uint(c)]);
      }
    float diagonal = 0.0;
    if (all(lessThanEqual(lo, hi))) {  // else: no ball was added (an empty step)
      const vec3 a = vec3(orderedFloat(lo.x), orderedFloat(lo.y), orderedFloat(lo.z));
      const vec3 b = vec3(orderedFloat(hi.x), orderedFloat(hi.y), orderedFloat(hi.z));
      diagonal = length(b - a);
    }
    // NaN displacements fail the comparison: rebuild (the watch reports the blow-up).
    const bool open = uForce != 0u || lists[uControl + BALLS_LIST_OVERFLOW] != 0u || !(diagonal < 0.999 * uSkin);
    if (open) {
      lists[uControl + BALLS_LIST_REBUILDS] += 1u;
      lists[uControl + BALLS_LIST_OVERFLOW] = 0u;  // the build counts again
    }
    lists[uControl + BALLS_LIST_STEPS] += 1u;
    sOpen = open;
  }
  barrier();
  memoryBarrierShared();
  writeGateArgs(sOpen);
  for (uint w = t; w < uint(BALLS_LIST_SLOTS) * 6u; w += gl_WorkGroupSize.x)
    lists[uControl + w] = w % 6u < 3u ? 0xffffffffu : 0u;  // each step measures from the build again
}
