// The water-surface grid and marching cubes' numbering (src/render/marching_cubes.h holds the same
// formulas and builds the case table): corner k of a cell at (k & 1, (k >> 1) & 1, (k >> 2) & 1);
// edge e along axis e / 4 from the corner whose other coordinates (axis + 1, axis + 2 mod 3) are
// (e & 1, (e >> 1) & 1). Densities live on the corners of the grid, linear index x + X (y + Y z);
// the outermost shell of corners reads as 0 whatever was splatted there, so the surface always
// closes inside the grid.
#ifndef SURFACE_CUBE_GLSL
#define SURFACE_CUBE_GLSL

#include "surface/bindings.glsl"

uniform vec3 uOrigin;    // corner (0, 0, 0), m
uniform float uCell;     // edge of a cell, m
uniform uvec3 uCorners;  // corners per axis (cells + 1)
uniform float uIso;      // the surface's level of normalised density

uint cornerIndex(ivec3 c) { return uint(c.x) + uCorners.x * (uint(c.y) + uCorners.y * uint(c.z)); }

ivec3 cornerOf(uint index) {
  return ivec3(index % uCorners.x, (index / uCorners.x) % uCorners.y, index / (uCorners.x * uCorners.y));
}

ivec3 cubeCorner(int k) { return ivec3(k & 1, (k >> 1) & 1, (k >> 2) & 1); }

int edgeAxis(int e) { return e >> 2; }

ivec3 edgeStart(int e) {
  const int axis = edgeAxis(e);
  ivec3 p = ivec3(0);
  p[(axis + 1) % 3] = e & 1;
  p[(axis + 2) % 3] = (e >> 1) & 1;
  return p;
}

ivec3 axisStep(int axis) { return ivec3(axis == 0 ? 1 : 0, axis == 1 ? 1 : 0, axis == 2 ? 1 : 0); }

#ifdef SURFACE_READS_DENSITY
layout(std430, binding = SURFACE_DENSITY) readonly buffer Density { uint density[]; };

// Normalised density at corner c (clamped into the grid); 0 on the outer shell.
float densityAt(ivec3 c) {
  c = clamp(c, ivec3(0), ivec3(uCorners) - 1);
  if (any(equal(c, ivec3(0))) || any(equal(c, ivec3(uCorners) - 1))) return 0.0;
  return float(density[cornerIndex(c)]) / SURFACE_FIXED_ONE;
}

bool inside(ivec3 c) { return densityAt(c) > uIso; }

// Does the edge from c along `axis` cross the surface? (Both ends inside the grid.)
bool crosses(ivec3 c, int axis) { return inside(c) != inside(c + axisStep(axis)); }

// The marching-cubes case of the cell whose corner 0 is c: bit k set when corner k is inside.
uint cellCase(ivec3 c) {
  uint bits = 0u;
  for (int k = 0; k < 8; ++k)
    if (inside(c + cubeCorner(k))) bits |= 1u << k;
  return bits;
}
#endif

#endif
