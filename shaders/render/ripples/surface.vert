#version 430 core
// Displaced water surface: uMesh.x * uMesh.y quads generated from gl_VertexID (6 per quad), the
// height read from the simulation's state buffer. No vertex buffer.
#include "render/ripples/view_3d.glsl"

uniform ivec2 uMesh;  // quads along x and y
uniform mat4 uViewProj;
out vec3 vWorld;

const ivec2 kCorners[6] = ivec2[](ivec2(0, 0), ivec2(1, 0), ivec2(1, 1), ivec2(0, 0), ivec2(1, 1), ivec2(0, 1));

void main() {
  const int quad = gl_VertexID / 6;
  const ivec2 q = ivec2(quad % uMesh.x, quad / uMesh.x) + kCorners[gl_VertexID % 6];
  const vec2 xy = vec2(q) / vec2(uMesh) * uTank;
  vWorld = vec3(xy, surfaceZ(xy));
  gl_Position = uViewProj * vec4(vWorld, 1.0);
}
