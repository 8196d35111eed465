// Every contact of the ball at p: the other balls within 2r in the 27 surrounding cells of the
// uniform grid, and the obstacles' fixed particles, placed in the world this step and found
// through their own grid (common/obstacle_grid.glsl); each moves with its obstacle
// (obstacle_poses.glsl, index k in w).
// The including kernel declares the cell-ordered posIn[] and velIn[] buffers and
//   void onContact(vec3 n, float overlap, vec3 otherVelocity, float massRatio, float share);
// before including this file (n points from the other body to the ball, world frame).
#ifndef BALLS_NEIGHBOURS_GLSL
#define BALLS_NEIGHBOURS_GLSL

#include "common/grid.glsl"

layout(std430, binding = BALLS_CELL_START) readonly buffer CellStart { uint cellStart[]; };

uniform float uRadius;  // m
// The first ball of the window posIn[] and velIn[] are bound from (src/gl/window.h): 0 when they
// fit one storage block.
uniform uint uSourceFirst;

// Candidate j at q: a contact when closer than reach. The ball itself (d = 0) is skipped by the
// distance test rather than by comparing indices: one test fewer per candidate made the collide
// pass 13% faster on the H100 (docs/ARCHITECTURE.md, "Rejected designs").
void candidate(uint j, vec3 p, vec3 q, float reach) {
  const vec3 d = p - q;
  const float dist2 = dot(d, d);
  if (dist2 >= reach * reach || dist2 == 0.0) return;  // itself, or coincident: no normal
  const float dist = sqrt(dist2);
  onContact(d / dist, reach - dist, velIn[j].xyz, 0.5, 0.5);
}

// Every ball within reach, from the 27 cells around p (the cells are at least 2r).
void forEachGridContact(vec3 p, float reach) {
  const ivec3 c = cellCoord(p);
  // Cells are numbered x fastest, so the three cells x-1..x+1 of a row hold one contiguous run
  // of balls: 9 runs instead of 27 cells (fewer cellStart reads and loop heads).
  const int x0 = max(c.x - 1, 0), x1 = min(c.x + 1, int(uGridDims.x) - 1);
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy) {
      const ivec3 row = ivec3(x0, c.y + dy, c.z + dz);
      if (!cellInGrid(row)) continue;
      const uint first = cellIndex(row);
      const uint end = cellStart[first + uint(x1 - x0) + 1u] - uSourceFirst;
      for (uint j = cellStart[first] - uSourceFirst; j < end; ++j) candidate(j, p, posIn[j].xyz, reach);
    }
}

#ifdef HAS_OBSTACLE
// Scenes with obstacles only: compiled into every kernel, the search made the collide 12–15%
// slower on obstacle-free scenes (docs/ARCHITECTURE.md, "Rejected designs").
#include "balls/obstacle_poses.glsl"

// An obstacle particle at q.xyz of obstacle q.w, within reach of the ball at gContactPos.
vec3 gContactPos;
float gContactReach;
void onObstacleParticle(uint j, vec4 q) {
  const vec3 d = gContactPos - q.xyz;
  const float dist2 = dot(d, d);
  if (dist2 >= gContactReach * gContactReach || dist2 == 0.0) return;
  const float dist = sqrt(dist2);
  onContact(d / dist, gContactReach - dist, obstacleVelocity(uint(q.w), q.xyz), 1.0, 1.0);
}
#include "common/obstacle_grid.glsl"
#endif

// Ball i at p: every ball within 2r, then every obstacle particle (the obstacle grid's cells are
// 2r: the 27 around p's).
void forEachContact(uint i, vec3 p) {
  const float reach = 2.0 * uRadius;
  forEachGridContact(p, reach);
#ifdef HAS_OBSTACLE
  gContactPos = p;
  gContactReach = reach;
  forEachObstacleParticle(p, 1);
#endif
}

#endif
