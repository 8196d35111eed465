#version 430 core
// The obstacles' fixed particles to where their obstacles are this step: world = c_k + R_k·b for
// a particle of obstacle k (w) at own-frame position b. The obstacle grid is built from the result.
#include "balls/bindings.glsl"

layout(local_size_x = BALLS_GROUP_SIZE) in;
#include "common/index.glsl"

layout(std430, binding = BALLS_POS_IN) readonly buffer Body { vec4 body[]; };     // own frame, w = k
layout(std430, binding = BALLS_POS_OUT) writeonly buffer World { vec4 world[]; };  // world, w = k

#include "balls/obstacle_poses.glsl"

uniform uint uCount;

void main() {
  const uint i = globalIndex();
  if (i >= uCount) return;
  const vec4 b = body[i];
  world[i] = vec4(obstaclePlace(uint(b.w), b.xyz), b.w);
}
