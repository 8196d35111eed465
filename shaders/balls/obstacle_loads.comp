#version 430 core
// The loads of the balls on the obstacles (water/obstacle_loads.glsl): for each obstacle particle
// b, the acceleration it gave each ball within 2r, as the step's collide summed it from the same
// inputs (the cell-ordered positions and velocities), and its moment about b's obstacle's centre
// taken at the contact's midpoint, so that the obstacle felt F = −m Σa. The balls come from the
// 27 grid cells around b, in the grid's order; with windows (src/gl/window.h), each dispatch adds
// the balls of its window [uFirst, uCount), so the sums add up in the same order as without.
#include "balls/bindings.glsl"

layout(local_size_x = BALLS_GROUP_SIZE) in;
#include "common/index.glsl"
#include "common/grid.glsl"

layout(std430, binding = BALLS_POS_IN) readonly buffer PosIn { vec4 posIn[]; };
layout(std430, binding = BALLS_VEL_IN) readonly buffer VelIn { vec4 velIn[]; };
layout(std430, binding = BALLS_CELL_START) readonly buffer CellStart { uint cellStart[]; };

uniform float uRadius;      // m
uniform uint uSourceFirst;  // the first ball of the inputs' window
uniform uint uFirst;        // the balls this dispatch counts: [uFirst, uCount)
uniform uint uCount;

#include "balls/contact.glsl"
#define PLACED_BINDING BALLS_OBSTACLE_PLACED
#define SHARES_BINDING BALLS_SHARES
#define MOMENTS_BINDING BALLS_MOMENTS
#include "water/obstacle_loads.glsl"

void main() {
  uint b, k;
  vec3 at;
  if (!obstacleParticle(b, at, k)) return;
  const vec3 velocity = obstacleVelocity(k, at), centre = poseCentre[k].xyz;
  const float reach = 2.0 * uRadius;
  vec3 share, moment;
  startShares(b, share, moment);
  const ivec3 c = cellCoord(at);
  const int x0 = max(c.x - 1, 0), x1 = min(c.x + 1, int(uGridDims.x) - 1);
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy) {
      const ivec3 row = ivec3(x0, c.y + dy, c.z + dz);
      if (!cellInGrid(row)) continue;
      const uint first = cellIndex(row);
      const uint end = min(cellStart[first + uint(x1 - x0) + 1u], uCount);
      for (uint i = max(cellStart[first], uFirst); i < end; ++i) {
        const vec3 p = posIn[i - uSourceFirst].xyz, d = p - at;
        const float dist2 = dot(d, d);
        if (dist2 >= reach * reach || dist2 == 0.0) continue;
        const float dist = sqrt(dist2);
        const vec3 a = contactAccel(d / dist, reach - dist, velIn[i - uSourceFirst].xyz - velocity, 1.0, 1.0);
        share += a;
        moment += cross(0.5 * (p + at) - centre, a);
      }
    }
  storeShares(b, share, moment);
}
