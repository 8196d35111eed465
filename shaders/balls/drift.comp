#version 430 core
// Velocity Verlet, first half (kick-drift): v½ = v + dt/2 · a,  x += dt · v½, in place.
// The force-and-kick half is collide.comp with INTEGRATOR_VERLET.
#include "balls/bindings.glsl"

layout(local_size_x = BALLS_GROUP_SIZE) in;
#include "common/index.glsl"

layout(std430, binding = BALLS_POS_OUT) buffer Pos { vec4 pos[]; };
layout(std430, binding = BALLS_VEL_OUT) buffer Vel { vec4 vel[]; };
layout(std430, binding = BALLS_ACC) readonly buffer Acc { vec4 acc[]; };

// Balls [uFirst, uCount), the arrays bound from ball uFirst on (src/gl/window.h).
uniform uint uFirst;
uniform uint uCount;
uniform float uDt;
uniform float uRadius;
uniform float uFoamGain;
uniform float uFoamDecay;
#include "balls/walls.glsl"

void driftBall(uint i) {
  const uint k = i - uFirst;
  vec3 v = vel[k].xyz + 0.5 * uDt * acc[k].xyz;
  vec3 x = pos[k].xyz + uDt * v;
  confineToDomain(x, v);
  const float foam = min(1.0, (vel[k].w + uFoamGain * uDt * length(v)) * uFoamDecay);
  pos[k] = vec4(x, pos[k].w);
  vel[k] = vec4(v, foam);
}

void main() {
  const uint i = uFirst + globalIndex();
  if (i < uCount) driftBall(i);
}
