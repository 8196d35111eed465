// The obstacles' fixed particles as kernels find them (src/sim/balls/obstacles.h): placed in the
// world this step and sorted into a grid of their own, read through buffer textures (kernels
// include it only for scenes with obstacles: HAS_OBSTACLE).
// The including kernel defines, before including this file,
//   void onObstacleParticle(uint j, vec4 q);  // q: world position (m), w = obstacle index
#ifndef COMMON_OBSTACLE_GRID_GLSL
#define COMMON_OBSTACLE_GRID_GLSL

#include "common/obstacle_bindings.glsl"

layout(binding = OBSTACLE_POS_UNIT) uniform samplerBuffer obstaclePos;
layout(binding = OBSTACLE_CELL_START_UNIT) uniform usamplerBuffer obstacleCellStart;
uniform vec3 uObstacleOrigin;  // the obstacle grid (world)
uniform float uObstacleInvCell;
uniform uvec3 uObstacleDims;

// Every obstacle particle in the cells within `span` cells of p's. Cells are numbered x fastest,
// so each row of cells x − span .. x + span holds one contiguous run of particles.
void forEachObstacleParticle(vec3 p, int span) {
  const vec3 g = (p - uObstacleOrigin) * uObstacleInvCell;
  if (any(lessThan(g, vec3(-span))) || any(greaterThan(g, vec3(uObstacleDims) + float(span)))) return;
  const ivec3 last = ivec3(uObstacleDims) - 1;
  const ivec3 c = clamp(ivec3(floor(g)), ivec3(0), last);
  const int x0 = max(c.x - span, 0), x1 = min(c.x + span, last.x);
  for (int dz = -span; dz <= span; ++dz)
    for (int dy = -span; dy <= span; ++dy) {
      const ivec3 row = ivec3(x0, c.y + dy, c.z + dz);
      if (row.y < 0 || row.z < 0 || row.y > last.y || row.z > last.z) continue;
      const int first = row.x + int(uObstacleDims.x) * (row.y + int(uObstacleDims.y) * row.z);
      const uint end = texelFetch(obstacleCellStart, first + x1 - x0 + 1).x;
      for (uint j = texelFetch(obstacleCellStart, first).x; j < end; ++j)
        onObstacleParticle(j, texelFetch(obstaclePos, int(j)));
    }
}

#endif
