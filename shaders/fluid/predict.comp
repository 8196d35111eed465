#version 430 core
// PBF step 1 (Macklin & Müller 2013, algorithm 1, lines 1-4): v += dt·g (with damping), the
// predicted position p = x + dt·v, kept inside the walls (half a spacing off them). Particle order; w carries the foam to
// the velocity pass (the velocities are recomputed from the positions there). With LOADS_WALLS
// it starts the step's partials of the walls' loads (water/loads.glsl) with their share (the clamp).
#include "fluid/bindings.glsl"

layout(local_size_x = FLUID_GROUP_SIZE) in;
#include "common/index.glsl"

layout(std430, binding = FLUID_POS) readonly buffer Pos { vec4 pos[]; };
layout(std430, binding = FLUID_VEL_IN) readonly buffer Vel { vec4 vel[]; };
layout(std430, binding = FLUID_OUT) writeonly buffer Pred { vec4 pred[]; };

uniform uint uCount;
uniform float uDt;
uniform vec3 uGravity;  // m/s², turned with the domain
uniform float uDecay;   // exp(−damping·dt)
#include "fluid/kernels.glsl"
#include "fluid/walls.glsl"

#ifdef LOADS_WALLS
#define LOADS_BINDING FLUID_LOADS
#define LOADS_GROUP_SIZE FLUID_GROUP_SIZE
#define LOADS_FIRST
#include "water/loads.glsl"
#endif

void main() {
  const uint i = globalIndex();
  vec3 wallShare = vec3(0.0), p = vec3(0.0);
  if (i < uCount) {
    const vec4 v = vel[i];
    const vec3 u = (v.xyz + uDt * uGravity) * uDecay;
    p = pos[i].xyz + uDt * u;
    const vec3 inside = clampToWalls(p);
    pred[i] = vec4(inside, v.w);
    wallShare = inside - p;
  }
#ifdef LOADS_WALLS
  addLoads(wallShare, wallSides(p));  // by every invocation: the group adds them
#endif
}
