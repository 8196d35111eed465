#version 430 core
// Divergence watch of the balls (src/sim/balls/balls.h): water/health.glsl's check of each ball.
#include "balls/bindings.glsl"

layout(local_size_x = BALLS_GROUP_SIZE) in;
#include "common/index.glsl"
#include "common/health.glsl"
#include "water/health.glsl"

layout(std430, binding = BALLS_POS_IN) readonly buffer PosIn { vec4 posIn[]; };
layout(std430, binding = BALLS_VEL_IN) readonly buffer VelIn { vec4 velIn[]; };

void checkHealth(uint i) { checkWaterParticle(posIn[i].xyz, velIn[i].xyz); }
