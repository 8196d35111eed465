// Uniform-grid cell math, shared by the grid kernels (shaders/grid) and the neighbour searches of
// the models. The C++ side (grid::UniformGrid::setUniforms) sets the three uniforms; the CPU
// twin of this file is src/grid/grid_reference.h and must stay bit-identical (same float ops).
//
// Cells are numbered x fastest: index = x + dims.x * (y + dims.y * z). Positions outside the
// domain (and NaN) are clamped into the border cells, so every particle has a valid cell.
#ifndef COMMON_GRID_GLSL
#define COMMON_GRID_GLSL

uniform vec3 uGridOrigin;        // domain min corner (world units)
uniform float uGridInvCellSize;  // 1 / cell size (1 / world units)
uniform uvec3 uGridDims;         // cells per axis; z = 1 for a 2D grid

// Integer cell coordinates of a position, clamped to the grid.
ivec3 cellCoord(vec3 p) {
  const vec3 f = floor((p - uGridOrigin) * uGridInvCellSize);
  const ivec3 last = ivec3(uGridDims) - 1;
  // Clamp in float first (float -> int of a huge value is undefined), then in int (NaN).
  return clamp(ivec3(clamp(f, vec3(0.0), vec3(last))), ivec3(0), last);
}

// Linear index of in-grid cell coordinates.
uint cellIndex(ivec3 c) { return uint(c.x) + uGridDims.x * (uint(c.y) + uGridDims.y * uint(c.z)); }

// True when a neighbour cell's coordinates lie inside the grid.
bool cellInGrid(ivec3 c) { return all(greaterThanEqual(c, ivec3(0))) && all(lessThan(c, ivec3(uGridDims))); }

uint cellOf(vec3 p) { return cellIndex(cellCoord(p)); }

#endif
