#version 430 core
// Triangle pass of the water-surface mesher: each cell writes its case's triangles at its scanned
// offset, as indices of the vertices on its edges (emit_vertices.comp numbers them by owner corner).
layout(local_size_x = 128) in;
#include "common/index.glsl"
#define SURFACE_READS_DENSITY
#include "surface/cube.glsl"

layout(std430, binding = SURFACE_TRI_COUNT) readonly buffer TriStart { uint triStart[]; };
layout(std430, binding = SURFACE_VERT_COUNT) readonly buffer VertStart { uint vertStart[]; };
layout(std430, binding = SURFACE_TRIANGLES) writeonly buffer Triangles { uint triangles[]; };
layout(std140, binding = SURFACE_CASES) uniform Cases { uvec4 cases[256]; };

uint nibble(uvec4 row, int n) { return (row[n >> 3] >> (4 * (n & 7))) & 15u; }

// The vertex on edge e of the cell at c: its owner corner's first vertex plus the owner's crossing
// edges along lower axes.
uint vertexOn(ivec3 c, int e) {
  const ivec3 owner = c + edgeStart(e);
  const int axis = edgeAxis(e);
  uint rank = 0u;
  for (int a = 0; a < axis; ++a)
    if (crosses(owner, a)) ++rank;
  return vertStart[cornerIndex(owner)] + rank;
}

void main() {
  const uint i = globalIndex();
  if (i >= uCorners.x * uCorners.y * uCorners.z) return;
  const ivec3 c = cornerOf(i);
  if (any(greaterThanEqual(c, ivec3(uCorners) - 1))) return;
  const uvec4 row = cases[cellCase(c)];
  const int count = int(nibble(row, 0));
  uint at = 3u * triStart[i];
  for (int k = 0; k < 3 * count; ++k) triangles[at + uint(k)] = vertexOn(c, int(nibble(row, 1 + k)));
}
