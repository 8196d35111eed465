#version 430 core
// Grid cells view, pass 2 of the compaction (src/render/balls_grid_cells.h): one thread per cell
// reads the exclusive scan of the non-empty flags; a cell whose entry grows to the next one is
// non-empty and writes its id at slot scan[cell], so the list holds the non-empty cells in index
// order (the same on every run). Thread 0 writes the glDrawArraysIndirect command in front of
// the list: 24 vertices (a cube's 12 edges), one instance per non-empty cell, scan[cells] of them.
#include "render/balls/bindings.glsl"
layout(local_size_x = 256) in;
#include "common/index.glsl"

layout(std430, binding = BALLS_VIEW_CELL_SCAN) readonly buffer Scan { uint scan[]; };
layout(std430, binding = BALLS_VIEW_CELL_LIST) writeonly buffer List {
  uint drawCount;      // DrawArraysIndirectCommand: vertices per instance
  uint drawInstances;  // non-empty cells
  uint drawFirst;
  uint drawBaseInstance;  // reserved in GL 4.3: 0
  uint cellIds[];
};

uniform uint uCells;  // cells of the grid

void main() {
  const uint cell = globalIndex();
  if (cell >= uCells) return;
  const uint slot = scan[cell];
  if (scan[cell + 1u] > slot) cellIds[slot] = cell;
  if (cell == 0u) {
    drawCount = 24u;
    drawInstances = scan[uCells];
    drawFirst = 0u;
    drawBaseInstance = 0u;
  }
}
