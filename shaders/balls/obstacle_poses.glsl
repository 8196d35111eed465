// Each obstacle's rigid pose this step (src/sim/balls/obstacle_pose.h evaluates it from the time,
// src/sim/water/obstacles.cpp fills the block, with each one's run of particles): a fixed
// particle of obstacle k with own-frame position b is at c_k + R_k·b and moves with
// v_k + ω_k × (x − c_k).
#ifndef BALLS_OBSTACLE_POSES_GLSL
#define BALLS_OBSTACLE_POSES_GLSL

layout(std140, binding = BALLS_OBST_POSES) uniform ObstaclePoses {
  vec4 poseRotation[3 * BALLS_MAX_OBSTACLES];  // columns of R_k: [3k], [3k + 1], [3k + 2]
  vec4 poseCentre[BALLS_MAX_OBSTACLES];        // c_k, m
  vec4 poseVelocity[BALLS_MAX_OBSTACLES];      // v_k, m/s
  vec4 poseOmega[BALLS_MAX_OBSTACLES];         // ω_k, rad/s
  uvec4 poseParticles[BALLS_MAX_OBSTACLES];    // x: the first of its particles, y: how many
};

vec3 obstaclePlace(uint k, vec3 body) {
  const mat3 r = mat3(poseRotation[3u * k].xyz, poseRotation[3u * k + 1u].xyz, poseRotation[3u * k + 2u].xyz);
  return poseCentre[k].xyz + r * body;
}

vec3 obstacleVelocity(uint k, vec3 world) {
  return poseVelocity[k].xyz + cross(poseOmega[k].xyz, world - poseCentre[k].xyz);
}

#endif
