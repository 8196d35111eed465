// The neighbours of a fluid particle at p: every particle in the 27 cells (of size h) around it,
// itself included (r = 0), and, with HAS_OBSTACLE, every obstacle particle within h found through
// the obstacles' own grid (cells of one spacing, so uObstacleReach cells each way). The including
// kernel declares the cell-ordered array the positions come from as `neighbourPos[]` (a #define)
// and, before including this file,
//   void onFluid(uint j, vec3 r, float r2);      // r = p − p_j, r2 = |r|² < h²
//   void onBoundary(vec3 r, float r2, float volume);  // an obstacle particle within h
#ifndef FLUID_NEIGHBOURS_GLSL
#define FLUID_NEIGHBOURS_GLSL

#include "common/grid.glsl"

layout(std430, binding = FLUID_CELL_START) readonly buffer CellStart { uint cellStart[]; };

void forEachFluid(vec3 p) {
  const float h2 = uH * uH;
  const ivec3 c = cellCoord(p);
  // Cells are numbered x fastest: the three cells x-1..x+1 of a row are one contiguous run.
  const int x0 = max(c.x - 1, 0), x1 = min(c.x + 1, int(uGridDims.x) - 1);
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy) {
      const ivec3 row = ivec3(x0, c.y + dy, c.z + dz);
      if (!cellInGrid(row)) continue;
      const uint first = cellIndex(row);
      const uint end = cellStart[first + uint(x1 - x0) + 1u];
      for (uint j = cellStart[first]; j < end; ++j) {
        const vec3 r = p - neighbourPos[j].xyz;
        const float r2 = dot(r, r);
        if (r2 < h2) onFluid(j, r, r2);
      }
    }
}

#ifdef HAS_OBSTACLE
layout(std430, binding = FLUID_OBST_POS) readonly buffer ObstaclePos { vec4 obstaclePos[]; };
layout(std430, binding = FLUID_OBST_CELL_START) readonly buffer ObstacleCellStart { uint obstacleCellStart[]; };
#ifdef OBSTACLE_VOLUMES
layout(std430, binding = FLUID_OBST_VOLUME) readonly buffer ObstacleVolume { vec4 obstacleVolume[]; };
#endif
uniform vec3 uObstacleOrigin;  // obstacle grid (world)
uniform float uObstacleInvCell;
uniform uvec3 uObstacleDims;
uniform int uObstacleReach;  // cells each way that cover h

// Obstacle particles within `reach` (≤ h) of p.
void forEachBoundary(vec3 p, float reach) {
  const vec3 g = (p - uObstacleOrigin) * uObstacleInvCell;
  const float span = float(uObstacleReach);
  if (any(lessThan(g, vec3(-span))) || any(greaterThan(g, vec3(uObstacleDims) + span))) return;
  const ivec3 last = ivec3(uObstacleDims) - 1;
  const ivec3 oc = clamp(ivec3(floor(g)), ivec3(0), last);
  const int ox0 = max(oc.x - uObstacleReach, 0), ox1 = min(oc.x + uObstacleReach, last.x);
  const float reach2 = reach * reach;
  for (int dz = -uObstacleReach; dz <= uObstacleReach; ++dz)
    for (int dy = -uObstacleReach; dy <= uObstacleReach; ++dy) {
      const ivec3 row = ivec3(ox0, oc.y + dy, oc.z + dz);
      if (row.y < 0 || row.z < 0 || row.y > last.y || row.z > last.z) continue;
      const uint first = uint(row.x) + uObstacleDims.x * (uint(row.y) + uObstacleDims.y * uint(row.z));
      const uint end = obstacleCellStart[first + uint(ox1 - ox0) + 1u];
      for (uint j = obstacleCellStart[first]; j < end; ++j) {
        const vec3 r = p - obstaclePos[j].xyz;
        const float r2 = dot(r, r);
        if (r2 >= reach2) continue;
#ifdef OBSTACLE_VOLUMES
        onBoundary(r, r2, obstacleVolume[j].x);
#else
        onBoundary(r, r2, uVolume);  // solid obstacles at the fluid's spacing: a fluid particle's volume
#endif
      }
    }
}
#endif

#endif
