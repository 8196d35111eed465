#version 430 core
// One step of the balls (explicit or symplectic Euler), or the force-and-kick half of velocity
// Verlet: contact accelerations from every body within 2r, the walls, gravity, then integration.
// Reads the cell-ordered arrays, writes the other buffers (no read/write hazard between balls).
#include "balls/bindings.glsl"

layout(local_size_x = BALLS_GROUP_SIZE) in;
#include "common/index.glsl"

layout(std430, binding = BALLS_POS_IN) readonly buffer PosIn { vec4 posIn[]; };
layout(std430, binding = BALLS_VEL_IN) readonly buffer VelIn { vec4 velIn[]; };
layout(std430, binding = BALLS_VEL_OUT) writeonly buffer VelOut { vec4 velOut[]; };
// The step's other output: the new position (Euler) or the acceleration (velocity Verlet).
layout(std430, binding = BALLS_STEP_OUT) writeonly buffer StepOut { vec4 stepOut[]; };
#ifdef INTEGRATOR_VERLET
uniform float uKick;  // fraction of dt·a added to the (half-step) velocity: 0.5, or 0 to only evaluate a
#else
// Euler writes the positions of the next step: it counts each ball into the next step's grid
// there (grid_count.comp's work, src/grid/grid.h), so the next step starts at the scan.
layout(std430, binding = BALLS_NEXT_CELL_COUNT) buffer NextCellCount { uint nextCellCount[]; };
layout(std430, binding = BALLS_NEXT_INDEX_IN_CELL) writeonly buffer NextIndexInCell { uint nextIndexInCell[]; };
layout(std430, binding = BALLS_NEXT_PARTICLE_CELL) writeonly buffer NextParticleCell { uint nextParticleCell[]; };
#endif

#include "balls/contact.glsl"

vec3 gAccel;
vec3 gVelocity = vec3(0.0);  // set in main(); initialised so that no compiler warns of its use in onContact()
void onContact(vec3 n, float overlap, vec3 otherVelocity, float massRatio, float share) {
  gAccel += contactAccel(n, overlap, gVelocity - otherVelocity, massRatio, share);
}

#include "balls/neighbours.glsl"
#include "balls/walls.glsl"

// Balls [uFirst, uCount): a window of arrays larger than one storage block (src/gl/window.h), or all
// of them (uFirst = uSourceFirst = 0). The outputs are bound from ball uFirst on, the inputs from
// uSourceFirst on (neighbours.glsl): a window of the balls within reach of this one's.
uniform uint uFirst;
uniform uint uCount;
uniform vec3 uGravity;    // m/s^2, rotated with the domain
uniform float uDecay;     // exp(−damping·dt)
uniform float uFoamGain;  // per m travelled
uniform float uFoamDecay; // factor per step

void stepBall(uint i) {
  const uint s = i - uSourceFirst, o = i - uFirst;  // in the inputs' and the outputs' windows
  const vec3 p = posIn[s].xyz;
  gVelocity = velIn[s].xyz;
  gAccel = uGravity;
  forEachContact(i, p);
  gAccel += wallsAccel(p, gVelocity);
  float foam = velIn[s].w;
#ifdef INTEGRATOR_VERLET
  const vec3 v = (gVelocity + uKick * uDt * gAccel) * (uKick > 0.0 ? uDecay : 1.0);
  stepOut[o] = vec4(gAccel, 0.0);  // a
  velOut[o] = vec4(v, foam);
#else
#ifdef INTEGRATOR_EXPLICIT
  vec3 x = p + uDt * gVelocity;
  vec3 v = (gVelocity + uDt * gAccel) * uDecay;
#else
  vec3 v = (gVelocity + uDt * gAccel) * uDecay;
  vec3 x = p + uDt * v;
#endif
  confineToDomain(x, v);
  foam = min(1.0, (foam + uFoamGain * uDt * length(gVelocity)) * uFoamDecay);
  stepOut[o] = vec4(x, posIn[s].w);  // x
  velOut[o] = vec4(v, foam);
  const uint cell = cellOf(x);
  nextParticleCell[i] = cell;
  nextIndexInCell[i] = atomicAdd(nextCellCount[cell], 1u);
#endif
}

void main() {
  const uint i = uFirst + globalIndex();
  if (i < uCount) stepBall(i);
}
