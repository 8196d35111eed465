#version 430 core
// Classify pass of the water-surface mesher: per grid corner, how many triangles the cell at that
// corner emits (its marching-cubes case) and how many vertices the corner owns (its +x, +y, +z
// edges that cross the surface). Both counts are then scanned into output offsets.
layout(local_size_x = 128) in;
#include "common/index.glsl"
#define SURFACE_READS_DENSITY
#include "surface/cube.glsl"

layout(std430, binding = SURFACE_TRI_COUNT) writeonly buffer TriCount { uint triCount[]; };
layout(std430, binding = SURFACE_VERT_COUNT) writeonly buffer VertCount { uint vertCount[]; };
layout(std140, binding = SURFACE_CASES) uniform Cases { uvec4 cases[256]; };

void main() {
  const uint i = globalIndex();
  if (i >= uCorners.x * uCorners.y * uCorners.z) return;
  const ivec3 c = cornerOf(i);
  const ivec3 last = ivec3(uCorners) - 1;
  uint vertices = 0u;
  for (int axis = 0; axis < 3; ++axis)
    if (c[axis] < last[axis] && crosses(c, axis)) ++vertices;
  uint triangles = 0u;
  if (all(lessThan(c, last))) triangles = cases[cellCase(c)].x & 15u;
  vertCount[i] = vertices;
  triCount[i] = triangles;
}
