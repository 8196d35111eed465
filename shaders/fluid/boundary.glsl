// The obstacle particles near a fluid particle, for the kernels that sum boundaries (λ, Δp and
// the statistics): with HAS_OBSTACLE, every obstacle particle within a reach ≤ h of p, found
// through the obstacles' own grid (common/obstacle_grid.glsl; cells of one spacing, so
// uObstacleReach cells each way), each with its rest volume (OBSTACLE_VOLUMES) or a fluid
// particle's. The including kernel defines, before including this file,
//   void onBoundary(vec3 r, float r2, float volume, uint k);  // r = p − p_b, r2 = |r|² < reach²,
//                                                             // k = p_b's obstacle
#ifndef FLUID_BOUNDARY_GLSL
#define FLUID_BOUNDARY_GLSL

#ifdef HAS_OBSTACLE
#include "common/obstacle_bindings.glsl"
#ifdef OBSTACLE_VOLUMES
layout(binding = OBSTACLE_VOLUME_UNIT) uniform samplerBuffer obstacleVolume;  // x = m³
#endif
uniform int uObstacleReach;  // cells each way that cover h

vec3 gBoundaryP;
float gBoundaryReach2;
void onObstacleParticle(uint j, vec4 q) {
  const vec3 r = gBoundaryP - q.xyz;
  const float r2 = dot(r, r);
  if (r2 >= gBoundaryReach2) return;
#ifdef OBSTACLE_VOLUMES
  onBoundary(r, r2, texelFetch(obstacleVolume, int(j)).x, uint(q.w));
#else
  onBoundary(r, r2, uVolume, uint(q.w));  // solid obstacles at the fluid's spacing: a fluid particle's volume
#endif
}
#include "common/obstacle_grid.glsl"

// Obstacle particles within `reach` (≤ h) of p.
void forEachBoundary(vec3 p, float reach) {
  gBoundaryP = p;
  gBoundaryReach2 = reach * reach;
  forEachObstacleParticle(p, uObstacleReach);
}
#endif

#endif
