#version 430 core
// Sphere impostors for the G-buffer and thickness passes: one quad per ball from gl_VertexID,
// reading the simulation's position (and foam) SSBOs directly — no instancing buffer, no copy.
#include "render/balls/sphere.glsl"

layout(std430, binding = BALLS_VIEW_VELOCITIES) readonly buffer Velocities { vec4 velocities[]; };

uniform mat4 uModelView;  // simulation -> view
uniform mat4 uProj;
uniform float uRadius;    // m
uniform int uHasFoam;     // 0: the velocity buffer is not bound

out vec3 vQuadPoint;             // view space
flat out vec3 vCentre;           // view space
flat out float vFoam;

void main() {
  const int ball = gl_VertexID / 6;
  const vec4 corner = sphereQuadCorner(ball, gl_VertexID % 6, uModelView, uRadius, isOrthographic(uProj), vCentre);
  vQuadPoint = corner.xyz;
  vFoam = uHasFoam != 0 ? velocities[ball].w : 0.0;
  // w = 0 puts all six vertices at the same point: a degenerate quad, nothing drawn.
  gl_Position = corner.w == 0.0 ? vec4(0.0) : uProj * corner;
}
