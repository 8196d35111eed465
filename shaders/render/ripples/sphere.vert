#version 430 core
// A UV sphere generated from gl_VertexID: uSegments.x around, uSegments.y from pole to pole,
// 6 vertices per quad. No vertex buffer.
uniform ivec2 uSegments;
uniform vec3 uCentre;   // world
uniform float uRadius;  // world
uniform mat4 uViewProj;
out vec3 vNormal;
out vec3 vWorld;

const ivec2 kCorners[6] = ivec2[](ivec2(0, 0), ivec2(1, 0), ivec2(1, 1), ivec2(0, 0), ivec2(1, 1), ivec2(0, 1));
const float kPi = 3.14159265358979;

void main() {
  const int quad = gl_VertexID / 6;
  const ivec2 q = ivec2(quad % uSegments.x, quad / uSegments.x) + kCorners[gl_VertexID % 6];
  const float around = 2.0 * kPi * float(q.x) / float(uSegments.x);
  const float polar = kPi * float(q.y) / float(uSegments.y);
  vNormal = vec3(sin(polar) * cos(around), sin(polar) * sin(around), cos(polar));
  vWorld = uCentre + uRadius * vNormal;
  gl_Position = uViewProj * vec4(vWorld, 1.0);
}
