#version 430 core
// Verlet lists: each ball's neighbours within 2r + skin, from the grid just built (cells of
// 2r + skin, so 27 cells hold them all). The balls were just moved into the grid's order, so each
// cell's balls are contiguous, as in the grid path's collide, and the stable grid's order makes
// the lists, and so the sums over them, the same on every run. Between builds the balls stay
// where they are in memory; the lists hold their indices.
#include "balls/bindings.glsl"

layout(local_size_x = BALLS_GROUP_SIZE) in;
#include "common/index.glsl"
#include "common/grid.glsl"
#include "balls/lists.glsl"

layout(std430, binding = BALLS_POS_IN) readonly buffer PosIn { vec4 posIn[]; };
layout(std430, binding = BALLS_CELL_START) readonly buffer CellStart { uint cellStart[]; };

uniform uint uCount;
uniform float uListReach;  // 2r + skin, m

void main() {
  const uint i = globalIndex();
  if (i >= uCount) return;
  const vec3 p = posIn[i].xyz;
  const float reach2 = uListReach * uListReach;
  uint n = 0u;
  const ivec3 c = cellCoord(p);
  const int x0 = max(c.x - 1, 0), x1 = min(c.x + 1, int(uGridDims.x) - 1);
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy) {
      const ivec3 row = ivec3(x0, c.y + dy, c.z + dz);
      if (!cellInGrid(row)) continue;
      const uint first = cellIndex(row);
      const uint end = cellStart[first + uint(x1 - x0) + 1u];
      for (uint j = cellStart[first]; j < end; ++j) {
        const vec3 d = p - posIn[j].xyz;
        if (j == i || dot(d, d) >= reach2) continue;
        if (n < uListCapacity) lists[listEntry(uint(BALLS_LIST_FIRST) + n, i)] = j;
        ++n;
      }
    }
  lists[listEntry(0u, i)] = floatBitsToUint(p.x);
  lists[listEntry(1u, i)] = floatBitsToUint(p.y);
  lists[listEntry(2u, i)] = floatBitsToUint(p.z);
  lists[listEntry(3u, i)] = n;
  if (n > uListCapacity) atomicAdd(lists[uControl + BALLS_LIST_OVERFLOW], 1u);
}
