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
// The step's other output: the acceleration (velocity Verlet) or the new position (Euler). One
// declaration keeps the kernel at 8 storage blocks with obstacles (GL 4.3's minimum).
#ifdef INTEGRATOR_VERLET
#define STEP_OUT_BINDING BALLS_ACC
uniform float uKick;  // fraction of dt·a added to the (half-step) velocity: 0.5, or 0 to only evaluate a
#else
#define STEP_OUT_BINDING BALLS_POS_OUT
#endif
layout(std430, binding = STEP_OUT_BINDING) writeonly buffer StepOut { vec4 stepOut[]; };

#include "balls/contact.glsl"
// Bindings 6 and 7: the obstacles' or the next count's (included here, outside any #if:
// the shader library inlines a file at its first #include only).
#include "balls/shared_slots.glsl"

#ifdef COUNT_CELLS
// The next step's grid count (grid_count.comp) done here, at the positions this pass writes: no
// count pass reading them again. Only without obstacles (8 storage blocks): the counts
// and the slots take bindings 6 and 7 (balls/shared_slots.glsl), the cells Verlet's binding 4.
#if defined(INTEGRATOR_VERLET)
#error "COUNT_CELLS takes binding 4, Verlet's accelerations: Balls::countsInCollide() keeps it from Verlet"
#endif
layout(std430, binding = BALLS_NEXT_PARTICLE_CELL) writeonly buffer NextParticleCell { uint nextParticleCell[]; };
#endif

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
#ifdef COUNT_CELLS
  const uint cell = cellOf(x);
  nextParticleCell[i] = cell;
  nextIndexInCell[i] = atomicAdd(nextCellCount[cell], 1u);
#endif
#endif
}

void main() {
  const uint i = uFirst + globalIndex();
  if (i < uCount) stepBall(i);
}
