#version 430 core
// One camera-facing quad per ball from gl_VertexID (6 vertices each), reading the simulation's
// position SSBO directly: no instancing buffer, no CPU copy.
#include "render/balls/bindings.glsl"

layout(std430, binding = BALLS_VIEW_POSITIONS) readonly buffer Positions { vec4 positions[]; };
layout(std430, binding = BALLS_VIEW_VELOCITIES) readonly buffer Velocities { vec4 velocities[]; };

uniform mat4 uModel;     // simulation -> world (domain rotation)
uniform mat4 uView;
uniform mat4 uProj;
uniform float uRadius;   // m
uniform int uHasVelocity;

out vec2 vLocal;         // billboard coordinates in [-1, 1]^2
out vec3 vCentreView;    // sphere centre, view space
out float vFoam;

const vec2 kCorners[6] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, -1), vec2(1, 1), vec2(-1, 1));

void main() {
  const int ball = gl_VertexID / 6;
  vLocal = kCorners[gl_VertexID % 6];
  vCentreView = (uView * uModel * vec4(positions[ball].xyz, 1.0)).xyz;
  vFoam = uHasVelocity != 0 ? velocities[ball].w : 0.0;
  // Enlarged slightly so the perspective-projected sphere stays inside its quad.
  const vec3 corner = vCentreView + vec3(vLocal * uRadius * 1.05, 0.0);
  gl_Position = uProj * vec4(corner, 1.0);
  vLocal *= 1.05;
}
