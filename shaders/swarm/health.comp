#version 430 core
// Divergence watch of the swarm (src/sim/swarm/swarm.h): particles whose position or velocity
// is NaN or infinite (fp16 storage overflows to infinity past 65504), and the largest speed,
// reduced in shared memory so that each work group makes one global atomic of each kind.
// Non-negative floats order like their bit patterns, so atomicMax works on floatBitsToUint.
layout(local_size_x = 256) in;
#include "common/index.glsl"
#include "swarm/bindings.glsl"
#include "swarm/state.glsl"

layout(std430, binding = SWARM_HEALTH_BINDING) buffer Health {
  uint nonFinite;
  uint maxSpeedBits;  // floatBitsToUint of the largest |v| (world units/s)
  uint unused[2];
};
uniform uint uCount;

shared uint sBad, sMax;

void main() {
  if (gl_LocalInvocationIndex == 0u) {
    sBad = 0u;
    sMax = 0u;
  }
  barrier();
  const uint i = globalIndex();
  if (i < uCount) {
    vec2 p, v;
    loadParticle(i, p, v);
    if (any(isnan(p)) || any(isinf(p)) || any(isnan(v)) || any(isinf(v)))
      atomicAdd(sBad, 1u);
    else
      atomicMax(sMax, floatBitsToUint(length(v)));
  }
  barrier();
  if (gl_LocalInvocationIndex == 0u) {
    if (sBad > 0u) atomicAdd(nonFinite, sBad);
    atomicMax(maxSpeedBits, sMax);
  }
}
