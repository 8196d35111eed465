#version 430 core
// XSPH viscosity (Macklin & Müller 2013, eq. 17; Schechter & Bridson 2012): v_i += c Σ_j V0
// (v_j − v_i) W(p_i − p_j), the neighbourhood's velocity blended in, and with VORTICITY the
// vorticity ω_i = Σ_j V0 (v_j − v_i) × ∇_j W(p_i − p_j) (eq. 15) for the confinement pass.
#include "fluid/bindings.glsl"

layout(local_size_x = FLUID_GROUP_SIZE) in;
#include "common/index.glsl"

layout(std430, binding = FLUID_PRED) readonly buffer Pos { vec4 pos[]; };  // the new positions
layout(std430, binding = FLUID_VEL_IN) readonly buffer Vel { vec4 vel[]; };
layout(std430, binding = FLUID_OUT) writeonly buffer VelOut { vec4 velOut[]; };
#ifdef VORTICITY
layout(std430, binding = FLUID_LAMBDA) writeonly buffer Omega { vec4 omega[]; };
#endif
#define neighbourPos pos

#include "fluid/kernels.glsl"

vec3 gVelocity = vec3(0.0);
vec3 gBlend;
vec3 gOmega;
void onFluid(uint j, vec3 r, float r2) {
  const vec3 dv = vel[j].xyz - gVelocity;
  gBlend += uVolume * poly6(r2) * dv;
#ifdef VORTICITY
  const float len = sqrt(r2);
  if (len > 0.0) gOmega += uVolume * cross(dv, -spikyGrad(r, len));  // ∇_j W = −∇_i W
#endif
}

#include "fluid/neighbours.glsl"

uniform uint uCount;
uniform float uViscosity;  // XSPH c

void main() {
  const uint i = globalIndex();
  if (i >= uCount) return;
  const vec4 v = vel[i];
  gVelocity = v.xyz;
  gBlend = vec3(0.0);
  gOmega = vec3(0.0);
  forEachFluid(i, pos[i].xyz);
  velOut[i] = vec4(v.xyz + uViscosity * gBlend, v.w);
#ifdef VORTICITY
  omega[i] = vec4(gOmega, 0.0);
#endif
}
