#version 430 core
// Pressure probes of the fluid (src/sim/fluid/fluid_probes.cpp), up to FLUID_PRESSURE_BATCH
// points per dispatch, each reduced per work group into 2 floats: Σ V0 p_i W(a − x_i) and
// Σ V0 W(a − x_i) over the particles (poly6, support h), which the CPU divides (Shepard). The
// pressure of particle i is the solver's: p_i = −ρ0 Λ_i / dt², Λ_i the sum of its λ over the last
// step's iterations: the position correction V0 (λ_i + λ_j) ∇W is SPH's pressure acceleration
// −V0 (p_i + p_j)/ρ0 ∇W times dt².
#include "fluid/bindings.glsl"

layout(local_size_x = FLUID_GROUP_SIZE) in;
#include "common/index.glsl"

#define FLUID_PRESSURE_BATCH 8
layout(std430, binding = FLUID_POS) readonly buffer Pos { vec4 pos[]; };
layout(std430, binding = FLUID_PRESSURE) readonly buffer LambdaSum { float lambdaSum[]; };
layout(std430, binding = FLUID_OUT) writeonly buffer Partials { float partials[]; };

#include "fluid/kernels.glsl"

uniform uint uCount;
uniform float uPressureScale;  // −ρ0 / dt², Pa per unit of Λ
uniform int uPoints;           // points in this batch
uniform vec4 uPoint[FLUID_PRESSURE_BATCH];  // m (w unused)

const int kValues = 2 * FLUID_PRESSURE_BATCH;
bool reducedByMax(int k) { return false; }
#define GROUP_SIZE FLUID_GROUP_SIZE
#include "common/group_reduce.glsl"

void main() {
  const uint i = globalIndex();
  float values[kValues];
  for (int k = 0; k < kValues; ++k) values[k] = 0.0;
  if (i < uCount) {
    const vec3 x = pos[i].xyz;
    const float p = uPressureScale * lambdaSum[i];
    for (int g = 0; g < uPoints; ++g) {
      const vec3 r = uPoint[g].xyz - x;
      const float w = uVolume * poly6(dot(r, r));
      values[2 * g] = w * p;
      values[2 * g + 1] = w;
    }
  }
  reduceGroup(values);
}
