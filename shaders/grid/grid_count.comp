#version 430 core
// Count pass of the uniform grid (src/grid/grid.h): each particle finds its cell (clamped into
// the grid) and takes a slot in it with atomicAdd. The slot is kept in indexInCell so the
// reorder needs no second atomic, and the cell in particleCell so the reorder's passes read 4
// bytes per particle where they would read its 16-byte position and find the cell again. Which particle gets which slot depends on scheduling; the
// counts do not.
layout(local_size_x = 256) in;
#include "common/index.glsl"
#include "common/grid.glsl"
#include "grid/bindings.glsl"
#include "grid/positions.glsl"

layout(std430, binding = GRID_CELL_COUNT) buffer CellCount { uint cellCount[]; };
layout(std430, binding = GRID_INDEX_IN_CELL) writeonly buffer IndexInCell { uint indexInCell[]; };
layout(std430, binding = GRID_PARTICLE_CELL_OUT) writeonly buffer ParticleCell { uint particleCell[]; };

// Particles [uFirst, uCount): a window of an array larger than one storage block (src/gl/window.h)
// or all of it (uFirst = 0). The positions are bound from particle uFirst on; the per-particle
// words are bound whole.
uniform uint uFirst;
uniform uint uCount;

void main() {
  const uint i = uFirst + globalIndex();
  if (i >= uCount) return;
  const uint cell = cellOf(particlePosition(i - uFirst));
  particleCell[i] = cell;
  indexInCell[i] = atomicAdd(cellCount[cell], 1u);
}
