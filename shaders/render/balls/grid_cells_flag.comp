#version 430 core
// Grid cells view, pass 1 of the compaction (src/render/balls_grid_cells.h): one thread per cell
// of the balls grid writes 1 where the cell holds a ball, else 0. The prefix scan then turns the
// flags in place into each non-empty cell's slot in the compacted list.
#include "render/balls/bindings.glsl"
layout(local_size_x = 256) in;
#include "common/index.glsl"

layout(std430, binding = BALLS_VIEW_CELL_COUNT) readonly buffer Counts { uint cellCount[]; };
layout(std430, binding = BALLS_VIEW_CELL_SCAN) writeonly buffer Flags { uint flags[]; };

uniform uint uCells;  // cells of the grid

void main() {
  const uint cell = globalIndex();
  if (cell < uCells) flags[cell] = cellCount[cell] > 0u ? 1u : 0u;
}
