// Access to the Verlet neighbour lists (balls/list_layout.glsl) for the kernels that build, use
// and gate them: the block, its geometry uniforms, and the displacement box each step adds to.
#ifndef BALLS_LISTS_GLSL
#define BALLS_LISTS_GLSL

#include "balls/list_layout.glsl"

// The kernels that include this file run in list mode (LISTS): binding 6 holds the lists.
#ifndef LISTS
#define LISTS
#endif
#include "balls/shared_slots.glsl"  // uint lists[], coherent
uniform uint uListStride;    // words per column (the balls' capacity)
uniform uint uListCapacity;  // neighbours a ball's list holds
uniform uint uControl;       // word of the control words

uint listEntry(uint column, uint i) { return column * uListStride + i; }

// Floats as uints whose unsigned order is the floats' order (atomicMin/Max on floats).
uint orderedBits(float f) {
  const uint u = floatBitsToUint(f);
  return (u & 0x80000000u) != 0u ? ~u : (u | 0x80000000u);
}
float orderedFloat(uint o) { return uintBitsToFloat((o & 0x80000000u) != 0u ? (o & 0x7fffffffu) : ~o); }

// The box of this step's displacements, per work group in shared memory, then into one of the
// slots (a few thousand groups share each slot's atomics, not millions of balls one word).
// Every invocation of the group calls begin and end (they hold barriers).
shared uint sBox[6];
void displacementBoxBegin() {
  if (gl_LocalInvocationIndex < 6u) sBox[gl_LocalInvocationIndex] = gl_LocalInvocationIndex < 3u ? 0xffffffffu : 0u;
  barrier();
}
void displacementBoxAdd(uint i, vec3 x) {
  const vec3 origin = vec3(uintBitsToFloat(lists[listEntry(0u, i)]), uintBitsToFloat(lists[listEntry(1u, i)]),
                           uintBitsToFloat(lists[listEntry(2u, i)]));
  const vec3 d = x - origin;
  for (int c = 0; c < 3; ++c) {
    atomicMin(sBox[c], orderedBits(d[c]));
    atomicMax(sBox[3 + c], orderedBits(d[c]));
  }
}
void displacementBoxEnd(uint group) {
  barrier();
  const uint k = gl_LocalInvocationIndex;
  if (k >= 6u) return;
  const uint word = uControl + (group % uint(BALLS_LIST_SLOTS)) * 6u + k;
  if (k < 3u)
    atomicMin(lists[word], sBox[k]);
  else
    atomicMax(lists[word], sBox[k]);
}

#endif
