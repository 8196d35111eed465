#version 430 core
// Divergence watch of particle life (src/sim/life/life.h): particles whose position or velocity
// is NaN or infinite, and the largest speed, reduced in shared memory so that each work group
// makes one global atomic of each kind. Non-negative floats order like their bit patterns.
#include "life/bindings.glsl"
layout(local_size_x = 256) in;
#include "common/index.glsl"
#include "life/state.glsl"

layout(std430, binding = LIFE_POSITIONS) readonly buffer Positions { LifePosition positions[]; };
layout(std430, binding = LIFE_VELOCITIES) readonly buffer Velocities { LifeVelocity velocities[]; };
layout(std430, binding = LIFE_HEALTH) buffer Health {
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
    const vec2 p = unpackPosition(positions[i]).xy, v = unpackVelocity(velocities[i]).xy;
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
