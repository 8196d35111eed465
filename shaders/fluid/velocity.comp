#version 430 core
// PBF step, after the iterations (Macklin & Müller 2013, algorithm 1, line 21): v = (p − x)/dt,
// and the foam grows with speed and decays (the renderer's, as the balls'). A particle with few
// neighbours, its density (the last iteration's) well under the rest density, is spray: its foam
// is raised to 1 − smoothstep(0.6 s, s, ρ/ρ0) for s = uSprayDensity (0: off), so a splash's
// droplets turn white and stay so for a while after they land. The predicted positions become the
// positions: w back to 1, in place (each invocation its own particle).
#include "fluid/bindings.glsl"

layout(local_size_x = FLUID_GROUP_SIZE) in;
#include "common/index.glsl"

layout(std430, binding = FLUID_POS) readonly buffer Pos { vec4 pos[]; };
layout(std430, binding = FLUID_PRED) buffer Pred { vec4 pred[]; };
layout(std430, binding = FLUID_OUT) writeonly buffer VelOut { vec4 velOut[]; };
layout(std430, binding = FLUID_LAMBDA) readonly buffer Lambda { vec2 lambda[]; };  // (λ, ρ/ρ0)

uniform uint uCount;
uniform float uDt;
uniform float uFoamGain;   // per m travelled
uniform float uFoamDecay;  // factor per step
uniform float uSprayDensity;  // ρ/ρ0 under which a particle is (partly) spray; 0: off

void main() {
  const uint i = globalIndex();
  if (i >= uCount) return;
  const vec4 p = pred[i];
  const vec3 v = (p.xyz - pos[i].xyz) / uDt;
  float foam = p.w + uFoamGain * uDt * length(v);
  if (uSprayDensity > 0.0) foam = max(foam, 1.0 - smoothstep(0.6 * uSprayDensity, uSprayDensity, lambda[i].y));
  velOut[i] = vec4(v, min(1.0, foam * uFoamDecay));
  pred[i] = vec4(p.xyz, 1.0);
}
