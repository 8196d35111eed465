#version 430 core
// Vorticity confinement (Macklin & Müller 2013, eq. 16; Fedkiw et al. 2001): η = ∇|ω| ≈ Σ_j V0
// |ω_j| ∇W(p_i − p_j), N = η/|η|, and v_i += dt·ε_v (N × ω_i), which puts back the swirl the
// position solver damps.
#include "fluid/bindings.glsl"

layout(local_size_x = FLUID_GROUP_SIZE) in;
#include "common/index.glsl"

layout(std430, binding = FLUID_PRED) readonly buffer Pos { vec4 pos[]; };
layout(std430, binding = FLUID_VEL_IN) readonly buffer Vel { vec4 vel[]; };
layout(std430, binding = FLUID_OUT) writeonly buffer VelOut { vec4 velOut[]; };
layout(std430, binding = FLUID_LAMBDA) readonly buffer Omega { vec4 omega[]; };
#define neighbourPos pos

#include "fluid/kernels.glsl"

vec3 gEta;
void onFluid(uint j, vec3 r, float r2) {
  const float len = sqrt(r2);
  if (len > 0.0) gEta += uVolume * length(omega[j].xyz) * spikyGrad(r, len);
}

#include "fluid/neighbours.glsl"

uniform uint uCount;
uniform float uDt;
uniform float uVorticity;  // ε_v, m/s

void main() {
  const uint i = globalIndex();
  if (i >= uCount) return;
  gEta = vec3(0.0);
  forEachFluid(i, pos[i].xyz);
  const float len = length(gEta);
  const vec3 n = len > 1e-12 ? gEta / len : vec3(0.0);
  const vec4 v = vel[i];
  velOut[i] = vec4(v.xyz + uDt * uVorticity * cross(n, omega[i].xyz), v.w);
}
