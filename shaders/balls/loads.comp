#version 430 core
// The loads of the balls on the walls (water/loads.glsl), while a wall is probed: each ball's
// acceleration from each wall, as the step's collide summed it from the same inputs (the
// cell-ordered positions and velocities), so that the wall felt F = −m Σa. A pass of its own, run
// after collide: collide uses all eight storage blocks with the Euler integrators. (The
// obstacles' loads: obstacle_loads.comp.)
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
    wall = wallShares(posIn[s].xyz, velIn[s].xyz, side);
  }
  addLoads(wall, side);  // by every invocation: the group adds them
}
