#version 430 core
// Swarm reset: positions uniform in the NDC box [-1,1]^2 from a hash of (index, seed); v = 0.
#include "swarm/bindings.glsl"
layout(local_size_x = SWARM_WORK_GROUP) in;
#include "common/index.glsl"
#include "common/random.glsl"
#include "swarm/state.glsl"

uniform uint uCount;
uniform uint uSeed;

void main() {
  const uint i = globalIndex();
  if (i >= uCount) return;
  const uint h = pcgHash(i ^ pcgHash(uSeed));
  const vec2 pos = 2.0 * vec2(random01(h), random01(h ^ 0x9E3779B9u)) - 1.0;
  storeParticle(i, pos, vec2(0.0));
}
