#version 430 core
// Obstacle mesh (src/render/obstacle_mesh.h): three vertices per triangle, unindexed, read from
// an SSBO by gl_VertexID (no vertex attributes to set up), in the obstacle's own frame; uModelView
// carries its pose (moving and turning) and the domain's rotation.
#include "render/balls/bindings.glsl"

struct MeshVertex {
  vec4 position;  // m, w = 1
  vec4 normal;    // unit (a face's for a mesh file, smooth for a surface built from balls)
};
layout(std430, binding = BALLS_VIEW_MESH) readonly buffer Mesh { MeshVertex vertices[]; };

uniform mat4 uModelView;  // rigid: its 3x3 turns normals too
uniform mat4 uProj;

out vec3 vView;    // view space: eye -> vertex (orthographic: the view direction)
out vec3 vNormal;  // view space

void main() {
  const MeshVertex v = vertices[gl_VertexID];
  const vec4 view = uModelView * v.position;
  vView = uProj[3][3] == 1.0 ? vec3(0.0, 0.0, -1.0) : view.xyz;
  vNormal = mat3(uModelView) * v.normal.xyz;
  gl_Position = uProj * view;
}
