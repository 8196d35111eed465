#version 430 core
// One triangle covering the viewport, from gl_VertexID alone (draw 3 vertices, no buffers).
out vec2 vUv;

void main() {
  const vec2 corner = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
  vUv = corner;
  gl_Position = vec4(2.0 * corner - 1.0, 0.0, 1.0);
}
