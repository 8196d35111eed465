#version 430 core
// Gather pass of the uniform grid's gather reorder (src/grid/grid.h, ReorderMode::Gather): after
// the permutation pass (grid_reorder.comp without arrays) wrote permutation[slot] = i, every slot
// fetches its particle for ARRAYS (1..GRID_REORDER_MAX_ARRAYS) arrays at once:
// dst[slot] = src[permutation[slot]]. The writes are coalesced whatever the particle order; from
// random order the reads land on random elements instead (whole sectors read, never a partial
// sector written), from last step's cell order they are nearly sequential too.
layout(local_size_x = 256) in;
#include "common/index.glsl"
#include "grid/bindings.glsl"
#include "grid/positions.glsl"  // GridElement

layout(std430, binding = GRID_PERMUTATION) readonly buffer Permutation { uint permutation[]; };
layout(std430, binding = GRID_REORDER_SRC) readonly buffer Src { GridElement values[]; } src[ARRAYS];
layout(std430, binding = GRID_REORDER_DST) writeonly buffer Dst { GridElement values[]; } dst[ARRAYS];

// Arrays larger than one storage block move a window at a time (src/gl/window.h): this dispatch
// fills slots [uFirst, uCount), the destination arrays bound from slot uFirst on, from the
// particles [uSrcFirst, uSrcFirst + uSrcCount), the source arrays bound from uSrcFirst on; the
// caller runs every pair of windows. One window: uFirst = uSrcFirst = 0, uSrcCount = uCount.
uniform uint uFirst;
uniform uint uCount;
uniform uint uSrcFirst;
uniform uint uSrcCount;

void main() {
  const uint slot = uFirst + globalIndex();
  if (slot >= uCount) return;
  const uint i = permutation[slot] - uSrcFirst;
  if (i >= uSrcCount) return;  // another window's (wraps below uSrcFirst)
  for (int a = 0; a < ARRAYS; ++a) dst[a].values[slot - uFirst] = src[a].values[i];
}
