#version 430 core
// Divergence watch of particle life (src/sim/life/life.h): particles whose position or velocity
// is NaN or infinite, and the largest speed (world units/s).
#include "life/bindings.glsl"
layout(local_size_x = 256) in;
#include "common/index.glsl"
#include "common/health.glsl"
#include "life/state.glsl"

layout(std430, binding = LIFE_POSITIONS) readonly buffer Positions { LifePosition positions[]; };
layout(std430, binding = LIFE_VELOCITIES) readonly buffer Velocities { LifeVelocity velocities[]; };

void checkHealth(uint i) {
  const vec2 p = unpackPosition(positions[i]).xy, v = unpackVelocity(velocities[i]).xy;
  if (isFinite(p) && isFinite(v))
    healthMax(length(v));
  else
    healthNonFinite();
}
