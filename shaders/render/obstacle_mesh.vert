#version 430 core
// A triangle mesh from gl_VertexID (3 vertices per triangle, unindexed), read from an SSBO the
// view uploads when the model rebuilds its obstacle: no vertex attributes to set up.
layout(std430, binding = 0) readonly buffer Vertices { vec4 vertices[]; };

uniform mat4 uModel;  // obstacle frame -> world (spin, domain rotation)
uniform mat4 uView;
uniform mat4 uProj;

out vec3 vView;  // position in view space, for the flat normal

void main() {
  const vec4 view = uView * uModel * vec4(vertices[gl_VertexID].xyz, 1.0);
  vView = view.xyz;
  gl_Position = uProj * view;
}
