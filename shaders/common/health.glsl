// The divergence watch's reduction (src/sim/divergence.h), shared by every model's health.comp.
// A kernel declares its local size and its state, includes this file after common/index.glsl,
// and defines what it checks of element i < uCount (the watch sets uCount):
//   void checkHealth(uint i) { ... isFinite(x) ? healthMax(length(v)) : healthNonFinite(); ... }
// Each work group reduces in shared memory first, then makes one global atomic of each kind.
// Magnitudes are non-negative, and non-negative floats order like their bit patterns, so the
// largest one is an atomicMax on floatBitsToUint (GL 4.3 has no float atomics).
#ifndef COMMON_HEALTH_GLSL
#define COMMON_HEALTH_GLSL

#include "common/health_layout.glsl"

layout(std430, binding = HEALTH_BINDING) buffer Health { uint health[HEALTH_WORDS]; };  // zeroed by the watch
// Elements [uFirst, uCount): a window of arrays larger than one storage block (src/gl/window.h),
// bound from element uFirst on, or all of them (uFirst = 0). checkHealth() gets the index in the window.
uniform uint uFirst;
uniform uint uCount;

shared uint sNonFinite, sMaxBits, sFlagged;

bool isFinite(vec2 x) { return !any(isnan(x)) && !any(isinf(x)); }
bool isFinite(vec3 x) { return !any(isnan(x)) && !any(isinf(x)); }
void healthNonFinite() { atomicAdd(sNonFinite, 1u); }
void healthMax(float magnitude) { atomicMax(sMaxBits, floatBitsToUint(magnitude)); }  // magnitude >= 0
void healthFlag() { atomicAdd(sFlagged, 1u); }

void checkHealth(uint i);  // the model's, defined after the include

void main() {
  if (gl_LocalInvocationIndex == 0u) {
    sNonFinite = 0u;
    sMaxBits = 0u;
    sFlagged = 0u;
  }
  barrier();
  const uint i = uFirst + globalIndex();
  if (i < uCount) checkHealth(i - uFirst);
  barrier();
  if (gl_LocalInvocationIndex == 0u) {
    if (sNonFinite > 0u) atomicAdd(health[HEALTH_NON_FINITE], sNonFinite);
    atomicMax(health[HEALTH_MAX_BITS], sMaxBits);
    if (sFlagged > 0u) atomicAdd(health[HEALTH_FLAGGED], sFlagged);
  }
}

#endif
