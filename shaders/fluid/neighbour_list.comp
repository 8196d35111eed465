#version 430 core
// The step's neighbour list (issue 18's lever against the grid's candidates: a loop over the cells
// around a particle visits several times more particles than lie within h): once per step, after
// the sort, every particle within h·(1 + skin) of each particle's predicted position, itself
// included, at most FLUID_MAX_NEIGHBOURS (more are dropped: a compression of 2.3 would be needed).
// The solver's iterations and the velocity passes then read the list (NEIGHBOUR_LIST).
#include "fluid/bindings.glsl"

layout(local_size_x = FLUID_GROUP_SIZE) in;
#include "common/index.glsl"

layout(std430, binding = FLUID_PRED) readonly buffer Pred { vec4 pred[]; };
layout(std430, binding = FLUID_OUT) writeonly buffer List { uint list[]; };
#define neighbourPos pred

#include "fluid/kernels.glsl"

uniform uint uListStride;  // entry k of particle i is list[k·stride + i]; k = 0 holds the count
uint gIndex = 0u, gCount = 0u;
void onFluid(uint j, vec3 r, float r2) {
  if (gCount < uint(FLUID_MAX_NEIGHBOURS)) list[(++gCount) * uListStride + gIndex] = j;
}

#include "fluid/neighbours.glsl"

uniform uint uCount;
uniform float uListReach;  // h·(1 + skin), m

void main() {
  const uint i = globalIndex();
  if (i >= uCount) return;
  gIndex = i;
  gCount = 0u;
  forEachGridNeighbour(pred[i].xyz, uListReach);
  list[i] = gCount;
}
