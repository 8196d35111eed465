#version 430 core
// A full-screen triangle from gl_VertexID alone (no vertex buffer); uv covers [0,1]^2 on screen.
out vec2 vUv;

void main() {
  const vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
  vUv = p;
  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
