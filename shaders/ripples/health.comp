#version 430 core
// Divergence watch: the largest |h| and |v| and the count of non-finite values over the grid,
// reduced in shared memory first so that each work group makes one global atomic of each kind.
// Non-negative floats order like their bit patterns, so atomicMax works on floatBitsToUint.
#include "ripples/bindings.glsl"

layout(local_size_x = 256) in;
#include "common/index.glsl"

layout(std430, binding = RIPPLES_STATE_IN) readonly buffer State { vec2 state[]; };
layout(std430, binding = RIPPLES_HEALTH) buffer Health {
  uint maxHeightBits;
  uint maxVelocityBits;
  uint nonFinite;
  uint unused;
};
uniform uint uCells;

shared uint sMaxH, sMaxV, sBad;

void main() {
  if (gl_LocalInvocationIndex == 0u) {
    sMaxH = 0u;
    sMaxV = 0u;
    sBad = 0u;
  }
  barrier();
  const uint i = globalIndex();
  if (i < uCells) {
    const vec2 s = state[i];
    if (any(isnan(s)) || any(isinf(s))) {
      atomicAdd(sBad, 1u);
    } else {
      atomicMax(sMaxH, floatBitsToUint(abs(s.x)));
      atomicMax(sMaxV, floatBitsToUint(abs(s.y)));
    }
  }
  barrier();
  if (gl_LocalInvocationIndex == 0u) {
    atomicMax(maxHeightBits, sMaxH);
    atomicMax(maxVelocityBits, sMaxV);
    if (sBad > 0u) atomicAdd(nonFinite, sBad);
  }
}
