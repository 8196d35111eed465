#version 430 core
// Rank pass of the stable uniform grid (src/grid/grid.h, GridParams::stable): after the members
// pass wrote each cell's particles in atomicAdd order (members[cellStart[cell] + slot] = i), a
// particle's slot in its cell becomes its rank by index among the cell's members, which no
// scheduling can change. Without WRITE_PERMUTATION the rank replaces indexInCell (the scatter
// reorder reads it); with it the pass writes the gather's permutation[cellStart[cell] + rank] = i
// directly, in place of the gather's own permutation pass. A cell of more than
// GRID_STABLE_MAX_CELL particles keeps its atomic slots: ranking is O(count) per particle.
layout(local_size_x = 256) in;
#include "common/index.glsl"
#include "common/grid.glsl"
#include "grid/bindings.glsl"
#include "grid/positions.glsl"

layout(std430, binding = GRID_INDEX_IN_CELL) buffer IndexInCell { uint indexInCell[]; };
layout(std430, binding = GRID_CELL_START) readonly buffer CellStart { uint cellStart[]; };
layout(std430, binding = GRID_MEMBERS) readonly buffer Members { uint members[]; };
#if WRITE_PERMUTATION
layout(std430, binding = GRID_PERMUTATION) writeonly buffer Permutation { uint permutation[]; };
#endif

uniform uint uCount;  // particles

void main() {
  const uint i = globalIndex();
  if (i >= uCount) return;
  const uint cell = cellOf(particlePosition(i));
  const uint begin = cellStart[cell], end = cellStart[cell + 1u];
  uint rank = 0u;
  if (end - begin > uint(GRID_STABLE_MAX_CELL)) {
    rank = indexInCell[i];
  } else {
    for (uint k = begin; k < end; ++k) rank += members[k] < i ? 1u : 0u;
  }
#if WRITE_PERMUTATION
  permutation[begin + rank] = i;
#else
  indexInCell[i] = rank;
#endif
}
