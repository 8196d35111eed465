#version 430 core
// The four glass walls of the tank (24 vertices from gl_VertexID, outward normals), from the
// floor to above the highest wave; the fragment shader clips them at the local water height.
#include "render/ripples/view_3d.glsl"

uniform mat4 uViewProj;
uniform float uWallTop;  // world z
out vec3 vWorld;
out vec3 vNormal;

void main() {
  const int face = gl_VertexID / 6;
  const int corner = gl_VertexID % 6;
  const vec2 uvs[6] = vec2[](vec2(0, 0), vec2(1, 0), vec2(1, 1), vec2(0, 0), vec2(1, 1), vec2(0, 1));
  const vec2 uv = uvs[corner];
  // Faces: y = 0 (normal -y), x = 1 (+x), y = top (+y), x = 0 (-x); counter-clockwise from outside.
  const vec2 a[4] = vec2[](vec2(0, 0), vec2(1, 0), vec2(1, 1), vec2(0, 1));
  const vec2 b[4] = vec2[](vec2(1, 0), vec2(1, 1), vec2(0, 1), vec2(0, 0));
  const vec2 normals[4] = vec2[](vec2(0, -1), vec2(1, 0), vec2(0, 1), vec2(-1, 0));
  const vec2 xy = mix(a[face], b[face], uv.x) * uTank;
  vWorld = vec3(xy, uv.y * uWallTop);
  vNormal = vec3(normals[face], 0.0);
  gl_Position = uViewProj * vec4(vWorld, 1.0);
}
