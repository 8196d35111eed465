#version 430 core
// PBF step, after the iterations (Macklin & Müller 2013, algorithm 1, line 21): v = (p − x)/dt,
// and the foam grows with speed and decays (the renderer's, as the balls'). The predicted
// positions become the positions: w back to 1, in place (each invocation its own particle).
#include "fluid/bindings.glsl"

layout(local_size_x = FLUID_GROUP_SIZE) in;
#include "common/index.glsl"

layout(std430, binding = FLUID_POS) readonly buffer Pos { vec4 pos[]; };
layout(std430, binding = FLUID_PRED) buffer Pred { vec4 pred[]; };
layout(std430, binding = FLUID_OUT) writeonly buffer VelOut { vec4 velOut[]; };

uniform uint uCount;
uniform float uDt;
uniform float uFoamGain;   // per m travelled
uniform float uFoamDecay;  // factor per step

void main() {
  const uint i = globalIndex();
  if (i >= uCount) return;
  const vec4 p = pred[i];
  const vec3 v = (p.xyz - pos[i].xyz) / uDt;
  velOut[i] = vec4(v, min(1.0, (p.w + uFoamGain * uDt * length(v)) * uFoamDecay));
  pred[i] = vec4(p.xyz, 1.0);
}
