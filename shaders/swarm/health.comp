#version 430 core
// Divergence watch of the swarm (src/sim/swarm/swarm.h): particles whose position or velocity
// is NaN or infinite (fp16 storage overflows to infinity past 65504), and the largest speed.
#include "swarm/bindings.glsl"
layout(local_size_x = SWARM_WORK_GROUP) in;
#include "common/index.glsl"
#include "common/health.glsl"
#include "swarm/state.glsl"

void checkHealth(uint i) {
  vec2 p, v;
  loadParticle(i, p, v);
  if (isFinite(p) && isFinite(v))
    healthMax(length(v));
  else
    healthNonFinite();
}
