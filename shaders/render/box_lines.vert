#version 430 core
// The 12 edges of a box from gl_VertexID (GL_LINES, 24 vertices).
uniform vec3 uMin;
uniform vec3 uMax;
uniform mat4 uViewProjModel;

const ivec2 kEdges[12] = ivec2[](ivec2(0, 1), ivec2(2, 3), ivec2(4, 5), ivec2(6, 7), ivec2(0, 2), ivec2(1, 3),
                                 ivec2(4, 6), ivec2(5, 7), ivec2(0, 4), ivec2(1, 5), ivec2(2, 6), ivec2(3, 7));

void main() {
  const ivec2 e = kEdges[gl_VertexID / 2];
  const int corner = (gl_VertexID % 2 == 0) ? e.x : e.y;
  const vec3 p = mix(uMin, uMax, vec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1));
  gl_Position = uViewProjModel * vec4(p, 1.0);
}
