#version 430 core
// Live statistics and probes of particle water (the fluid, or the balls measured with the same
// kernel and h), reduced per work group: FLUID_STATS_VALUES floats (fluid/stats_layout.glsl).
// The density is the solver's: fluid neighbours, obstacle particles and the walls' half spaces.
#include "fluid/bindings.glsl"
#include "fluid/stats_layout.glsl"

layout(local_size_x = FLUID_GROUP_SIZE) in;
#include "common/index.glsl"

layout(std430, binding = FLUID_PRED) readonly buffer Pos { vec4 pos[]; };  // cell order
layout(std430, binding = FLUID_VEL_IN) readonly buffer Vel { vec4 vel[]; };
layout(std430, binding = FLUID_OUT) writeonly buffer Stats { float partials[]; };
#define neighbourPos pos

#include "fluid/kernels.glsl"

float gDensity;
void onFluid(uint j, vec3 r, float r2) { gDensity += uVolume * poly6(r2); }
void onBoundary(vec3 r, float r2, float volume, uint k) { gDensity += volume * poly6(r2); }

#include "fluid/neighbours.glsl"
#include "fluid/boundary.glsl"
#include "fluid/walls.glsl"

uniform uint uCount;
uniform vec3 uGravity;
uniform vec3 uDomainMin;
uniform float uSpacing;  // m

const int kValues = FLUID_STATS_VALUES;
bool reducedByMax(int k) {
  return k == FLUID_STATS_MAX_COMPRESSION || k == FLUID_STATS_MAX_SPEED || k == FLUID_STATS_FRONT ||
         k == FLUID_STATS_BACK_HEIGHT;
}

#define GROUP_SIZE FLUID_GROUP_SIZE
#include "common/group_reduce.glsl"

void main() {
  const uint i = globalIndex();
  const float kNone = -3.0e38;
  float values[kValues];
  for (int k = 0; k < kValues; ++k) values[k] = 0.0;
  values[FLUID_STATS_FRONT] = kNone;
  values[FLUID_STATS_BACK_HEIGHT] = kNone;
  values[FLUID_STATS_MAX_COMPRESSION] = kNone;
  if (i < uCount) {
    const vec3 p = pos[i].xyz, v = vel[i].xyz;
    if (any(isnan(p)) || any(isinf(p)) || any(isnan(v)) || any(isinf(v))) {
      values[FLUID_STATS_NON_FINITE] = 1.0;
    } else {
      gDensity = 0.0;
      forEachFluid(i, p);
#ifdef HAS_OBSTACLE
      forEachBoundary(p, uH);
#endif
      vec3 unused = vec3(0.0);
      wallsDensity(p, gDensity, unused);
      const float error = gDensity - 1.0;
      values[FLUID_STATS_KINETIC] = 0.5 * dot(v, v);
      values[FLUID_STATS_POTENTIAL] = -dot(uGravity, p - uDomainMin);
      values[FLUID_STATS_COMPRESSION] = max(error, 0.0);
      values[FLUID_STATS_DENSITY] = error;
      values[FLUID_STATS_MAX_COMPRESSION] = error;
      values[FLUID_STATS_MAX_SPEED] = length(v);
      values[FLUID_STATS_OUTSIDE] = any(lessThan(p, uWallMin - 1e-6)) || any(greaterThan(p, uWallMax + 1e-6)) ? 1.0 : 0.0;
      if (p.z < uWallMin.z + uSpacing) values[FLUID_STATS_FRONT] = p.x;
      if (p.x < uWallMin.x + uSpacing) values[FLUID_STATS_BACK_HEIGHT] = p.z;
    }
  }
  reduceGroup(values);
}
