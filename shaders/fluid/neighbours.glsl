// The neighbours of fluid particle i at p: every particle within h, itself included (r = 0),
// found in the (2R + 1)³ cells around its own (R = uReach cells cover h: cells of h give the usual
// 27, cells of h/2 give 125 smaller ones holding 1.7 times fewer candidates). The obstacles'
// particles are found through their own grid (fluid/boundary.glsl). The including kernel declares the cell-ordered array the positions come from as `neighbourPos[]` (a #define)
// and, before including this file,
//   void onFluid(uint j, vec3 r, float r2);      // r = p − p_j, r2 = |r|² < h²
#ifndef FLUID_NEIGHBOURS_GLSL
#define FLUID_NEIGHBOURS_GLSL

#include "common/grid.glsl"

layout(std430, binding = FLUID_CELL_START) readonly buffer CellStart { uint cellStart[]; };
uniform int uReach;  // cells each way that cover h

// Only the cells the sphere of `reach` around p touches: rows (fixed y, z) whose nearest point is
// farther than reach are skipped, and each row is cut to the x-range the sphere spans there. With
// cells of h/2 this visits about half the candidates of the whole 5 × 5 × 5 block.
void forEachGridNeighbour(vec3 p, float reach) {
  const float reach2 = reach * reach;
  const float cell = 1.0 / uGridInvCellSize;
  const vec3 at = (p - uGridOrigin) * uGridInvCellSize;  // in cells
  const ivec3 c = cellCoord(p);
  const int lastX = int(uGridDims.x) - 1;
  for (int dz = -uReach; dz <= uReach; ++dz) {
    const int z = c.z + dz;
    if (z < 0 || z >= int(uGridDims.z)) continue;
    const float gz = max(0.0, max(float(z) - at.z, at.z - float(z + 1))) * cell;  // p to the layer
    for (int dy = -uReach; dy <= uReach; ++dy) {
      const int y = c.y + dy;
      if (y < 0 || y >= int(uGridDims.y)) continue;
      const float gy = max(0.0, max(float(y) - at.y, at.y - float(y + 1))) * cell;
      const float left = reach2 - gz * gz - gy * gy;
      if (left < 0.0) continue;
      // Cells are numbered x fastest: the row's cells x0..x1 are one contiguous run.
      const float span = sqrt(left) * uGridInvCellSize;
      const int x0 = max(int(floor(at.x - span)), max(c.x - uReach, 0));
      const int x1 = min(int(floor(at.x + span)), min(c.x + uReach, lastX));
      if (x1 < x0) continue;
      const uint first = cellIndex(ivec3(x0, y, z));
      const uint end = cellStart[first + uint(x1 - x0) + 1u];
      for (uint j = cellStart[first]; j < end; ++j) {
        const vec3 r = p - neighbourPos[j].xyz;
        const float r2 = dot(r, r);
        if (r2 < reach2) onFluid(j, r, r2);
      }
    }
  }
}

void forEachFluid(uint i, vec3 p) { forEachGridNeighbour(p, uH); }

#endif
