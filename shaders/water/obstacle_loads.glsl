// The loads on the obstacles (src/sim/water/boundary_loads.h), summed from the obstacles' side:
// each of a model's obstacle-loads kernels runs an invocation per obstacle particle b (placed in
// the world this step, in the obstacles' own order) that sums what b did to every water particle
// near it, in the order the water's grid holds them: its share (the fluid: of their corrections;
// the balls: of their accelerations) and that share's moment about its obstacle's centre c_k.
// A step may add several dispatches' sums (the fluid's solver iterations, the balls' windows):
// the first starts from zero (uAddShares 0), the others go on adding to what the earlier ones
// stored, particle by particle, so the sums are the same on every run and for any windows. water/obstacle_loads_sum.comp then adds
// each obstacle's particles.
// The including kernel includes balls/bindings.glsl (the obstacles' pose block) and
// common/index.glsl, and defines
// PLACED_BINDING (the placed particles), SHARES_BINDING and MOMENTS_BINDING (their storage blocks:
// one vec4 per particle each, as the particles' own array).
#ifndef WATER_OBSTACLE_LOADS_GLSL
#define WATER_OBSTACLE_LOADS_GLSL

#include "balls/obstacle_poses.glsl"

layout(std430, binding = PLACED_BINDING) readonly buffer Placed { vec4 placed[]; };  // world, w = obstacle

layout(std430, binding = SHARES_BINDING) buffer Shares { vec4 shares[]; };     // Σ share per particle
layout(std430, binding = MOMENTS_BINDING) buffer Moments { vec4 moments[]; };  // Σ moment per particle

uniform uint uObstacleParticles;  // all obstacles'
uniform uint uAddShares;          // 0: this dispatch is the step's first

// This invocation's obstacle particle b: false past the last; else where it is (world) and its
// obstacle.
bool obstacleParticle(out uint b, out vec3 at, out uint k) {
  b = globalIndex();
  if (b >= uObstacleParticles) return false;
  const vec4 q = placed[b];
  at = q.xyz;
  k = uint(q.w);
  return true;
}

// The sums so far: zero for the step's first dispatch, else what the earlier ones left, which
// this one goes on adding to.
void startShares(uint b, out vec3 share, out vec3 moment) {
  share = moment = vec3(0.0);
  if (uAddShares != 0u) {
    share = shares[b].xyz;
    moment = moments[b].xyz;
  }
}

void storeShares(uint b, vec3 share, vec3 moment) {
  shares[b] = vec4(share, 0.0);
  moments[b] = vec4(moment, 0.0);
}

#endif
