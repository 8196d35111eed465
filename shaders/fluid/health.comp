#version 430 core
// Divergence watch of the fluid (src/sim/fluid/fluid.h): water/health.glsl's check of each particle.
#include "fluid/bindings.glsl"

layout(local_size_x = FLUID_GROUP_SIZE) in;
#include "common/index.glsl"
#include "common/health.glsl"
#include "water/health.glsl"

layout(std430, binding = FLUID_POS) readonly buffer Pos { vec4 pos[]; };
layout(std430, binding = FLUID_VEL_IN) readonly buffer Vel { vec4 vel[]; };

void checkHealth(uint i) { checkWaterParticle(pos[i].xyz, vel[i].xyz); }
