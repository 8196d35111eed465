#version 430 core
// Self-test kernel (tidepool info, tests/gl): out[i] = i * uMul + 1 for i < uCount. Exercises
// globalIndex() over dispatches that spill into y, and the bounds check every 1D kernel needs.
layout(local_size_x = 64) in;
#include "common/index.glsl"
#include "selftest/bindings.glsl"

layout(std430, binding = SELFTEST_OUT) buffer Out { uint values[]; };
uniform uint uCount;
uniform uint uMul;

void main() {
  const uint i = globalIndex();
  if (i >= uCount) return;
  values[i] = i * uMul + 1u;
}
