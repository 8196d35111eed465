#version 430 core
// Rank pass of the stable uniform grid (src/grid/grid.h, GridParams::stable): after the members
// pass wrote each cell's particles in atomicAdd order (members[cellStart[cell] + slot] = i), a
// particle's slot in its cell becomes its rank by index among the cell's members, which no
// scheduling can change. A cell of more than GRID_STABLE_MAX_CELL particles keeps its atomic
// slots: ranking is O(count) per particle. What the pass does with the rank:
//   ARRAYS = 0                          indexInCell[i] = rank (a scatter pass reads it)
//   ARRAYS > 0                          the stable scatter itself: dst[slot] = src[i] for ARRAYS
//                                       arrays, permutation[slot] = i with WRITE_PERMUTATION, and
//                                       with KEEP_RANK indexInCell[i] = rank for later batches
// where slot = cellStart[cell] + rank. With arrays the positions are src[0] (the caller moves
// them too), which frees their binding for the members: 8 storage blocks at most.
layout(local_size_x = 256) in;
#include "common/index.glsl"
#include "common/grid.glsl"
#include "grid/bindings.glsl"
// Without arrays the cell is the one the count pass stored (particleCell, at the positions'
// binding); with arrays it comes from the positions, src[0], whose binding the members take.
#define GRID_NO_POSITIONS_BLOCK
#if ARRAYS > 0
#define RANK_MEMBERS GRID_POSITIONS
#else
#define RANK_MEMBERS GRID_MEMBERS
#endif
#include "grid/positions.glsl"

layout(std430, binding = GRID_INDEX_IN_CELL) buffer IndexInCell { uint indexInCell[]; };
layout(std430, binding = GRID_CELL_START) readonly buffer CellStart { uint cellStart[]; };
layout(std430, binding = RANK_MEMBERS) readonly buffer Members { uint members[]; };
#if WRITE_PERMUTATION
layout(std430, binding = GRID_PERMUTATION) writeonly buffer Permutation { uint permutation[]; };
#endif
#if ARRAYS > GRID_REORDER_MAX_ARRAYS
#error "at most GRID_REORDER_MAX_ARRAYS arrays per pass: more would pass GL 4.3's 8 storage blocks"
#endif
#if ARRAYS > 0
layout(std430, binding = GRID_REORDER_SRC) readonly buffer Src { GridElement values[]; } src[ARRAYS];
layout(std430, binding = GRID_REORDER_DST) writeonly buffer Dst { GridElement values[]; } dst[ARRAYS];
uint rankedCell(uint i) { return cellOf(elementPosition(src[0].values[i])); }
#else
layout(std430, binding = GRID_PARTICLE_CELL) readonly buffer ParticleCell { uint particleCell[]; };
uint rankedCell(uint i) { return particleCell[i]; }
#endif

uniform uint uCount;  // particles

void main() {
  const uint i = globalIndex();
  if (i >= uCount) return;
  const uint cell = rankedCell(i);
  const uint begin = cellStart[cell], end = cellStart[cell + 1u];
  uint rank = 0u;
  if (end - begin > uint(GRID_STABLE_MAX_CELL)) {
    rank = indexInCell[i];
  } else {
    for (uint k = begin; k < end; ++k) rank += members[k] < i ? 1u : 0u;
  }
  const uint slot = begin + rank;
#if ARRAYS > 0
  for (int a = 0; a < ARRAYS; ++a) dst[a].values[slot] = src[a].values[i];
#if KEEP_RANK
  indexInCell[i] = rank;
#endif
#if WRITE_PERMUTATION
  permutation[slot] = i;
#endif
#else
  indexInCell[i] = rank;
#endif
}
