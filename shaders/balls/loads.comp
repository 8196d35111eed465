#version 430 core
// The loads of the balls on the walls and the obstacles (water/loads.glsl): each ball's
// acceleration from each wall and from each obstacle's particles, as the step's collide summed it
// from the same inputs (the cell-ordered positions and velocities), so that the boundary felt
// F = −m Σa. A pass of its own, run after collide while a force probe or a body is listed: collide
// uses all eight storage blocks with the Euler integrators. An obstacle's moment is taken at each
// contact's midpoint, about the obstacle's centre.
#include "balls/bindings.glsl"

layout(local_size_x = BALLS_GROUP_SIZE) in;
#include "common/index.glsl"

layout(std430, binding = BALLS_POS_IN) readonly buffer PosIn { vec4 posIn[]; };
layout(std430, binding = BALLS_VEL_IN) readonly buffer VelIn { vec4 velIn[]; };

uniform float uRadius;       // m
uniform uint uSourceFirst;   // the first ball of the inputs' window
uniform uint uFirst;         // balls [uFirst, uCount): a window of them (src/gl/window.h), or all
uniform uint uCount;

#include "balls/contact.glsl"
#include "balls/walls.glsl"

vec3 gPos = vec3(0.0), gVelocity = vec3(0.0);  // the ball (initialised: no compiler warns of their use in the callbacks)
uint gTouched = 0u;  // bit k: a particle of obstacle k was in contact
int gOnly = -1;      // ≥ 0: only obstacle gOnly's particles count (a recount, obstacleShare())
// The first obstacle met: its share is summed on the way, in the order a recount would sum it
// (a ball seldom touches two obstacles at once).
int gFirst = -1;
vec3 gAccel = vec3(0.0), gMoment = vec3(0.0);

#ifdef HAS_OBSTACLE
#include "balls/obstacle_poses.glsl"
void onObstacleParticle(uint j, vec4 q) {
  const uint k = uint(q.w);
  if (gOnly >= 0 && k != uint(gOnly)) return;
  const vec3 d = gPos - q.xyz;
  const float dist2 = dot(d, d), reach = 2.0 * uRadius;
  if (dist2 >= reach * reach || dist2 == 0.0) return;
  gTouched |= 1u << k;
  if (gFirst < 0) gFirst = int(k);
  if (k != uint(gFirst) && gOnly < 0) return;  // recounted in obstacleShare()
  const float dist = sqrt(dist2);
  const vec3 a = contactAccel(d / dist, reach - dist, gVelocity - obstacleVelocity(k, q.xyz), 1.0, 1.0);
  gAccel += a;
  gMoment += cross(0.5 * (gPos + q.xyz) - poseCentre[k].xyz, a);
}
#include "common/obstacle_grid.glsl"
#endif

// Obstacle k's share of this ball's acceleration, and its moment about c_k.
void obstacleShare(uint k, out vec3 delta, out vec3 moment) {
#ifdef HAS_OBSTACLE
  if (int(k) != gFirst) {  // recounted: only k's particles
    gOnly = int(k);
    gAccel = gMoment = vec3(0.0);
    forEachObstacleParticle(gPos, 1);
  }
  delta = gAccel;
  moment = gMoment;
#else
  delta = moment = vec3(0.0);
#endif
}

#define LOADS_BINDING BALLS_LOADS
#define LOADS_GROUP_SIZE BALLS_GROUP_SIZE
#define LOADS_FIRST
#include "water/loads.glsl"

// Each wall's push on the ball at p, along its axis (walls.glsl's wallsAccel, a wall at a time:
// one helper serving both made the collide 1.2% slower, docs/ARCHITECTURE.md, "Rejected
// designs"); `side` per axis: −1 the wall at the minimum, +1 at the maximum.
vec3 wallShares(vec3 p, vec3 v, out vec3 side) {
  vec3 share = vec3(0.0);
  side = vec3(1.0);
  for (int k = 0; k < 3; ++k) {
    vec3 axis = vec3(0.0);
    axis[k] = 1.0;
    const float below = uWallMin[k] + uRadius - p[k];
    const float above = p[k] - (uWallMax[k] - uRadius);
    if (below > 0.0) {
      share[k] = wallAccel(axis, below, v - uWallMinVel)[k];
      side[k] = -1.0;
    } else if (above > 0.0) {
      share[k] = wallAccel(-axis, above, v - uWallMaxVel)[k];
    }
  }
  return share;
}

void main() {
  const uint i = uFirst + globalIndex();
  vec3 wall = vec3(0.0), side = vec3(1.0);
  if (i < uCount) {
    const uint s = i - uSourceFirst;
    gPos = posIn[s].xyz;
    gVelocity = velIn[s].xyz;
#ifdef HAS_OBSTACLE
    forEachObstacleParticle(gPos, 1);
#endif
    wall = wallShares(gPos, gVelocity, side);
  }
  addLoads(wall, side, gTouched);  // by every invocation: the group adds them
}
