#version 430 core
// Divergence watch of the balls: non-finite balls, the largest speed, balls outside the walls,
// reduced in shared memory so each work group makes one global atomic of each kind.
#include "balls/bindings.glsl"

layout(local_size_x = 128) in;
#include "common/index.glsl"

layout(std430, binding = BALLS_POS_IN) readonly buffer PosIn { vec4 posIn[]; };
layout(std430, binding = BALLS_VEL_IN) readonly buffer VelIn { vec4 velIn[]; };
layout(std430, binding = BALLS_STATS) buffer Health {
  uint nonFinite;
  uint maxSpeedBits;  // floatBitsToUint of a non-negative float orders like the float
  uint outside;
  uint unused;
};
uniform uint uCount;
uniform vec3 uWallMin;
uniform vec3 uWallMax;

shared uint sBad, sMax, sOut;

void main() {
  if (gl_LocalInvocationIndex == 0u) {
    sBad = 0u;
    sMax = 0u;
    sOut = 0u;
  }
  barrier();
  const uint i = globalIndex();
  if (i < uCount) {
    const vec3 p = posIn[i].xyz, v = velIn[i].xyz;
    if (any(isnan(p)) || any(isinf(p)) || any(isnan(v)) || any(isinf(v))) {
      atomicAdd(sBad, 1u);
    } else {
      atomicMax(sMax, floatBitsToUint(length(v)));
      if (any(lessThan(p, uWallMin - 1e-6)) || any(greaterThan(p, uWallMax + 1e-6))) atomicAdd(sOut, 1u);
    }
  }
  barrier();
  if (gl_LocalInvocationIndex == 0u) {
    if (sBad > 0u) atomicAdd(nonFinite, sBad);
    atomicMax(maxSpeedBits, sMax);
    if (sOut > 0u) atomicAdd(outside, sOut);
  }
}
