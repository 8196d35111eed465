#version 430 core
// The windows of a windowed collide (src/sim/balls/balls_windows.cpp), found on the GPU from the
// grid's cellStart alone: window k holds the cell-ordered balls [k·uWindowSize, (k+1)·uWindowSize)
// (the last one fewer), which lie in the cells from c0 (its first ball's) to c1 (its last's); every
// ball they can touch lies in the cells c0 − uReach .. c1 + uReach, where uReach is a plane, a row
// and a cell. bounds[k] = (cellStart[c0 − uReach], cellStart[c1 + uReach + 1]), clamped to the grid.
#include "balls/bindings.glsl"

layout(local_size_x = 64) in;
#include "common/index.glsl"

layout(std430, binding = BALLS_CELL_START) readonly buffer CellStart { uint cellStart[]; };  // cells + 1
layout(std430, binding = BALLS_REACH_BOUNDS) writeonly buffer Bounds { uvec2 bounds[]; };

uniform uint uWindows;
uniform uint uWindowSize;  // balls
uniform uint uCount;       // balls
uniform uint uCells;
uniform uint uReach;  // cells

// The cell holding ball i: the last c with cellStart[c] <= i (empty cells before it share its start).
uint cellOfBall(uint i) {
  uint lo = 0u, hi = uCells;  // cellStart[lo] <= i; the answer lies in [lo, hi)
  while (hi - lo > 1u) {
    const uint mid = lo + (hi - lo) / 2u;
    if (cellStart[mid] <= i)
      lo = mid;
    else
      hi = mid;
  }
  return lo;
}

void main() {
  const uint k = globalIndex();
  if (k >= uWindows) return;
  const uint first = k * uWindowSize, last = min(first + uWindowSize, uCount) - 1u;
  const uint c0 = cellOfBall(first), c1 = cellOfBall(last);
  const uint lo = c0 > uReach ? c0 - uReach : 0u;
  const uint hi = min(c1 + uReach + 1u, uCells);  // c1 < uCells <= 2^30, uReach < 2^30: no overflow
  bounds[k] = uvec2(cellStart[lo], cellStart[hi]);
}
