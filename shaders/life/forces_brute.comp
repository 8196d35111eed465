#version 430 core
// Reference for benchmarks: the life forces by brute force over all N^2 pairs, tiled through
// shared memory (each work group loads LIFE_BRUTE_TILE positions at a time and every invocation
// reads them from there). Same force law and minimum image as forces.comp, no grid.
#include "life/bindings.glsl"
layout(local_size_x = LIFE_BRUTE_TILE) in;
#include "common/index.glsl"
#include "life/box.glsl"
#include "life/pair_force.glsl"
#include "life/state.glsl"

layout(std430, binding = LIFE_POSITIONS) readonly buffer Positions { LifePosition positions[]; };
layout(std430, binding = LIFE_ACCELERATIONS) writeonly buffer Accelerations { vec2 accelerations[]; };
layout(std430, binding = LIFE_FORCE_TABLE) readonly buffer ForceTable { vec4 forceTable[]; };

uniform uint uCount;
uniform uint uSpecies;
uniform float uCentralForce;

shared vec4 sTile[LIFE_BRUTE_TILE];

void main() {
  const uint i = globalIndex();
  const vec4 pi = unpackPosition(positions[min(i, uCount - 1u)]);
  const uint row = uint(pi.w) * uSpecies;
  vec2 force = -uCentralForce * pi.xy;
  for (uint base = 0u; base < uCount; base += LIFE_BRUTE_TILE) {
    const uint k = base + gl_LocalInvocationID.x;
    sTile[gl_LocalInvocationID.x] = k < uCount ? unpackPosition(positions[k]) : vec4(0.0);
    barrier();
    const uint n = min(uint(LIFE_BRUTE_TILE), uCount - base);
    for (uint t = 0u; t < n; ++t) {
      const vec4 pj = sTile[t];
      vec4 a;
      float b;
      shapePair(forceTable[row + uint(pj.w)], a, b);  // from the cache: the table is tiny
      if (base + t != i) force += pairForce(boxDelta(pi.xy, pj.xy), a, b);
    }
    barrier();
  }
  if (i < uCount) accelerations[i] = force;
}
