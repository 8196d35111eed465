#version 430 core
// The obstacles' shares of one solver iteration's corrections (water/obstacle_loads.glsl), after
// Δp (fluid/delta.comp): for each obstacle particle b, what it added to the correction of every
// fluid particle j within h of it, λ_j V_b ∇W(p_j − b), then its push of q_j (j's corrected
// position before the obstacles' push) out to uContact, and the moments of both about b's
// obstacle's centre (at p_j and at q_j), so that the obstacle felt F = −m ΣΔ / dt². The same
// float operations as Δp's, from its inputs p and λ; q comes from Δp (OBSTACLE_LOADS). The fluid
// particles come from the grid of the step's sort: the search reaches half a cell farther than h
// (one ring more), for the particles the iterations so far moved out of their cells. Δp keeps q
// only for a particle within h of an obstacle particle, so a push of one farther than h (an
// iteration moving it more than h − uContact, 1.25 spacings) is not counted.
#include "fluid/bindings.glsl"

layout(local_size_x = FLUID_GROUP_SIZE) in;
#include "common/index.glsl"

layout(std430, binding = FLUID_PRED) readonly buffer Pred { vec4 pred[]; };  // p, this iteration's input
layout(std430, binding = FLUID_LAMBDA) readonly buffer Lambda { vec2 lambda[]; };
layout(std430, binding = FLUID_UNPUSHED) readonly buffer Unpushed { vec4 unpushed[]; };  // q
#ifdef OBSTACLE_VOLUMES
layout(std430, binding = FLUID_OBSTACLE_VOLUMES) readonly buffer Volumes { vec4 volumes[]; };  // x = m³
#endif
#define neighbourPos pred

#include "fluid/kernels.glsl"

uniform float uContact;  // m: the closest a fluid particle comes to an obstacle particle

vec3 gB = vec3(0.0), gCentre = vec3(0.0);  // the obstacle particle and its obstacle's centre
float gVolume = 0.0;
vec3 gShare = vec3(0.0), gMoment = vec3(0.0);
void onFluid(uint j, vec3 r, float r2) {  // r = b − p_j
  if (r2 >= uH * uH) return;
  const float len = sqrt(r2);
  if (len <= 0.0) return;
  const vec3 p = pred[j].xyz;
  const vec3 gradient = lambda[j].x * (gVolume * spikyGrad(p - gB, len));
  gShare += gradient;
  gMoment += cross(p - gCentre, gradient);
  const vec3 q = unpushed[j].xyz, e = q - gB;
  const float e2 = dot(e, e);
  if (e2 >= uContact * uContact) return;
  const float elen = sqrt(e2);
  if (elen <= 0.0) return;
  const vec3 push = (uContact - elen) / elen * e;
  gShare += push;
  gMoment += cross(q - gCentre, push);
}

#include "fluid/neighbours.glsl"
#include "balls/bindings.glsl"
#define PLACED_BINDING FLUID_OBSTACLE_PLACED
#define SHARES_BINDING FLUID_SHARES
#define MOMENTS_BINDING FLUID_MOMENTS
#include "water/obstacle_loads.glsl"

void main() {
  uint b, k;
  if (!obstacleParticle(b, gB, k)) return;
  gCentre = poseCentre[k].xyz;
#ifdef OBSTACLE_VOLUMES
  gVolume = volumes[b].x;
#else
  gVolume = uVolume;  // solid obstacles at the fluid's spacing: a fluid particle's volume
#endif
  startShares(b, gShare, gMoment);
  forEachGridNeighbour(gB, 1.5 * uH);  // uReach: one ring more than Δp's
  storeShares(b, gShare, gMoment);
}
