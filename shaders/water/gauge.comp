#version 430 core
// Water gauges (src/sim/water/probes.h): for each gauge g, the sum over particles of the 2D kernel
// W(s) = 4/(πR²)·(1 − s²/R²)³ (= 4/(πR⁸)·(R² − s²)³) of the horizontal distance s = |p.xy − at_g| (s < R), reduced per work
// group in a fixed order; the CPU adds the groups in double and multiplies by the rest volume.
#include "water/probe_bindings.glsl"

layout(local_size_x = PROBE_GROUP_SIZE) in;
#include "common/index.glsl"

layout(std430, binding = PROBE_POS) readonly buffer Pos { vec4 pos[]; };
layout(std430, binding = PROBE_PARTIALS) writeonly buffer Partials { float partials[]; };

uniform uint uFirst;  // the window's first particle (pos[0] is particle uFirst)
uniform uint uCount;  // the window's end
uniform int uGauges;
uniform vec4 uGauge[PROBE_MAX_GAUGES];  // x, y, 1/R², 4/(πR²)

const int kValues = PROBE_MAX_GAUGES;
bool reducedByMax(int k) { return false; }
#define GROUP_SIZE PROBE_GROUP_SIZE
#include "common/group_reduce.glsl"

void main() {
  const uint i = uFirst + globalIndex();
  float values[kValues];
  for (int k = 0; k < kValues; ++k) values[k] = 0.0;
  if (i < uCount) {
    const vec2 p = pos[i - uFirst].xy;
    for (int g = 0; g < uGauges; ++g) {
      const vec2 s = p - uGauge[g].xy;
      const float q = 1.0 - dot(s, s) * uGauge[g].z;
      if (q > 0.0) values[g] = uGauge[g].w * q * q * q;
    }
  }
  reduceGroup(values);
}
