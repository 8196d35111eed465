// Every contact of ball `self` at p: the other balls within 2r in the 27 surrounding cells of the
// uniform grid, and the obstacle's fixed particles, found in the obstacle's own (spinning) frame
// through its own grid. The including kernel declares
//   void onContact(vec3 n, float overlap, vec3 otherVelocity, float massRatio, float share);
// before including this file (n points from the other body to the ball, world frame).
#ifndef BALLS_NEIGHBOURS_GLSL
#define BALLS_NEIGHBOURS_GLSL

#include "common/grid.glsl"

layout(std430, binding = BALLS_CELL_START) readonly buffer CellStart { uint cellStart[]; };
#ifdef HAS_OBSTACLE
layout(std430, binding = BALLS_OBST_POS) readonly buffer ObstaclePos { vec4 obstaclePos[]; };
layout(std430, binding = BALLS_OBST_CELL_START) readonly buffer ObstacleCellStart { uint obstacleCellStart[]; };
uniform vec3 uObstacleOrigin;      // obstacle grid, in the obstacle's frame
uniform float uObstacleInvCell;
uniform uvec3 uObstacleDims;
uniform vec3 uObstaclePivot;       // spin axis (vertical) passes through it, m
uniform vec2 uObstacleRotation;    // cos, sin of the current spin angle
uniform float uObstacleSpin;       // rad/s
#endif

uniform float uRadius;  // m

void forEachContact(uint self, vec3 p, vec3 v) {
  const float reach = 2.0 * uRadius;
  const ivec3 c = cellCoord(p);
  // Cells are numbered x fastest, so the three cells x-1..x+1 of a row hold one contiguous run
  // of balls: 9 runs instead of 27 cells (fewer cellStart reads and loop heads).
  const int x0 = max(c.x - 1, 0), x1 = min(c.x + 1, int(uGridDims.x) - 1);
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy) {
      const ivec3 row = ivec3(x0, c.y + dy, c.z + dz);
      if (!cellInGrid(row)) continue;
      const uint first = cellIndex(row);
      const uint end = cellStart[first + uint(x1 - x0) + 1u];
      for (uint j = cellStart[first]; j < end; ++j) {
        if (j == self) continue;
        const vec3 d = p - posIn[j].xyz;
        const float dist2 = dot(d, d);
        if (dist2 >= reach * reach || dist2 == 0.0) continue;  // coincident balls have no normal
        const float dist = sqrt(dist2);
        onContact(d / dist, reach - dist, velIn[j].xyz, 0.5, 0.5);
      }
    }
#ifdef HAS_OBSTACLE
  // The ball in the obstacle's frame: rotate by −angle about the vertical axis through the pivot.
  const vec2 cs = uObstacleRotation;
  const vec2 rel = p.xy - uObstaclePivot.xy;
  const vec3 local = vec3(uObstaclePivot.xy + vec2(cs.x * rel.x + cs.y * rel.y, -cs.y * rel.x + cs.x * rel.y), p.z);
  const vec3 bodyVelocity = uObstacleSpin * vec3(-rel.y, rel.x, 0.0);
  const ivec3 last = ivec3(uObstacleDims) - 1;
  const ivec3 oc = clamp(ivec3(clamp(floor((local - uObstacleOrigin) * uObstacleInvCell), vec3(0.0), vec3(last))),
                         ivec3(0), last);
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const ivec3 nc = oc + ivec3(dx, dy, dz);
        if (any(lessThan(nc, ivec3(0))) || any(greaterThan(nc, last))) continue;
        const uint cell = uint(nc.x) + uObstacleDims.x * (uint(nc.y) + uObstacleDims.y * uint(nc.z));
        const uint end = obstacleCellStart[cell + 1u];
        for (uint j = obstacleCellStart[cell]; j < end; ++j) {
          const vec3 d = local - obstaclePos[j].xyz;
          const float dist2 = dot(d, d);
          if (dist2 >= reach * reach || dist2 == 0.0) continue;
          const float dist = sqrt(dist2);
          const vec3 nLocal = d / dist;
          const vec3 n = vec3(cs.x * nLocal.x - cs.y * nLocal.y, cs.y * nLocal.x + cs.x * nLocal.y, nLocal.z);
          onContact(n, reach - dist, bodyVelocity, 1.0, 1.0);
        }
      }
#endif
}

#endif
