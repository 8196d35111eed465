#version 430 core
// Splat of the water-surface mesher (src/render/surface_mesher.h): each particle adds its kernel
// W = (1 - d²/h²)³ (d < h) to the grid corners within h, scaled so that water at rest sums to 1.
// A splat, not a gather over the model's particle grid: it reads only the positions (any model,
// any order) and needs no cell lists sized for the surface's kernel. GL 4.3 has no float
// atomics, so each weight is rounded to fixed point (SURFACE_FIXED_ONE per 1) and added with
// atomicAdd on uint: integer sums do not depend on the order, so the grid is the same bit for bit
// on every run (the CPU twin in tests/reference/surface_reference.cpp rounds the same way).
layout(local_size_x = 128) in;
#include "common/index.glsl"
#include "surface/cube.glsl"

layout(std430, binding = SURFACE_POSITIONS) readonly buffer Positions { vec4 positions[]; };
layout(std430, binding = SURFACE_DENSITY) buffer Density { uint density[]; };

uniform uint uCount;       // particles
uniform float uReach;      // h / cell: the kernel's reach in cells
uniform float uInvH2;      // 1 / h², 1/m²
uniform float uWeightOne;  // fixed-point units of a kernel peak (W = 1)

void main() {
  const uint i = globalIndex();
  if (i >= uCount) return;
  const vec3 g = (positions[i].xyz - uOrigin) / uCell;  // in cells
  if (any(isnan(g)) || any(isinf(g))) return;
  // Interior corners only: the shell reads as 0 anyway (cube.glsl). Clamped as floats, so a
  // particle flung far away converts to no loop rather than to an overflowed int.
  const vec3 top = vec3(uCorners) - 2.0;
  const ivec3 lo = ivec3(clamp(ceil(g - uReach), vec3(1.0), top + 1.0));
  const ivec3 hi = ivec3(clamp(floor(g + uReach), vec3(0.0), top));
  for (int z = lo.z; z <= hi.z; ++z)
    for (int y = lo.y; y <= hi.y; ++y)
      for (int x = lo.x; x <= hi.x; ++x) {
        const vec3 d = (vec3(x, y, z) - g) * uCell;
        const float q2 = dot(d, d) * uInvH2;
        if (q2 >= 1.0) continue;
        const float w = (1.0 - q2) * (1.0 - q2) * (1.0 - q2);
        atomicAdd(density[cornerIndex(ivec3(x, y, z))], uint(w * uWeightOne + 0.5));
      }
}
