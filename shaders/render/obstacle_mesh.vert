#version 430 core
// Obstacle surface mesh (src/render/obstacle_mesh.h): three vertices per triangle read from an
// SSBO by gl_VertexID, in the balls' frame; `uModelView` carries the obstacle's spin.
#include "render/balls_bindings.glsl"

struct MeshVertex {
  vec4 position;  // m, w = 1
  vec4 normal;    // unit, outward
};
layout(std430, binding = BALLS_VIEW_MESH) readonly buffer Mesh { MeshVertex vertices[]; };

uniform mat4 uModelView;  // rigid: its 3x3 turns normals too
uniform mat4 uProj;

out vec3 vNormal;  // view space

void main() {
  const MeshVertex v = vertices[gl_VertexID];
  vNormal = mat3(uModelView) * v.normal.xyz;
  gl_Position = uProj * (uModelView * v.position);
}
