// Cell addressing of the ripples grid with the boundary chosen at compile time:
//   BOUNDARY_PERIODIC  neighbours wrap around (torus)
//   otherwise          mirrored neighbours: an outside neighbour has the cell's own height
//                      (zero normal derivative; the discrete Laplacian then sums to zero, so
//                      the total height is conserved). The absorbing boundary adds a sponge.
#ifndef RIPPLES_CELLS_GLSL
#define RIPPLES_CELLS_GLSL

uniform ivec2 uSize;  // cells in x and y

ivec2 neighbourCell(ivec2 p) {
#ifdef BOUNDARY_PERIODIC
  return (p + uSize) % uSize;
#else
  return clamp(p, ivec2(0), uSize - 1);
#endif
}

int cellIndex(ivec2 p) { return p.y * uSize.x + p.x; }

#endif
