#version 430 core
// Vertex pass of the water-surface mesher: each crossing grid edge is one vertex, numbered by its
// owner corner's scanned count (+x before +y before +z), so the triangles of the cells around an
// edge share it: the mesh comes out welded. Position: linear interpolation of the density to the
// iso level along the edge. Normal: minus the density gradient (central differences at both
// ends, interpolated the same way), pointing out of the water.
layout(local_size_x = 128) in;
#include "common/index.glsl"
#define SURFACE_READS_DENSITY
#include "surface/cube.glsl"

layout(std430, binding = SURFACE_VERT_COUNT) readonly buffer VertStart { uint vertStart[]; };
layout(std430, binding = SURFACE_VERTICES) writeonly buffer Vertices { vec4 vertices[]; };
layout(std430, binding = SURFACE_NORMALS) writeonly buffer Normals { vec4 normals[]; };

vec3 gradient(ivec3 c) {  // per cell (the normal is normalised)
  return vec3(densityAt(c + ivec3(1, 0, 0)) - densityAt(c - ivec3(1, 0, 0)),
              densityAt(c + ivec3(0, 1, 0)) - densityAt(c - ivec3(0, 1, 0)),
              densityAt(c + ivec3(0, 0, 1)) - densityAt(c - ivec3(0, 0, 1)));
}

void main() {
  const uint i = globalIndex();
  if (i >= uCorners.x * uCorners.y * uCorners.z) return;
  const ivec3 c = cornerOf(i);
  const ivec3 last = ivec3(uCorners) - 1;
  uint at = vertStart[i];
  for (int axis = 0; axis < 3; ++axis) {
    if (c[axis] >= last[axis] || !crosses(c, axis)) continue;
    const ivec3 b = c + axisStep(axis);
    const float da = densityAt(c), db = densityAt(b);
    const float t = (uIso - da) / (db - da);
    vec3 p = vec3(c);
    p[axis] += t;
    vec3 g = mix(gradient(c), gradient(b), t);
    const float len = length(g);
    // A flat gradient (never on a crossing edge in practice): the edge's own direction.
    const vec3 n = len > 0.0 ? -g / len : vec3(axisStep(axis)) * (da > db ? 1.0 : -1.0);
    vertices[at] = vec4(uOrigin + p * uCell, 1.0);
    normals[at] = vec4(n, 0.0);
    ++at;
  }
}
