#version 430 core
// Divergence watch of the balls (src/sim/balls/balls.h): balls whose position or velocity is NaN
// or infinite, the largest speed, and balls outside the walls (flagged).
#include "balls/bindings.glsl"

layout(local_size_x = BALLS_GROUP_SIZE) in;
#include "common/index.glsl"
#include "common/health.glsl"

layout(std430, binding = BALLS_POS_IN) readonly buffer PosIn { vec4 posIn[]; };
layout(std430, binding = BALLS_VEL_IN) readonly buffer VelIn { vec4 velIn[]; };
uniform vec3 uWallMin;
uniform vec3 uWallMax;

void checkHealth(uint i) {
  const vec3 p = posIn[i].xyz, v = velIn[i].xyz;
  if (!isFinite(p) || !isFinite(v)) {
    healthNonFinite();
    return;
  }
  healthMax(length(v));
  if (any(lessThan(p, uWallMin - 1e-6)) || any(greaterThan(p, uWallMax + 1e-6))) healthFlag();
}
