#version 430 core
// Divergence watch of the ripples (src/sim/ripples/ripples.h): cells whose height or velocity is
// NaN or infinite, and the largest |h|.
#include "ripples/bindings.glsl"

layout(local_size_x = 256) in;
#include "common/index.glsl"
#include "common/health.glsl"

layout(std430, binding = RIPPLES_STATE_IN) readonly buffer State { vec2 state[]; };

void checkHealth(uint i) {
  const vec2 s = state[i];
  if (isFinite(s))
    healthMax(abs(s.x));
  else
    healthNonFinite();
}
