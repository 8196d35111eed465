#version 430 core
// Reorder pass of the uniform grid (src/grid/grid.h): particle i moves to slot
// cellStart[cell] + indexInCell[i], for ARRAYS (0..GRID_REORDER_MAX_ARRAYS) arrays at once
// (src -> dst, double-buffered: no copy back) of the layout's elements (grid/positions.glsl).
// With WRITE_PERMUTATION, permutation[slot] = i; with ARRAYS = 0 that is the stable grid's
// members pass (the permutation bound to its members).
// The cell is the one the count pass stored (particleCell), not recomputed from the positions:
// 4 bytes read per particle instead of 16 (the members and permutation passes move no array).
layout(local_size_x = 256) in;
#include "common/index.glsl"
#include "grid/bindings.glsl"
#define GRID_NO_POSITIONS_BLOCK
#include "grid/positions.glsl"  // GridElement

layout(std430, binding = GRID_PARTICLE_CELL) readonly buffer ParticleCell { uint particleCell[]; };

layout(std430, binding = GRID_INDEX_IN_CELL) readonly buffer IndexInCell { uint indexInCell[]; };
layout(std430, binding = GRID_CELL_START) readonly buffer CellStart { uint cellStart[]; };
#if WRITE_PERMUTATION
layout(std430, binding = GRID_PERMUTATION) writeonly buffer Permutation { uint permutation[]; };
#endif
#if ARRAYS > 0
layout(std430, binding = GRID_REORDER_SRC) readonly buffer Src { GridElement values[]; } src[ARRAYS];
layout(std430, binding = GRID_REORDER_DST) writeonly buffer Dst { GridElement values[]; } dst[ARRAYS];
#endif

// Arrays larger than one storage block move a window at a time (src/gl/window.h): this dispatch
// takes particles [uFirst, uCount), the source arrays bound from particle uFirst on, and writes the
// slots [uDstFirst, uDstFirst + uDstCount), the destination arrays bound from slot uDstFirst on;
// the caller runs every pair of windows. The per-particle words are bound whole. One window:
// uFirst = uDstFirst = 0, uDstCount = uCount.
uniform uint uFirst;
uniform uint uCount;
uniform uint uDstFirst;
uniform uint uDstCount;

void main() {
  const uint i = uFirst + globalIndex();
  if (i >= uCount) return;
  const uint slot = cellStart[particleCell[i]] + indexInCell[i];
  if (slot - uDstFirst >= uDstCount) return;  // another window's (wraps below uDstFirst)
#if ARRAYS > 0
  for (int a = 0; a < ARRAYS; ++a) dst[a].values[slot - uDstFirst] = src[a].values[i - uFirst];
#endif
#if WRITE_PERMUTATION
  permutation[slot] = i;
#endif
}
