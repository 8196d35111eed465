// The obstacle particles near a fluid particle, for the kernels that sum boundaries (λ, Δp and
// the statistics): with HAS_OBSTACLE, every obstacle particle within a reach ≤ h of p, found
// through the obstacles' own grid (cells of one spacing, so uObstacleReach cells each way), each
// with its rest volume (OBSTACLE_VOLUMES) or a fluid particle's. Kernels that need no boundary
// (XSPH, vorticity, the neighbour list) do not include it, which keeps them within GL 4.3's eight
// storage blocks. The including kernel defines, before including this file,
//   void onBoundary(vec3 r, float r2, float volume);  // r = p − p_b, r2 = |r|² < reach²
#ifndef FLUID_BOUNDARY_GLSL
#define FLUID_BOUNDARY_GLSL

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
